// The NDF-map kernels through Mesa llvmpipe against the C++ float path, with the images in an
// RGBA32F texture array (texelFetch, the bilinear filter done by hand on both sides) and the
// elements in an std430 buffer: stochastic owners and anchors (integer hashing and exact float
// arithmetic: bit-exact), the P-NDF on tiled, transformed and stochastic layouts, the sampler,
// and the coated BRDF. A P-NDF value is a weighted sum of bilinear lookups and Gaussian terms
// whose exp and sqrt differ by a few ulp in Mesa, so values are compared relative to the map's
// peak density; the share that differs by more than 1e-3 of it (the mismatch rate) is bounded,
// and a sample is a mismatch when its s differs by more than 1e-4 (a draw near a tile or bin
// boundary that rounding moves).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glint/glsl.hpp>
#include <glint/ndf_map.hpp>

#include "../support/ndf_map_support.hpp"
#include "../support/pndf_support.hpp"
#include "parity.hpp"
#include "tolerances.hpp"

namespace {

using K = glint::detail::glsl::kernels<float>;
using map_t = glint::ndf_map<float>;
using placement = glint::ndf_placement<float>;

float rnd(std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, salt, 0x77au)).x); }

std::string f(float x) { return glint_test::glsl_float_bits(x); }
std::string v2(glm::vec2 v) { return "vec2(" + f(v.x) + ", " + f(v.y) + ")"; }
std::string v4(glm::vec4 v) { return "vec4(" + f(v.x) + ", " + f(v.y) + ", " + f(v.z) + ", " + f(v.w) + ")"; }

// GLSL statements that set `name` to the C++ struct's values, bit for bit.
std::string params_glsl(const K::glint_ndf_map_params& p, const std::string& name) {
    const auto& e = p.el;
    return "glint_ndf_map_params " + name + "; " + name + ".n = " + std::to_string(p.n) + "; " + name + ".levels = " + std::to_string(p.levels) + "; " + name +
           ".res = " + std::to_string(p.res) + "; " + name + ".max_tiles = " + std::to_string(p.max_tiles) + "; " + name + ".s_min = " + v2(p.s_min) + "; " +
           name + ".s_bin = " + f(p.s_bin) + "; " + name + ".tau = " + f(p.tau) + "; " + name + ".cull = " + f(p.cull) + "; " + name +
           ".direct_below = " + f(p.direct_below) + "; " + name + ".blend = " + f(p.blend) + "; " + name + ".el.sigma_h = " + f(e.sigma_h) + "; " + name +
           ".el.sigma_r = " + f(e.sigma_r) + "; " + name + ".el.spacing = " + f(e.spacing) + "; " + name + ".el.area = " + f(e.area) + "; " + name +
           ".el.cull_u = " + f(e.cull_u) + "; " + name + ".el.cull_s = " + f(e.cull_s) + "; " + name + ".el.width = " + std::to_string(e.width) + "; " +
           name + ".el.height = " + std::to_string(e.height) + "; " + name + ".el.periodic = " + std::to_string(e.periodic) + "; " + name +
           ".el.max_side = " + std::to_string(e.max_side) + ";\n";
}
std::string placement_glsl(const K::glint_ndf_placement& p, const std::string& name) {
    return "glint_ndf_placement " + name + "; " + name + ".kind = " + std::to_string(p.kind) + "; " + name + ".seed = " + std::to_string(p.seed) + "u; " +
           name + ".a = " + v4(p.a) + "; " + name + ".origin = " + v2(p.origin) + "; " + name + ".cell = " + f(p.cell) + "; " + name +
           ".rotation = " + v2(p.rotation) + "; " + name + ".scale = " + v2(p.scale) + "; " + name + ".flip = " + f(p.flip) + "; " + name +
           ".max_cells = " + std::to_string(p.max_cells) + ";\n";
}

