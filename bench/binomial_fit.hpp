// For the programs that make the mean-preserving binomial sampler's tables (glint/binomial.hpp,
// steps 2 to 4), in double: the clamped Gaussian max(t + Z, 0), psi(t) = E[max(t + Z, 0)] and
// chi(t) = E[max(t + Z, 0)^2] for a standard normal Z, the exact one-sided solution, and the
// tables' printing and lookup as the kernels read them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glint/binomial.hpp>

namespace glint_bench {

inline double normal_cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }
inline double normal_pdf(double t) { return std::exp(-t * t / 2) / std::sqrt(2 * M_PI); }
inline double psi(double t) { return t * normal_cdf(t) + normal_pdf(t); }
inline double chi(double t) { return (t * t + 1) * normal_cdf(t) + t * normal_pdf(t); }

// The t at which Var[max(t + Z, 0)] / E[max(t + Z, 0)]^2 = ratio (the ratio decreases in t), by
// bisection on [-12, 40].
inline double t_of_ratio(double ratio) {
    double lo = -12, hi = 40;
    for (int i = 0; i < 200; ++i) {
        const double mid = (lo + hi) / 2;
        (chi(mid) / (psi(mid) * psi(mid)) - 1 > ratio ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// (t, sigma) such that sigma max(t + Z, 0) has mean m and variance v: the one-sided fit solved
// exactly (the kernels' glint_binomial_one_sided_fit approximates it by polynomials).
inline glm::dvec2 one_sided_exact(double m, double v) {
    const double t = t_of_ratio(v / (m * m));
    return {t, m / psi(t)};
}

// Prints a table of (value, value) pairs per node as kernels/binomial.glsl holds it: each value
// rounded to float, four to a GLINT_FLOAT4, padded to whole vec4s.
inline void print_table(const char* name, const std::vector<double>& table) {
    const int floats = static_cast<int>(table.size());
    std::printf("GLINT_FLOAT_TABLE(%s, %d) GLINT_TABLE_OPEN\n", name, floats);
    for (int k = 0; k < floats; k += 4) {
        auto f = [&](int d) { return static_cast<double>(static_cast<float>(table[static_cast<std::size_t>(k + d)])); };
        std::printf("%sGLINT_FLOAT4(%.8ef, %.8ef, %.8ef, %.8ef)%s", k % 8 == 0 ? "    " : " ", f(0), f(1), f(2), f(3),
                    k + 4 == floats ? "\n" : (k % 8 == 4 ? ",\n" : ","));
    }
    std::printf("GLINT_TABLE_CLOSE;\n");
}

// The kernels' read of such a table at fractional node coordinates (fr, fc), clamped to the
// table: cubic Lagrange in both axes on a 4 x 4 stencil (glint_cubic_weights), centred except
// in the edge cells, on the values rounded to float.
inline glm::dvec2 table_lookup(const std::vector<double>& table, int rows, int columns, double fr, double fc) {
    fr = std::fmin(std::fmax(fr, 0.0), rows - 1), fc = std::fmin(std::fmax(fc, 0.0), columns - 1);
    const int i = std::min(std::max(static_cast<int>(fr) - 1, 0), rows - 4), j = std::min(std::max(static_cast<int>(fc) - 1, 0), columns - 4);
    using K = glint::detail::glsl::kernels<double>;
    const glm::dvec4 wr = K::glint_cubic_weights(fr - i - 1), wc = K::glint_cubic_weights(fc - j - 1);
    glm::dvec2 c(0);
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            for (int k = 0; k < 2; ++k)
                c[k] += wr[a] * wc[b] * static_cast<double>(static_cast<float>(table[static_cast<std::size_t>(2 * ((i + a) * columns + j + b) + k)]));
    return c;
}

}  // namespace glint_bench
