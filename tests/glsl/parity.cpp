#include "parity.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <glint/glsl.hpp>

namespace glint_test {

gl_compute& gl() {
    static gl_compute context;
    return context;
}

std::vector<std::uint32_t> map_floats(const std::vector<std::string>& kernels, const std::string& result_type,
                                      const std::string& expression, const std::vector<float>& x,
                                      const std::vector<float>& y) {
    const bool binary = !y.empty();
    std::string s = shader_header(kernels);
    s += "layout(std430, binding = 0) readonly buffer In0 { float in0[]; };\n";
    if (binary) s += "layout(std430, binding = 1) readonly buffer In1 { float in1[]; };\n";
    s += "layout(std430, binding = " + std::string(binary ? "2" : "1") + ") writeonly buffer Out { " +
         result_type + " out0[]; };\n";
    s += "void main() {\n"
         "  uint n = uint(in0.length());\n"
         "  for (uint i = gl_GlobalInvocationID.x; i < n; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {\n"
         "    float x = in0[i];\n";
    if (binary) s += "    float y = in1[i];\n";
    s += "    out0[i] = " + expression + ";\n  }\n}\n";
    unsigned prog = gl().program(s);
    std::vector<std::vector<std::uint32_t>> inputs = {to_words(x)};
    if (binary) inputs.push_back(to_words(y));
    return gl().run(prog, inputs, x.size(), x.size());
}

std::vector<std::uint32_t> map_words(const std::vector<std::string>& kernels, const std::string& body,
                                     const std::vector<std::uint32_t>& in, std::size_t items,
                                     std::size_t out_words_per_item) {
    std::string s = shader_header(kernels);
    s += "layout(std430, binding = 0) readonly buffer In0 { uint in0[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Out { uint out0[]; };\n"
         "float in_float(uint k) { return uintBitsToFloat(in0[k]); }\n"
         "vec2 in_vec2(uint k) { return vec2(in_float(k), in_float(k + 1u)); }\n"
         "vec3 in_vec3(uint k) { return vec3(in_float(k), in_float(k + 1u), in_float(k + 2u)); }\n"
         "void main() {\n"
         "  uint n = " + std::to_string(items) + "u;\n"
         "  for (uint i = gl_GlobalInvocationID.x; i < n; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {\n" +
         body + "\n  }\n}\n";
    unsigned prog = gl().program(s);
    return gl().run(prog, {in}, items * out_words_per_item, items);
}

std::string glsl_float_bits(float x) {
    std::uint32_t u;
    std::memcpy(&u, &x, 4);
    return "uintBitsToFloat(" + std::to_string(u) + "u)";
}

std::vector<std::uint32_t> map_words_with_data(const std::vector<std::string>& kernels, const std::string& data_kernel, const std::string& data_name,
                                               const std::string& declared, const std::string& body, const std::vector<std::uint32_t>& in,
                                               const std::vector<std::uint32_t>& data, std::size_t items, std::size_t out_words_per_item) {
    std::string s = shader_header(kernels);
    s += "layout(std430, binding = 0) readonly buffer In0 { uint in0[]; };\n"
         "layout(std430, binding = 1) readonly buffer Data { vec4 " + data_name + "[]; };\n"
         "layout(std430, binding = 2) writeonly buffer Out { uint out0[]; };\n"
         "#define " + declared + "\n";
    s += std::string(glint::glsl_source(data_kernel));
    s += "float in_float(uint k) { return uintBitsToFloat(in0[k]); }\n"
         "vec2 in_vec2(uint k) { return vec2(in_float(k), in_float(k + 1u)); }\n"
         "vec3 in_vec3(uint k) { return vec3(in_float(k), in_float(k + 1u), in_float(k + 2u)); }\n"
         "void main() {\n"
         "  uint n = " + std::to_string(items) + "u;\n"
         "  for (uint i = gl_GlobalInvocationID.x; i < n; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {\n" +
         body + "\n  }\n}\n";
    unsigned prog = gl().program(s);
    return gl().run(prog, {in, data}, items * out_words_per_item, items);
}

ulp_stats compare(const std::vector<float>& gpu, const std::vector<float>& cpu) {
    if (gpu.size() != cpu.size()) throw std::runtime_error("compare: GLSL and C++ result sizes differ");
    ulp_stats s;
    s.count = gpu.size();
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        const std::int64_t d = ulp_distance(gpu[i], cpu[i]);
        s.max = std::max(s.max, d);
        s.differing += d != 0;
    }
    return s;
}

ulp_stats compare(const std::vector<std::uint32_t>& gpu, const std::vector<std::uint32_t>& cpu) {
    if (gpu.size() != cpu.size()) throw std::runtime_error("compare: GLSL and C++ result sizes differ");
    ulp_stats s;
    s.count = gpu.size();
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        const std::int64_t d = static_cast<std::int64_t>(gpu[i]) - static_cast<std::int64_t>(cpu[i]);
        s.max = std::max(s.max, d < 0 ? -d : d);
        s.differing += d != 0;
    }
    return s;
}

}  // namespace glint_test
