// Special functions the statistics kit needs, in double, with no dependency beyond <cmath>:
// the regularized upper incomplete gamma function (chi-square p-values) and the Kolmogorov
// distribution (KS p-values). The tests compare them with Boost.Math.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>

namespace glint {
namespace testing {

// Q(a, x) = Gamma(a, x) / Gamma(a), a > 0, x >= 0. Series of P(a, x) for x < a + 1, Legendre's
// continued fraction of Q(a, x) (evaluated by the modified Lentz method) otherwise; both are
// summed until the relative change is below 1e-15. Relative accuracy about 1e-13 except where
// Q is below 1e-300.
inline double gamma_q(double a, double x) {
    if (!(a > 0) || !(x >= 0)) throw std::invalid_argument("glint::testing::gamma_q: needs a > 0 and x >= 0");
    if (x == 0) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    const double tiny = 1e-300;
    if (x < a + 1) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-16) break;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1) < 1e-16) break;
    }
    return std::exp(log_prefix) * h;
}

// Upper tail of the chi-square distribution with `dof` degrees of freedom.
inline double chi_square_survival(double statistic, double dof) { return gamma_q(dof / 2, std::max(statistic, 0.0) / 2); }

// Upper tail of the Kolmogorov distribution, P(K > lambda) = 2 sum_j (-1)^(j-1) exp(-2 j^2 lambda^2).
inline double kolmogorov_survival(double lambda) {
    if (lambda <= 0) return 1.0;
    if (lambda < 0.2) return 1.0;  // the series converges slowly here; the value is 1 - 1e-20
    double sum = 0;
    for (int j = 1; j < 200; ++j) {
        const double term = std::exp(-2.0 * j * j * lambda * lambda);
        sum += (j % 2 ? term : -term);
        if (term < 1e-18) break;
    }
    return std::min(1.0, std::max(0.0, 2 * sum));
}

// Upper-tail quantile of the standard normal: z with P(Z > z) = alpha, by bisection on erfc.
inline double normal_upper_quantile(double alpha) {
    if (!(alpha > 0 && alpha < 1)) throw std::invalid_argument("glint::testing::normal_upper_quantile: needs 0 < alpha < 1");
    double lo = -40, hi = 40;
    for (int i = 0; i < 200; ++i) {
        const double mid = (lo + hi) / 2;
        (0.5 * std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

}  // namespace testing
}  // namespace glint