// Runs `body` (GLSL; `uint i`, in_float(k), out0[]) with the map's elements at binding 1 and its
// images as the texture array glint_ndf_images on unit 0.
std::vector<std::uint32_t> run_with_map(const map_t& m, const std::string& prelude, const std::string& body, const std::vector<std::uint32_t>& in, std::size_t items,
                                std::size_t words) {
    std::string s = glint_test::shader_header({"core.glsl", "microfacet.glsl"});
    s += "layout(std430, binding = 0) readonly buffer In0 { uint in0[]; };\n"
         "layout(std430, binding = 1) readonly buffer Data { vec4 glint_element_data[]; };\n"
         "layout(std430, binding = 2) writeonly buffer Out { uint out0[]; };\n"
         "#define GLINT_ELEMENT_BUFFER_DECLARED\n";
    s += std::string(glint::glsl_source("gaussian.glsl"));
    s += "#define GLINT_NDF_IMAGE_BINDING 0\n";
    s += std::string(glint::glsl_source("ndf_map.glsl"));
    s += "float in_float(uint k) { return uintBitsToFloat(in0[k]); }\n"
         "void main() {\n" +
         prelude + "  uint n = " + std::to_string(items) +
         "u;\n"
         "  for (uint i = gl_GlobalInvocationID.x; i < n; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {\n" +
         body + "\n  }\n}\n";
    auto& gl = glint_test::gl();
    const unsigned tex = gl.texture_array_rgba32f(m.resolution(), m.resolution(), m.layers(), m.images());
    const unsigned prog = gl.program(s);
    const auto out = gl.run(prog, {in, glint_test::to_words(m.element_data())}, items * words, items);
    gl.delete_texture(tex);
    return out;
}

map_t parity_map() {
    glint::ndf_map_params mp;
    mp.sigma_r = 0.02, mp.resolution = 32, mp.max_tiles = 128;
    return map_t::build(glint::make_normal_map(glint_test::example_pattern(glint::pattern::leather, 16)), mp);
}

}  // namespace

TEST_CASE("ndf_map: stochastic owners and anchors, GLSL against C++ bit for bit") {
    const auto pl = placement::stochastic(13.7f, 0xa11ceu, glm::vec2(-1, 2), glm::vec2(0.5f, 2), 0.4f);
    const std::size_t n = 20000;
    std::vector<std::uint32_t> in;
    std::vector<glm::vec2> xs(n);
    for (std::uint32_t i = 0; i < n; ++i) xs[i] = {4000 * rnd(i, 1) - 2000, 4000 * rnd(i, 2) - 2000}, glint_test::append_words(in, {xs[i].x, xs[i].y});
    const std::string body =
        "vec2 x = vec2(in_float(2u * i), in_float(2u * i + 1u)); ivec2 o = glint_ndf_owner(pl, x);"
        " glint_ndf_copy c = glint_ndf_cell_copy(pl, o, 16);"
        " out0[6u * i] = uint(o.x); out0[6u * i + 1u] = uint(o.y); out0[6u * i + 2u] = floatBitsToUint(c.anchor.x);"
        " out0[6u * i + 3u] = floatBitsToUint(c.anchor.y); out0[6u * i + 4u] = floatBitsToUint(c.a.x); out0[6u * i + 5u] = floatBitsToUint(c.offset.y);";
    std::string s = glint_test::shader_header({"core.glsl", "microfacet.glsl", "gaussian.glsl", "ndf_map.glsl"});
    s += "layout(std430, binding = 0) readonly buffer In0 { uint in0[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Out { uint out0[]; };\n"
         "float in_float(uint k) { return uintBitsToFloat(in0[k]); }\n"
         "void main() {\n" +
         placement_glsl(pl.k, "pl") + "  for (uint i = gl_GlobalInvocationID.x; i < " + std::to_string(n) +
         "u; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {\n" + body + "\n  }\n}\n";
    const auto out = glint_test::gl().run(glint_test::gl().program(s), {in}, 6 * n, n);
    std::size_t owners = 0, copies = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::ivec2 o = pl.owner(xs[i]);
        const auto c = K::glint_ndf_cell_copy(pl.k, o, 16);
        owners += static_cast<int>(out[6 * i]) == o.x && static_cast<int>(out[6 * i + 1]) == o.y;
        const float g[4] = {glint_test::from_words<float>({out[6 * i + 2]})[0], glint_test::from_words<float>({out[6 * i + 3]})[0],
                            glint_test::from_words<float>({out[6 * i + 4]})[0], glint_test::from_words<float>({out[6 * i + 5]})[0]};
        copies += g[0] == c.anchor.x && g[1] == c.anchor.y && g[3] == c.offset.y && std::fabs(g[2] - c.a.x) <= 1e-6f;
    }
    MESSAGE(owners << " of " << n << " owners equal, " << copies << " anchors and offsets equal");
    CHECK(owners == n);
    CHECK(copies == n);
}

