// For the programs that make the mean-preserving binomial sampler's tables (glint/binomial.hpp,
// steps 2 to 4), in double: the clamped Gaussian max(t + Z, 0), psi(t) = E[max(t + Z, 0)] and
// chi(t) = E[max(t + Z, 0)^2] for a standard normal Z, and the exact one-sided solution.
#pragma once

#include <algorithm>
#include <cmath>

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

}  // namespace glint_bench
