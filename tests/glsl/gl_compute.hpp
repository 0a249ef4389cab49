// Headless OpenGL 4.5 compute runner for the GLSL parity tests: an EGL surfaceless context on
// Mesa's llvmpipe (software, on the CPU), std430 buffers in and out, dispatch, read back.
#pragma once

#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

namespace glint_test {

class gl_compute {
public:
    // Creates the context. Forces Mesa's software rasterizer (LIBGL_ALWAYS_SOFTWARE=1) so that
    // results do not depend on a GPU driver. Throws std::runtime_error naming the failing step.
    gl_compute();
    ~gl_compute();
    gl_compute(const gl_compute&) = delete;
    gl_compute& operator=(const gl_compute&) = delete;

    // "GL_RENDERER" and "GL_VERSION" of the context.
    std::string renderer() const;
    std::string version() const;

    // Compiles and links a compute shader; throws with the info log on failure.
    unsigned program(const std::string& source);

    // Runs `prog` with each of `inputs` bound read-only at bindings 0..k-1 and an output of
    // `output_words` 32-bit words at binding k; `invocations` threads are dispatched (the shader
    // should loop with a grid stride if `invocations` exceeds 64 * 65535). Returns the output.
    std::vector<std::uint32_t> run(unsigned prog,
                                   const std::vector<std::vector<std::uint32_t>>& inputs,
                                   std::size_t output_words, std::size_t invocations);

    // An RGBA32F 2D texture on unit 0 with GL_LINEAR filtering, GL_REPEAT in s and
    // GL_CLAMP_TO_EDGE in t (an equirectangular environment map); rows bottom to top as GL
    // addresses them (row y at t = (y + 1/2) / height). Returns its name.
    unsigned texture_rgba32f(int width, int height, const std::vector<float>& rgba);
    // An RGBA32F 2D array texture on unit 0 (layer after layer, rows bottom to top), GL_NEAREST:
    // shaders read it with texelFetch.
    unsigned texture_array_rgba32f(int width, int height, int layers, const std::vector<float>& rgba);
    void delete_texture(unsigned texture);

    struct impl;

private:
    std::unique_ptr<impl> impl_;
};

// The local size every parity shader declares, and the most groups one dispatch uses.
constexpr unsigned local_size = 64;
constexpr unsigned max_groups = 65535;

// "#version 450", the local size, and the given glint kernel files, in order (an entry that
// starts with "#define " is a line of its own, for the kernels' configuration macros).
std::string shader_header(const std::vector<std::string>& kernel_files);

template <class T>
std::vector<std::uint32_t> to_words(const std::vector<T>& v) {
    static_assert(sizeof(T) % 4 == 0, "32-bit words only");
    std::vector<std::uint32_t> w(v.size() * sizeof(T) / 4);
    if (!v.empty()) std::memcpy(w.data(), v.data(), w.size() * 4);
    return w;
}

// Appends the floats' bit patterns to a word buffer.
inline void append_words(std::vector<std::uint32_t>& words, std::initializer_list<float> values) {
    const std::vector<std::uint32_t> w = to_words(std::vector<float>(values));
    words.insert(words.end(), w.begin(), w.end());
}

template <class T>
std::vector<T> from_words(const std::vector<std::uint32_t>& w) {
    static_assert(sizeof(T) % 4 == 0, "32-bit words only");
    std::vector<T> v(w.size() * 4 / sizeof(T));
    if (!v.empty()) std::memcpy(v.data(), w.data(), v.size() * sizeof(T));
    return v;
}

// Distance in units in the last place between two floats (0 if both are the same NaN class;
// a large sentinel if one is NaN and the other is not).
std::int64_t ulp_distance(float a, float b);

}  // namespace glint_test