TEST_CASE("ndf_map: the P-NDF and its sampler, GLSL against C++ on tiled, transformed and stochastic layouts") {
    const auto m = parity_map();
    const placement layouts[] = {placement::tiled(), placement::tiled(glm::mat2(0.8f, 0.5f, -0.9f, 1.1f), glm::vec2(3, -7)),
                                 placement::stochastic(14.0f, 9u, glm::vec2(0, 6.2831853f), glm::vec2(0.7f, 1.4f), 0.5f)};
    const char* names[] = {"tiled", "tiled, sheared and rotated", "stochastic"};
    float peak = 0;
    for (std::size_t b = 0; b < m.images().size(); b += 4) peak = std::max(peak, m.images()[b]);
    for (int li = 0; li < 3; ++li) {
        const placement& pl = layouts[li];
        const std::size_t n = li == 2 ? 600 : 3000;
        std::vector<std::uint32_t> in;
        std::vector<glint::texel_footprint<float>> fps(n);
        std::vector<glm::vec2> ss(n);
        std::vector<glm::vec3> us(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            const float a = std::exp2(-1.5f + 9 * rnd(i, 3)), b = a * (0.2f + 0.8f * rnd(i, 4));
            fps[i] = glint_test::rotated_footprint(glm::vec2(200 * rnd(i, 5) - 100, 200 * rnd(i, 6) - 100), a, b, 6.28f * rnd(i, 7));
            ss[i] = {0.6f * rnd(i, 8) - 0.3f, 0.6f * rnd(i, 9) - 0.3f};
            us[i] = {rnd(i, 10), rnd(i, 11), rnd(i, 12)};
            const auto& c = fps[i].covariance;
            const float det = static_cast<float>(std::max(0.0, static_cast<double>(c[0][0]) * static_cast<double>(c[1][1]) -
                                                                   static_cast<double>(c[1][0]) * static_cast<double>(c[1][0])));
            glint_test::append_words(in, {fps[i].center.x, fps[i].center.y, c[0][0], c[1][0], c[1][1], det, ss[i].x, ss[i].y, us[i].x, us[i].y, us[i].z});
        }
        const std::string body =
            "uint b = 11u * i; vec2 mu = vec2(in_float(b), in_float(b + 1u)); vec4 cov = vec4(in_float(b + 2u), in_float(b + 3u), in_float(b + 4u), in_float(b + 5u));"
            " vec2 s = vec2(in_float(b + 6u), in_float(b + 7u));"
            " out0[5u * i] = floatBitsToUint(glint_ndf_pndf(p, pl, mu, cov, s));"
            " glint_ndf_draw d = glint_ndf_sample(p, pl, mu, cov, in_float(b + 8u), in_float(b + 9u), in_float(b + 10u));"
            " out0[5u * i + 1u] = floatBitsToUint(d.s.x); out0[5u * i + 2u] = floatBitsToUint(d.s.y); out0[5u * i + 3u] = floatBitsToUint(d.pdf_s);"
            " out0[5u * i + 4u] = d.valid ? 1u : 0u;";
        const auto words = run_with_map(m, params_glsl(m.kernel_params(), "p") + placement_glsl(pl.k, "pl"), body, in, n, 5);
        const auto out = glint_test::from_words<float>(words);
        std::size_t over = 0, non_finite = 0, positive = 0, sample_mismatch = 0, valid = 0;
        double worst = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const float cpu = m.eval(pl, fps[i], ss[i]), gpu = out[5 * i];
            non_finite += !std::isfinite(gpu);
            positive += cpu > 0;
            const double d = std::fabs(static_cast<double>(gpu) - static_cast<double>(cpu)) / static_cast<double>(peak);
            worst = std::max(worst, d);
            over += d > 1e-3;
            const auto cs = m.sample(pl, fps[i], us[i].x, us[i].y, us[i].z);
            const bool gv = words[5 * i + 4] != 0;
            valid += cs.valid;
            const bool same = cs.valid == gv && (!cs.valid || (std::fabs(cs.s.x - out[5 * i + 1]) <= 1e-4f && std::fabs(cs.s.y - out[5 * i + 2]) <= 1e-4f &&
                                                              std::fabs(cs.pdf_s - out[5 * i + 3]) <= 1e-3f * std::max(cs.pdf_s, 1.0f)));
            sample_mismatch += !same;
        }
        const double rate = static_cast<double>(over) / static_cast<double>(n), srate = static_cast<double>(sample_mismatch) / static_cast<double>(n);
        MESSAGE(std::string(names[li]) << ": " << n << " queries (" << positive << " positive), largest difference " << worst << " of the peak density, mismatch rate "
                          << rate << "; samples: " << valid << " valid, mismatch rate " << srate);
        CHECK(positive > n / 10);
        CHECK(non_finite == 0u);
        CHECK(worst < NDF_MAP_GLSL_MAX_DIFFERENCE);
        CHECK(rate <= NDF_MAP_GLSL_MAX_MISMATCH_RATE);
        CHECK(srate <= NDF_MAP_GLSL_MAX_MISMATCH_RATE);
    }
}

