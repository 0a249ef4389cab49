// Reproduces GLINT_BINOMIAL_FAR_TABLE (kernels/binomial.glsl): the mean-preserving sampler's
// two-sided fit for N < 32. At every node (N, x) of a 41 x 41 grid,
//   rows:    ((N - 3) / 29)^(1/4) uniform from 0 to 1 (N from 3 to 32; dense near N = 3, where
//            the correction grows like -0.75 log(N - 3)),
//   columns: x = log2(p) + 20 p uniform from -20 to 9 (p from 9.5e-7 to 1/2; steps of 0.72 in
//            log2 p where p is small and the correction follows log p, of 0.03 in p near 1/2),
// it takes the one-sided fit (t, sigma) of the middle's offset (mean m, variance v), solved
// exactly (bench/binomial_fit.hpp), and solves, in double by damped Newton steps on the closed-form
// moments of the capped offset (glint_capped_offset_moments), for the (t', sigma') that give
// min(sigma' max(t' + Z, 0), N - 2) the same m and v, starting from the solution of the node
// above (continuation from N = 32 down). The node stores (t', log(sigma' / sqrt(lambda))),
// lambda = N p (so that the sampler needs neither the ends nor m and v), blended into the one-sided
// fit's (t, log(sigma / sqrt(lambda))) from N = 26 to 32, where the one-sided fit takes over.
// At N = 3 itself (span 1) the fit is degenerate: row 0 holds the solution
// at N = 3 + 1e-5.
//
// It then measures what the kernel's interpolation (cubic Lagrange in both axes on a 4 x 4
// stencil, glint_cubic_weights, the table rounded to float) leaves, on a sweep 7.3 times finer than
// the nodes on each axis, in double: the largest relative errors of the capped offset's mean
// and variance (weighted by the Gaussian's share of the middle, min(N - 3, 1)), and of E[n]
// against N p over p from 2^-30 (below the table its first column is used).
//   glint_fit_binomial_far_bound            prints the table (stdout) and the errors (stderr)
//   glint_fit_binomial_far_bound --errors   the errors only, on stdout
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <glint/binomial.hpp>

#include "binomial_fit.hpp"

