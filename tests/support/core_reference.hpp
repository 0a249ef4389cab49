// Exact references for the core numerics, from an independent implementation (Boost.Math and
// long double), and the sweeps the tests and the accuracy report share.
#pragma once

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace glint_test {

inline double erfinv_exact(double x) { return boost::math::erf_inv(x); }

// Phi^-1(u) = -sqrt(2) erfc^-1(2u): accurate in both tails, unlike sqrt(2) erf^-1(2u - 1).
inline double normal_quantile_exact(double u) {
    return -1.4142135623730950488 * boost::math::erfc_inv(2.0 * u);
}

// (1 - p)^N and 1 - (1 - p)^N in long double (64-bit mantissa) for inputs exactly
// representable in the type under test.
inline long double pow_one_minus_exact(long double p, long double N) {
    if (N == 0) return 1;
    if (p >= 1) return 0;
    return expl(N * log1pl(-p));
}
inline long double any_success_exact(long double p, long double N) {
    if (N == 0) return 0;
    if (p >= 1) return 1;
    return -expm1l(N * log1pl(-p));
}

inline float float_from_bits(std::uint32_t b) {
    float f;
    std::memcpy(&f, &b, 4);
    return f;
}

// Floats in [0, 1): every `stride`-th bit pattern from +0 up to 1, then every float of the
// last `dense_tail` below 1. With stride 100 that is 1.07e7 values covering every binade.
inline std::vector<float> unit_interval_sweep(std::uint32_t stride, std::uint32_t dense_tail) {
    const std::uint32_t one = 0x3f800000u;
    std::vector<float> xs;
    xs.reserve(one / stride + dense_tail + 1);
    for (std::uint32_t b = 0; b < one - dense_tail; b += stride) xs.push_back(float_from_bits(b));
    for (std::uint32_t b = one - dense_tail; b < one; ++b) xs.push_back(float_from_bits(b));
    return xs;
}

// The (p, N) grid of docs/pow_one_minus.md: p = 10^(-k/4) for k = 0..64 (1 down to 1e-16),
// plus p near 1 and p = 0; N in 0, 1e-3, 0.5, 1, 1.5, 2, 3, 5 and 10^(j/2) for j = 2..32.
inline std::vector<double> pow_grid_p() {
    std::vector<double> ps = {0.0, 1.0 - 1e-6, 1.0 - 1e-3, 0.5};
    for (int k = 0; k <= 64; ++k) ps.push_back(std::pow(10.0, -k / 4.0));
    return ps;
}
inline std::vector<double> pow_grid_n() {
    std::vector<double> ns = {0.0, 1e-3, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0};
    for (int j = 2; j <= 32; ++j) ns.push_back(std::pow(10.0, j / 2.0));
    return ns;
}

}  // namespace glint_test