TEST_CASE("ndf_map: the coated BRDF (Eq. 10), GLSL against C++") {
    const std::size_t n = 20000;
    std::vector<std::uint32_t> in;
    std::vector<float> cpu(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::vec3 wi = glm::normalize(glm::vec3(rnd(i, 1) - 0.5f, rnd(i, 2) - 0.5f, rnd(i, 3) + 0.05f));
        const glm::vec3 wo = glm::normalize(glm::vec3(rnd(i, 4) - 0.5f, rnd(i, 5) - 0.5f, rnd(i, 6) - 0.1f));
        const float db = 10 * rnd(i, 7), dc = 10 * rnd(i, 8), ab = 0.05f + 0.5f * rnd(i, 9), ac = 0.05f + 0.5f * rnd(i, 10), eb = 0.1f + 2 * rnd(i, 11),
                    kb = 4 * rnd(i, 12), ec = 1 + rnd(i, 13);
        glint_test::append_words(in, {wi.x, wi.y, wi.z, wo.x, wo.y, wo.z, db, dc, ab, ac, eb, kb, ec});
        cpu[i] = K::glint_ndf_coated_brdf(db, dc, wi, wo, glm::vec2(ab), glm::vec2(ac), eb, kb, ec);
    }
    const std::string body =
        "uint b = 13u * i; vec3 wi = vec3(in_float(b), in_float(b + 1u), in_float(b + 2u)); vec3 wo = vec3(in_float(b + 3u), in_float(b + 4u), in_float(b + 5u));"
        " out0[i] = floatBitsToUint(glint_ndf_coated_brdf(in_float(b + 6u), in_float(b + 7u), wi, wo, vec2(in_float(b + 8u)), vec2(in_float(b + 9u)),"
        " in_float(b + 10u), in_float(b + 11u), in_float(b + 12u)));";
    const auto gpu = glint_test::from_words<float>(glint_test::map_words({"core.glsl", "microfacet.glsl", "gaussian.glsl", "ndf_map.glsl"}, body, in, n, 1));
    double worst = 0;
    std::size_t positive = 0;
    for (std::size_t i = 0; i < n; ++i) {
        worst = std::max(worst, std::fabs(static_cast<double>(gpu[i]) - static_cast<double>(cpu[i])) / std::max(static_cast<double>(cpu[i]), 1e-3));
        positive += cpu[i] > 0;
    }
    MESSAGE("coated BRDF: " << positive << " positive of " << n << ", largest relative difference " << worst);
    CHECK(positive > n / 4);
    CHECK(worst < GAUSSIAN_GLSL_MAX_RELATIVE);
}
