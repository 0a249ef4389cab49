// How far an approximate binomial sampler's closed-form distribution (binomial_models.hpp) is
// from the exact binomial (binomial_reference.hpp), without randomness: bias of the mean,
// variance error, P(n = 0) error, W1 / sigma, and KS at the half-integers. Needs Boost.Math.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "glint/testing/binomial_models.hpp"
#include "glint/testing/binomial_reference.hpp"

namespace glint {
namespace testing {

struct binomial_distance {
    double mean_bias = 0;       // (E_model - N p) / (N p); E_model itself when N p = 0
    double variance_error = 0;  // Var_model / Var_exact - 1; Var_model when Var_exact = 0
    double p0_error = 0;        // P_model(0) / P_exact(0) - 1; P_model(0) when P_exact(0) = 0
    double w1_over_sigma = 0;   // W1 / sqrt(Var_exact); W1 when Var_exact = 0
    double ks = 0;              // max |F_model - F_exact| at the half-integers
};

// The exact CDF on the cells where the two distributions can differ, shared by all variants
// at one (N, p). Cells are the unit intervals [k, k + 1) where the support spans at most
// `max_cells` integers; otherwise `max_cells` equal cells (then W1 is integrated by the midpoint
// rule with the exact CDF sampled at cell midpoints, an error of W1 / sigma below 1 / sigma,
// and KS looks at one half-integer per cell).
class binomial_comparison {
public:
    binomial_comparison(double N, double p, double max_cells = 20000)
        : N_(std::max(N, 0.0)), p_(std::min(std::max(p, 0.0), 1.0)), exact_(N_, p_) {
        const double sd = std::sqrt(exact_.variance()), mean = exact_.mean();
        lo_ = std::max(0.0, std::floor(mean - 40 * sd) - 2);
        hi_ = std::min(std::ceil(N_) + 1, std::ceil(mean + 40 * sd) + 2);
        unit_ = (hi_ - lo_) <= max_cells;
        cells_ = unit_ ? static_cast<std::size_t>(hi_ - lo_) : static_cast<std::size_t>(max_cells);
        width_ = (hi_ - lo_) / static_cast<double>(cells_);
        for (std::size_t i = 0; i < cells_; ++i) exact_cdf_.push_back(exact_.cdf(half_integer(i)));
    }

    const binomial_exact& exact() const { return exact_; }

    binomial_distance distance(const binomial_model& m) const {
        binomial_distance d;
        const double np = exact_.mean(), var = exact_.variance(), p0 = exact_.probability_zero();
        const double mm = m.mean(), mv = m.variance(), mp0 = m.probability_zero();
        d.mean_bias = np > 0 ? (mm - np) / np : mm;
        d.variance_error = var > 0 ? mv / var - 1 : mv;
        d.p0_error = p0 > 0 ? mp0 / p0 - 1 : mp0;
        // KS at the half-integers and W1 over the cells. Below lo and above hi both CDFs are
        // within 1e-300 of each other unless the model puts mass there; that mass is added.
        double w1 = 0;
        for (std::size_t i = 0; i < cells_; ++i) {
            const double x = half_integer(i), fe = exact_cdf_[i];
            d.ks = std::max(d.ks, std::fabs(m.cdf(x) - fe));
            const double a = lo_ + static_cast<double>(i) * width_;
            if (unit_) {
                double s = 0;  // 8-point midpoint rule inside the unit cell, where F_exact is constant
                for (int j = 0; j < 8; ++j) s += std::fabs(m.cdf(a + (j + 0.5) / 8) - fe);
                w1 += s / 8;
            } else {
                w1 += std::fabs(m.cdf(a + 0.5 * width_) - fe) * width_;
            }
        }
        w1 += outside_mass(m);
        d.w1_over_sigma = var > 0 ? w1 / std::sqrt(var) : w1;
        return d;
    }

private:
    double half_integer(std::size_t i) const {
        return unit_ ? lo_ + static_cast<double>(i) + 0.5 : std::floor(lo_ + (static_cast<double>(i) + 0.5) * width_) + 0.5;
    }
    // W1 contribution of model mass outside [lo, hi], where the exact CDF is 0 below lo and 1
    // above hi (to within 1e-300): E[(lo - n)+] + E[(n - hi)+] of the model.
    double outside_mass(const binomial_model& m) const { return m.deficit_below(lo_) + m.excess_above(hi_); }

    double N_, p_;
    binomial_exact exact_;
    double lo_ = 0, hi_ = 0, width_ = 1;
    bool unit_ = true;
    std::size_t cells_ = 0;
    std::vector<double> exact_cdf_;
};

// The (N, p) grid of the model tables and tests: 17 values of N from 0 to 1e16 times 19 values
// of p from 1e-16 to 1, 323 points.
inline std::vector<double> binomial_grid_n() {
    return {0, 1e-3, 0.5, 1, 1.5, 2, 3, 5, 10, 30, 100, 1e3, 1e4, 1e6, 1e9, 1e12, 1e16};
}
inline std::vector<double> binomial_grid_p() {
    return {1e-16, 1e-14, 1e-12, 1e-10, 1e-8, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.03, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1 - 1e-6, 1};
}

}  // namespace testing
}  // namespace glint
