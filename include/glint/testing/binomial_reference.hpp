// The exact binomial distribution, as the reference that glint's approximate samplers are
// judged against: its CDF and moments for real N, and an exact sampler. Needs Boost.Math
// (header-only); include it in tests and tools, not in shading code.
//
// Real-valued N. The target for real N >= 0 is the randomised-rounding binomial: with
// N = n0 + f, n0 = floor(N), draw b(n0 + 1, p) with probability f and b(n0, p) otherwise. It is
// exact at integer N, continuous in N, and has E = N p, Var = N p (1 - p) + f (1 - f) p^2.
#pragma once

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/poisson.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace glint {
namespace testing {

class binomial_exact {
public:
    // Rejects N < 0, N > 1e18, p outside [0, 1], NaN. (Above 2^53 every double is an integer,
    // so N is then integer and sampled counts are rounded to representable values.)
    binomial_exact(double N, double p) : N_(N), p_(p) {
        if (!(N >= 0 && N <= 1e18) || !(p >= 0 && p <= 1)) {
            std::ostringstream m;
            m << "glint::testing::binomial_exact: needs 0 <= N <= 1e18 and 0 <= p <= 1, got N = " << N << ", p = " << p;
            throw std::invalid_argument(m.str());
        }
        n0_ = std::floor(N);
        f_ = N - n0_;
    }

    double mean() const { return N_ * p_; }
    double variance() const { return N_ * p_ * (1 - p_) + f_ * (1 - f_) * p_ * p_; }

    // P(n = 0) = (1 - f)(1 - p)^n0 + f (1 - p)^(n0 + 1), without cancellation.
    double probability_zero() const {
        if (p_ >= 1) return n0_ == 0 ? 1 - f_ : 0.0;
        const double q = std::exp(n0_ * std::log1p(-p_));
        return q * (1 - f_ + f_ * (1 - p_));
    }

    // P(n <= x).
    double cdf(double x) const {
        if (x < 0) return 0;
        const double k = std::floor(x);
        double F = (1 - f_) * integer_cdf(n0_, k);
        if (f_ > 0) F += f_ * integer_cdf(n0_ + 1, k);
        return F;
    }

    // Exact sampling by inversion: u_round picks the integer count (probability f for n0 + 1),
    // u the quantile. Returns the smallest k with P(n <= k) >= u. For p <= 1e-8 it draws from
    // Poisson(n p) instead, whose total-variation distance from b(n, p) is at most n p^2 (Le Cam
    // 1960), i.e. below 1e-8 times the mean.
    double sample(double u_round, double u) const {
        const double n = n0_ + (u_round < f_ ? 1 : 0);
        if (n == 0 || p_ == 0) return 0;
        if (p_ >= 1) return n;
        const double mean = n * p_, sd = std::sqrt(n * p_ * (1 - p_));
        // Bracket the answer around the normal approximation, k0 = mean + sd z(u), whose error in
        // counts is below 1 + |1 - 2p| (z^2 + 1) / 6 (the Cornish-Fisher skewness term); widen by
        // doubling until F(lo) < u <= F(hi) (F(-1) = 0, F(n) = 1), then bisect. A handful of CDF
        // evaluations whatever N is (each costs up to 0.5 ms in Boost at N = 1e16).
        const double z = -1.4142135623730951 * boost::math::erfc_inv(2 * std::min(std::max(u, 1e-300), 1 - 1e-16));
        const double k0 = std::floor(mean + sd * z);
        double width = 2 + std::fabs(1 - 2 * p_) * (z * z + 1);
        double lo = std::max(-1.0, k0 - width), hi = std::min(n, k0 + width);
        while (lo > -1 && integer_cdf_sampling(n, lo) >= u) lo = std::max(-1.0, lo - (width *= 2));
        while (hi < n && integer_cdf_sampling(n, hi) < u) hi = std::min(n, hi + (width *= 2));
        // Invariant: F(lo) < u <= F(hi).
        while (hi - lo > 1) {
            const double mid = std::floor((lo + hi) / 2);
            if (mid <= lo || mid >= hi) break;  // above 2^53 neighbouring doubles are 2 apart
            (integer_cdf_sampling(n, mid) < u ? lo : hi) = mid;
        }
        return hi;
    }

private:
    double integer_cdf(double n, double k) const {
        if (k < 0) return 0;
        if (k >= n) return 1;
        if (p_ == 0) return 1;
        if (p_ >= 1) return 0;
        return boost::math::cdf(boost::math::binomial_distribution<double>(n, p_), k);
    }
    double integer_cdf_sampling(double n, double k) const {
        if (k < 0) return 0;
        if (k >= n) return 1;
        if (p_ <= 1e-8) return boost::math::cdf(boost::math::poisson_distribution<double>(n * p_), k);
        return integer_cdf(n, k);
    }

    double N_, p_, n0_ = 0, f_ = 0;
};

}  // namespace testing
}  // namespace glint
