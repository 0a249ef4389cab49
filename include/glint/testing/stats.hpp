// glint's statistical test kit: the tests a sampler or estimator must pass, each with the
// bookkeeping that keeps it honest (pooling, family-wise significance, a resolution check).
//
//   chi_square         Pearson's test of counts against probabilities, pooling cells with low
//                      expectation, as many degrees of freedom as cells remain minus one
//   sidak_alpha        per-test significance for a family-wise significance over m tests
//   ks_test            Kolmogorov-Smirnov of samples against a model CDF evaluated at given points
//                      (discrete and mixed distributions: the p-value is conservative)
//   wasserstein1       W1 between two samples, or between samples and a CDF on a grid
//   mean_test          two-sided z-test of a mean that states whether it can resolve a tolerance
//
// Header-only, double precision, no dependency beyond the standard library. Bad input (empty
// samples, probabilities that do not sum to 1, mismatched sizes) throws std::invalid_argument
// naming the function and the value.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/testing/special.hpp"

namespace glint {
namespace testing {

// 1 - (1 - family_alpha)^(1/tests): each of `tests` independent tests at this level gives the
// family a false-rejection probability of exactly `family_alpha`.
inline double sidak_alpha(double family_alpha, int tests) {
    if (!(family_alpha > 0 && family_alpha < 1) || tests < 1) {
        std::ostringstream m;
        m << "glint::testing::sidak_alpha: needs 0 < family_alpha < 1 and tests >= 1, got " << family_alpha << ", " << tests;
        throw std::invalid_argument(m.str());
    }
    return -std::expm1(std::log1p(-family_alpha) / tests);
}

struct chi_square_result {
    double statistic = 0;
    int degrees_of_freedom = 0;
    double p_value = 1;
    std::size_t cells = 0;  // after pooling
    bool rejects(double alpha) const { return p_value < alpha; }
};

// Pearson's chi-square test of `observed` counts against cell `probabilities` (summing to 1
// within 1e-9). Adjacent cells are pooled, in order, until each pooled cell expects at least
// `min_expected` counts; a short remainder joins the last pooled cell. `fitted_parameters` are
// subtracted from the degrees of freedom.
inline chi_square_result chi_square(const std::vector<double>& observed, const std::vector<double>& probabilities,
                                    double min_expected = 5.0, int fitted_parameters = 0) {
    if (observed.size() != probabilities.size() || observed.empty()) {
        std::ostringstream m;
        m << "glint::testing::chi_square: " << observed.size() << " observed cells but " << probabilities.size() << " probabilities";
        throw std::invalid_argument(m.str());
    }
    const double total_p = std::accumulate(probabilities.begin(), probabilities.end(), 0.0);
    if (std::fabs(total_p - 1) > 1e-9) {
        std::ostringstream m;
        m << "glint::testing::chi_square: probabilities sum to " << total_p << ", not 1";
        throw std::invalid_argument(m.str());
    }
    const double n = std::accumulate(observed.begin(), observed.end(), 0.0);
    chi_square_result r;
    for (std::size_t i = 0; i < observed.size(); ++i)
        if (probabilities[i] <= 0 && observed[i] > 0) {
            // An observation where none can occur: no pooling may hide it.
            r.statistic = std::numeric_limits<double>::infinity();
            r.p_value = 0;
            return r;
        }
    std::vector<double> o, e;
    double oc = 0, ec = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        oc += observed[i];
        ec += probabilities[i] * n;
        if (ec >= min_expected) {
            o.push_back(oc), e.push_back(ec);
            oc = ec = 0;
        }
    }
    if (ec > 0 || oc > 0) {
        if (e.empty()) o.push_back(oc), e.push_back(ec);
        else o.back() += oc, e.back() += ec;
    }
    r.cells = o.size();
    for (std::size_t i = 0; i < o.size(); ++i)
        if (e[i] > 0) r.statistic += (o[i] - e[i]) * (o[i] - e[i]) / e[i];
    r.degrees_of_freedom = static_cast<int>(o.size()) - 1 - fitted_parameters;
    if (r.degrees_of_freedom < 1) {
        // One cell after pooling: the test cannot distinguish anything.
        r.degrees_of_freedom = 0;
        r.p_value = 1.0;
        return r;
    }
    r.p_value = chi_square_survival(r.statistic, r.degrees_of_freedom);
    return r;
}

struct ks_result {
    double statistic = 0;  // max |F_n(x) - F(x)| over the evaluation points
    double p_value = 1;    // asymptotic Kolmogorov with Stephens' small-sample correction
    bool rejects(double alpha) const { return p_value < alpha; }
};

// Kolmogorov-Smirnov test of `samples` against a model whose right-continuous CDF `cdf` is
// compared with the empirical CDF at `points` (for an integer-valued or mixed model, its
// support points and half-integers). The statistic is at most the continuous supremum, so the
// Kolmogorov p-value is conservative: the test keeps its level.
inline ks_result ks_test(std::vector<double> samples, const std::function<double(double)>& cdf, const std::vector<double>& points) {
    if (samples.empty() || points.empty()) throw std::invalid_argument("glint::testing::ks_test: empty samples or points");
    std::sort(samples.begin(), samples.end());
    const double n = static_cast<double>(samples.size());
    ks_result r;
    for (double x : points) {
        const double empirical = static_cast<double>(std::upper_bound(samples.begin(), samples.end(), x) - samples.begin()) / n;
        r.statistic = std::max(r.statistic, std::fabs(empirical - cdf(x)));
    }
    const double sn = std::sqrt(n);
    r.p_value = kolmogorov_survival((sn + 0.12 + 0.11 / sn) * r.statistic);
    return r;
}

// W1 between two samples: the integral of |F_a - F_b| over the merged support.
inline double wasserstein1(std::vector<double> a, std::vector<double> b) {
    if (a.empty() || b.empty()) throw std::invalid_argument("glint::testing::wasserstein1: empty sample");
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
    std::size_t i = 0, j = 0;
    double x = std::min(a[0], b[0]), w = 0;
    while (i < a.size() || j < b.size()) {
        const double next = (j >= b.size() || (i < a.size() && a[i] <= b[j])) ? a[i] : b[j];
        w += std::fabs(static_cast<double>(i) / na - static_cast<double>(j) / nb) * (next - x);
        x = next;
        while (i < a.size() && a[i] == x) ++i;
        while (j < b.size() && b[j] == x) ++j;
    }
    return w;
}

// W1 between two distributions given by their CDFs, integrated on [lo, hi] by the midpoint
// rule with `steps` cells (both CDFs must be 0 below lo and 1 above hi).
inline double wasserstein1(const std::function<double(double)>& cdf_a, const std::function<double(double)>& cdf_b, double lo,
                           double hi, int steps) {
    if (!(hi > lo) || steps < 1) throw std::invalid_argument("glint::testing::wasserstein1: needs hi > lo and steps >= 1");
    const double h = (hi - lo) / steps;
    double w = 0;
    for (int k = 0; k < steps; ++k) {
        const double x = lo + (k + 0.5) * h;
        w += std::fabs(cdf_a(x) - cdf_b(x));
    }
    return w * h;
}

// Running mean and variance (Welford), for sample counts too large to store.
struct running_moments {
    double count = 0, mean = 0, m2 = 0;
    void add(double x) {
        count += 1;
        const double d = x - mean;
        mean += d / count;
        m2 += d * (x - mean);
    }
    double variance() const { return count > 1 ? m2 / (count - 1) : 0; }
    double standard_error() const { return count > 0 ? std::sqrt(variance() / count) : std::numeric_limits<double>::infinity(); }
};

struct mean_test_result {
    double mean = 0, expected = 0, standard_error = 0, z = 0, p_value = 1;
    // The smallest |mean - expected| the test detects with probability 0.9 at its alpha:
    // (z_{alpha/2} + z_{0.1}) standard errors.
    double resolution = 0;
    bool resolves(double tolerance) const { return resolution <= tolerance; }
    bool rejects(double alpha) const { return p_value < alpha; }
};

// Two-sided z-test that the population mean behind `moments` equals `expected`. Call
// resolves(tolerance) before trusting a pass: a test whose standard error is too large to see
// a deviation of `tolerance` passes vacuously.
inline mean_test_result mean_test(const running_moments& moments, double expected, double alpha) {
    if (moments.count < 2) throw std::invalid_argument("glint::testing::mean_test: needs at least 2 samples");
    mean_test_result r;
    r.mean = moments.mean;
    r.expected = expected;
    r.standard_error = moments.standard_error();
    const double d = moments.mean - expected;
    r.z = r.standard_error > 0 ? d / r.standard_error : (d == 0 ? 0.0 : std::numeric_limits<double>::infinity());
    r.p_value = std::isinf(r.z) ? 0.0 : std::erfc(std::fabs(r.z) / std::sqrt(2.0));
    r.resolution = (normal_upper_quantile(alpha / 2) + normal_upper_quantile(0.1)) * r.standard_error;
    return r;
}

}  // namespace testing
}  // namespace glint
