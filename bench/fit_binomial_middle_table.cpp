// Reproduces GLINT_BINOMIAL_MIDDLE_TABLE (kernels/binomial.glsl): the mean-preserving sampler's
// middle part for N >= 32 and lambda = N p_near from 2^-7 to 17, where its parameters used to
// cost a log1p, two exps and a log per draw. At every node (lambda, r) of a 128 x 13 grid,
//   rows:    log2(lambda) uniform from -7 to log2(17),
//   columns: r = p_near / p_max(lambda) uniform from 0 to 1, with p_max(lambda) =
//            (1 - (1 - min(lambda / 16, 1))^3) / 2: at least min(lambda / 32, 1/2), so that the
//            columns cover every p_near with N >= 32, and twice differentiable in lambda (a kink
//            there, as min(lambda / 32, 1/2) has, costs the cubic interpolation 10x in accuracy),
// it solves the one-sided fit exactly (bisection in double, bench/binomial_fit.hpp) for the
// middle's target moments m, v (glint_binomial_middle_targets, from the exact ends), and stores
// (t, sigma / sqrt(lambda)) (linear: no exp per draw; log(sigma / sqrt(lambda)) was 1.6x as
// accurate). Column 0 (p_near -> 0, the Poisson limit) is evaluated at
// r = 1e-9.
//
// It then measures what the kernel's interpolation (cubic Lagrange in both axes on a 4 x 4
// stencil, the table rounded to float) leaves, on a sweep 7.3 times finer than the nodes, in
// double: the largest relative errors of the middle's mean and variance, and of E[n] against N p.
//   glint_fit_binomial_middle_table            prints the table (stdout) and the errors (stderr)
//   glint_fit_binomial_middle_table --errors   the errors only, on stdout
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <glint/binomial.hpp>

#include "binomial_fit.hpp"

namespace {

using K = glint::detail::glsl::kernels<double>;

constexpr int rows = 128, columns = 13;
constexpr double x_min = -7;
const double x_max = std::log2(17.0);
const double x_step = (x_max - x_min) / (rows - 1);

double p_max(double lambda) {
    const double a = 1 - std::fmin(lambda / 16, 1.0);
    return 0.5 * (1 - a * a * a);
}

struct targets {
    double m, v;  // the middle offset's mean and variance
    double any_near, all_near;
};

targets targets_at(double lambda, double p) {
    const double N = lambda / p;
    const auto e = K::glint_binomial_unbiased_ends(N, p, K::GLINT_POW_LOG1P);
    const auto g = K::glint_binomial_middle_targets(N, p, e);
    return {g.mean, g.variance, e.any_near, e.all_positive};
}

}  // namespace

int main(int argc, char** argv) {
    const bool errors_only = argc > 1 && std::strcmp(argv[1], "--errors") == 0;
    const int floats = (2 * rows * columns + 3) / 4 * 4;  // padded to whole vec4s
    std::vector<double> table(static_cast<std::size_t>(floats), 0.0);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            const double lambda = std::exp2(x_min + x_step * i), r = std::fmax(static_cast<double>(j) / (columns - 1), 1e-9);
            const targets g = targets_at(lambda, r * p_max(lambda));
            const glm::dvec2 f = glint_bench::one_sided_exact(g.m, g.v);
            table[static_cast<std::size_t>(2 * (i * columns + j))] = f.x;
            table[static_cast<std::size_t>(2 * (i * columns + j) + 1)] = f.y / std::sqrt(lambda);
        }
    if (!errors_only) glint_bench::print_table("GLINT_BINOMIAL_MIDDLE_TABLE", table);
    // The kernel's lookup (glint_binomial_middle_table), in double on the float table.
    auto lookup = [&](double lambda, double p) {
        return glint_bench::table_lookup(table, rows, columns, (std::log2(lambda) - x_min) / x_step, p / p_max(lambda) * (columns - 1));
    };
    double worst_mean = 0, worst_var = 0, worst_total = 0;
    glm::dvec2 at_mean(0), at_var(0), at_total(0);
    for (double x = x_min; x <= x_max; x += x_step / 7.3)
        for (double r = 1e-6; r <= 1; r += 1 / (7.3 * (columns - 1))) {
            const double lambda = std::exp2(x), p = r * p_max(lambda), N = lambda / p;
            if (N < 32) continue;
            const targets g = targets_at(lambda, p);
            const glm::dvec2 c = lookup(lambda, p);
            const auto m = K::glint_capped_offset_moments(c.x, std::sqrt(lambda) * c.y, 1e300);
            const double e_mean = std::fabs(m.mean / g.m - 1), e_var = std::fabs((m.square_mean - m.mean * m.mean) / g.v - 1);
            // E[n] = N p^N + P(middle) (1 + offset mean): its error is P(middle) times the offset's.
            const double e_total = (g.any_near - g.all_near) * std::fabs(m.mean - g.m) / lambda;
            if (e_mean > worst_mean) worst_mean = e_mean, at_mean = glm::dvec2(N, p);
            if (e_var > worst_var) worst_var = e_var, at_var = glm::dvec2(N, p);
            if (e_total > worst_total) worst_total = e_total, at_total = glm::dvec2(N, p);
        }
    std::fprintf(errors_only ? stdout : stderr,
                 "nodes %d x %d. Interpolated, N >= 32: worst relative error of the middle's mean %.3g at (N, p) = (%.4g, %.3g), of its "
                 "variance %.3g at (%.4g, %.3g); worst |E[n] / (N p) - 1| %.3g at (%.4g, %.3g)\n",
                 rows, columns, worst_mean, at_mean.x, at_mean.y, worst_var, at_var.x, at_var.y, worst_total, at_total.x, at_total.y);
    return 0;
}