namespace {

using K = glint::detail::glsl::kernels<double>;

constexpr int rows = 41, columns = 41;
constexpr double n_min = 3, n_max = 32, x_min = -20, x_max = 9;

double n_of_row(double i) { return n_min + (n_max - n_min) * std::pow(i / (rows - 1), 4.0); }
double row_of_n(double N) { return std::sqrt(std::sqrt(std::fmax(N - n_min, 0.0) / (n_max - n_min))) * (rows - 1); }
constexpr double x_step = (x_max - x_min) / (columns - 1);
double x_of_p(double p) { return std::log2(p) + 20 * p; }
double p_of_x(double x) {  // x_of_p is increasing on (0, 1/2]
    double lo = 0, hi = 0.5;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (x_of_p(mid) < x ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

struct problem {
    double span, mean, second;  // target E[O] and E[O^2]
    glm::dvec2 fit;             // the one-sided (t, sigma)
};

problem problem_at(double N, double p) {
    const auto e = K::glint_binomial_unbiased_ends(N, p, K::GLINT_POW_LOG1P);
    const auto g = K::glint_binomial_middle_targets(N, p, e);
    return {N - 2, g.mean, g.variance + g.mean * g.mean, glint_bench::one_sided_exact(g.mean, g.variance)};
}

// Damped Newton on (mu, sigma) from (t, sigma) as given; whether it converged.
bool solve(const problem& q, double& t, double& sigma) {
    double mu = t * sigma;
    auto residual = [&](double m, double s, double& f1, double& f2) {
        const auto c = K::glint_capped_offset_moments(m / s, s, q.span);
        f1 = c.mean - q.mean, f2 = c.square_mean - q.second;
        return c;
    };
    for (int i = 0; i < 200; ++i) {
        double f1, f2;
        const auto c = residual(mu, sigma, f1, f2);
        if (std::fabs(f1) <= 1e-11 * q.mean && std::fabs(f2) <= 1e-11 * q.second) {
            t = mu / sigma;
            return true;
        }
        const double det = c.dmean_dmu * c.dsquare_dsigma - c.dmean_dsigma * c.dsquare_dmu;
        if (!(std::fabs(det) > 0)) break;
        const double dmu = (-f1 * c.dsquare_dsigma + f2 * c.dmean_dsigma) / det;
        const double dsigma = (-f2 * c.dmean_dmu + f1 * c.dsquare_dmu) / det;
        // Halve the step until the residual shrinks and sigma stays positive.
        const double before = std::hypot(f1 / q.mean, f2 / q.second);
        for (double step = 1; step > 1e-6; step /= 2) {
            const double m2 = mu + step * dmu, s2 = sigma + step * dsigma;
            if (!(s2 > 0)) continue;
            double g1, g2;
            residual(m2, s2, g1, g2);
            if (std::hypot(g1 / q.mean, g2 / q.second) < before || step < 1e-5) {
                mu = m2, sigma = s2;
                break;
            }
        }
    }
    // Near N = 3 sigma' grows past 100 and the capped moments cancel (t - t_far = span / sigma'):
    // the residual stops near 1e-3 there, where the Gaussian's weight in the middle, N - 3, is
    // below 0.01. Counted apart.
    t = mu / sigma;
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    const bool errors_only = argc > 1 && std::strcmp(argv[1], "--errors") == 0;
    const int floats = (2 * rows * columns + 3) / 4 * 4;  // padded to whole vec4s
    std::vector<double> table(static_cast<std::size_t>(floats), 0.0), start(2 * rows * columns);  // faded, and Newton's own
    int failures = 0, near_three = 0;  // nodes without convergence, at N >= 3.01 and below
    for (int i = rows - 1; i >= 0; --i)
        for (int j = 0; j < columns; ++j) {
            const double N = i == 0 ? n_min + 1e-5 : n_of_row(i), p = p_of_x(x_min + x_step * j);
            const problem q = problem_at(N, p);
            const std::size_t at = static_cast<std::size_t>(2 * (i * columns + j)), above = at + 2 * columns;
            double t = q.fit.x + (i + 1 < rows ? start[above] : 0.0), sigma = q.fit.y * std::exp(i + 1 < rows ? start[above + 1] : 0.0);
            if (!solve(q, t, sigma)) {
                if (N < 3.01) ++near_three;
                else ++failures, std::fprintf(stderr, "no convergence at N = %g, p = %g\n", N, p);
            }
            start[at] = t - q.fit.x;
            start[at + 1] = std::log(sigma / q.fit.y);
            // From N = 26 to 32 the node blends into the one-sided fit, which the sampler uses from
            // N = 32 on (there the far bound removes less than 1e-8 of the mean): the law is
            // continuous where the table ends.
            const double u = std::fmin(std::fmax((N - 26) / 6, 0.0), 1.0), fit_share = u * u * (3 - 2 * u);
            const double root = std::sqrt(N * p);
            table[at] = (1 - fit_share) * t + fit_share * q.fit.x;
            table[at + 1] = (1 - fit_share) * std::log(sigma / root) + fit_share * std::log(q.fit.y / root);
        }
    if (!errors_only) glint_bench::print_table("GLINT_BINOMIAL_FAR_TABLE", table);
    // The kernel's lookup (glint_binomial_two_sided_fit), in double on the float table.
    auto lookup = [&](double N, double p) { return glint_bench::table_lookup(table, rows, columns, row_of_n(N), (x_of_p(p) - x_min) / x_step); };
    double worst_mean = 0, worst_var = 0, worst_total = 0;
    glm::dvec2 at_mean(0), at_var(0), at_total(0);
    for (double row = 0.01; row < rows - 1; row += 1 / 7.3)
        for (double x = -30 + 20 * std::exp2(-30.0); x <= x_max; x += x_step / 7.3) {
            const double N = n_of_row(row), p = p_of_x(x);
            if (!(N > n_min)) continue;
            const problem q = problem_at(N, p);
            const glm::dvec2 c = lookup(N, p);
            const double t = c.x, sigma = std::sqrt(N * p) * std::exp(c.y);
            const auto m = K::glint_capped_offset_moments(t, sigma, q.span);
            const double w = std::fmin(N - 3, 1.0), var_target = q.second - q.mean * q.mean;
            const double e_mean = w * std::fabs(m.mean / q.mean - 1);
            const double e_var = w * std::fabs((m.square_mean - m.mean * m.mean) / var_target - 1);
            const auto e = K::glint_binomial_unbiased_ends(N, p, K::GLINT_POW_LOG1P);
            const double e_total = (e.any_near - e.all_positive) * w * std::fabs(m.mean - q.mean) / (N * p);
            if (x >= x_min && e_mean > worst_mean) worst_mean = e_mean, at_mean = glm::dvec2(N, p);
            if (x >= x_min && e_var > worst_var) worst_var = e_var, at_var = glm::dvec2(N, p);
            if (e_total > worst_total) worst_total = e_total, at_total = glm::dvec2(N, p);
        }
    std::fprintf(errors_only ? stdout : stderr,
                 "nodes %d x %d, %d without convergence at N >= 3.01 and %d below (residual up to 1e-3). Interpolated, p in the table: "
                 "worst relative error of the offset's mean %.3g at (N, p) = (%.4g, %.3g), of its variance %.3g at (%.4g, %.3g); "
                 "p from 2^-30: worst |E[n] / (N p) - 1| %.3g at (%.4g, %.3g)\n",
                 rows, columns, failures, near_three, worst_mean, at_mean.x, at_mean.y, worst_var, at_var.x, at_var.y, worst_total, at_total.x,
                 at_total.y);
    return failures == 0 ? 0 : 1;
}
