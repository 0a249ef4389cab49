// Runs a test's comparisons once for each of glint's vector paths that this build and CPU have
// (glint_cpu_lanes, kernels/core.glsl): the AVX2 code built with AVX-512 (2) and for AVX2 alone
// (1), or where neither runs, once on the baseline code (0), whose one-at-a-time fallbacks the
// comparisons then check against themselves. glint::detail::lanes_limit selects the path; the
// test's output names each path run, so a CPU without AVX-512 shows that it tested AVX2 only.
#pragma once

#include <doctest/doctest.h>

#include <glint/detail/kernels.hpp>

#include <string>

namespace glint_test {

inline std::string lanes_path_name(int path) {
    return path == 2 ? "AVX2 with AVX-512" : path == 1 ? "AVX2" : "baseline (no vector path in this build or CPU)";
}

// body(path) for each path, the widest first; the limit is restored afterwards.
template <class F>
void for_each_lanes_path(F&& body) {
    using K = glint::detail::glsl::kernels<float>;
    glint::detail::lanes_limit = 2;
    const int widest = K::glint_cpu_lanes();
    struct restore {
        ~restore() { glint::detail::lanes_limit = 2; }
    } restore_limit;
    for (int path = widest; path >= (widest > 0 ? 1 : 0); --path) {
        glint::detail::lanes_limit = path;
        MESSAGE("vector path: " << lanes_path_name(path));
        INFO("vector path: " << lanes_path_name(path));
        body(path);
    }
}

}  // namespace glint_test
