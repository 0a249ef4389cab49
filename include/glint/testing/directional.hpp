// Chi-square tests of direction samplers against their densities (as Mitsuba 3's and pbrt-v4's
// sampling tests do): the domain is cut into cells of exactly equal measure, the density is
// integrated over each cell by adaptive quadrature, and the sampled counts are compared with
// glint::testing::chi_square (pooling, then the caller's Sidak-corrected level).
//
//   auto t = glint::testing::directional_chi_square(glint::testing::domain::disk, 32, 32,
//                 [&](glm::dvec2 s) { return pdf(s); },            // density per unit area
//                 samples, rejected);                               // points drawn, failed draws
//   CHECK_FALSE(t.rejects(alpha));
//
// Domains and their equal-measure cells (t, phi in [0, 1) x [0, 2 pi), cells uniform in both):
// - disk: the unit disk, points (x, y), area element r dr dphi; t = r^2 (so dA = dt dphi / 2);
// - hemisphere: unit directions with z >= 0, solid angle; t = z (Archimedes: d omega = dt dphi).
// A density that integrates to less than 1 over the domain (a sampler that may fail, or mass
// outside the domain) gets one more cell for the failures; the integrated densities must sum to
// 1 within 1e-3 with it (else std::invalid_argument: the density or the sampler is not normalised).
// Cells are ordered in rings of t, phi fastest, so pooling merges neighbours.
#pragma once

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "glint/testing/stats.hpp"

namespace glint {
namespace testing {

enum class domain { disk, hemisphere };

struct directional_result {
    chi_square_result chi2;
    std::vector<double> observed, expected_probability;  // per cell, the failure cell last
    double integral = 0;  // the density's integral over the domain
    bool rejects(double alpha) const { return chi2.rejects(alpha); }
};

namespace detail {

inline double two_pi() { return 6.283185307179586477; }

// The point of the domain at cell coordinates (t, phi).
inline glm::dvec3 domain_point(domain d, double t, double phi) {
    if (d == domain::disk) {
        const double r = std::sqrt(t);
        return {r * std::cos(phi), r * std::sin(phi), 0.0};
    }
    const double z = t, r = std::sqrt(std::max(0.0, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// The measure of the domain per unit dt dphi.
inline double domain_jacobian(domain d) { return d == domain::disk ? 0.5 : 1.0; }

// 4 x 4 Gauss-Legendre over [t0, t1] x [p0, p1] of f (in cell coordinates).
template <class F>
double gauss_4x4(const F& f, double t0, double t1, double p0, double p1) {
    static const double x[4] = {-0.86113631159405257522, -0.33998104358485626480, 0.33998104358485626480, 0.86113631159405257522};
    static const double w[4] = {0.34785484513745385737, 0.65214515486254614263, 0.65214515486254614263, 0.34785484513745385737};
    double sum = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            sum += w[i] * w[j] * f(0.5 * (t0 + t1) + 0.5 * (t1 - t0) * x[i], 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * x[j]);
    return sum * 0.25 * (t1 - t0) * (p1 - p0);
}

// Adaptive: split in 4 until the children's sum agrees with the parent to rel * |parent| + abs,
// always at least `forced` times (so that a lobe narrower than the cell is not missed).
template <class F>
double adaptive(const F& f, double t0, double t1, double p0, double p1, double whole, double rel, double abs, int depth, int forced) {
    const double tm = 0.5 * (t0 + t1), pm = 0.5 * (p0 + p1);
    const double a = gauss_4x4(f, t0, tm, p0, pm), b = gauss_4x4(f, tm, t1, p0, pm), c = gauss_4x4(f, t0, tm, pm, p1),
                 e = gauss_4x4(f, tm, t1, pm, p1);
    const double children = a + b + c + e;
    if (forced <= 0 && (depth <= 0 || std::fabs(children - whole) <= rel * std::fabs(children) + abs)) return children;
    return adaptive(f, t0, tm, p0, pm, a, rel, abs / 4, depth - 1, forced - 1) + adaptive(f, tm, t1, p0, pm, b, rel, abs / 4, depth - 1, forced - 1) +
           adaptive(f, t0, tm, pm, p1, c, rel, abs / 4, depth - 1, forced - 1) + adaptive(f, tm, t1, pm, p1, e, rel, abs / 4, depth - 1, forced - 1);
}

}  // namespace detail

// The probability of each of the t_cells x phi_cells cells under `density` (a density per unit
// measure of the domain, evaluated at domain points (x, y) for the disk, (x, y, z) for the
// hemisphere), integrated adaptively to 1e-4 relative or 1e-8 absolute (below what 1e6
// samples resolve): each cell split at least once (8 x 8 Gauss-Legendre points), at most `depth`
// times (4; a density with kinks, such as a bilinear table, converges only as the square of the
// split and would reach the depth in every cell: a caller may pass less, stating the error).
inline std::vector<double> cell_probabilities(domain d, int t_cells, int phi_cells, const std::function<double(const glm::dvec3&)>& density, int depth = 4) {
    if (t_cells < 1 || phi_cells < 1) throw std::invalid_argument("glint::testing::cell_probabilities: no cells");
    std::vector<double> p;
    p.reserve(static_cast<std::size_t>(t_cells) * static_cast<std::size_t>(phi_cells));
    const double jac = detail::domain_jacobian(d);
    const auto f = [&](double t, double phi) { return jac * density(detail::domain_point(d, t, phi)); };
    for (int i = 0; i < t_cells; ++i)
        for (int j = 0; j < phi_cells; ++j) {
            const double t0 = static_cast<double>(i) / t_cells, t1 = static_cast<double>(i + 1) / t_cells;
            const double p0 = detail::two_pi() * j / phi_cells, p1 = detail::two_pi() * (j + 1) / phi_cells;
            const double whole = detail::gauss_4x4(f, t0, t1, p0, p1);
            p.push_back(detail::adaptive(f, t0, t1, p0, p1, whole, 1e-4, 1e-8, depth, 1));
        }
    return p;
}

// The cell of a domain point (the disk's (x, y) or the hemisphere's (x, y, z)); -1 outside.
inline int cell_of(domain d, int t_cells, int phi_cells, const glm::dvec3& v) {
    const double t = d == domain::disk ? v.x * v.x + v.y * v.y : v.z;
    if (!(t >= 0 && t < 1)) return t == 1 && d == domain::hemisphere ? (t_cells - 1) * phi_cells : -1;
    double phi = std::atan2(v.y, v.x);
    if (phi < 0) phi += detail::two_pi();
    const int i = std::min(t_cells - 1, static_cast<int>(t * t_cells)), j = std::min(phi_cells - 1, static_cast<int>(phi / detail::two_pi() * phi_cells));
    return i * phi_cells + j;
}

// The test of `samples` (domain points; failed draws counted in `failures`) against the cells'
// probabilities from cell_probabilities (so that several samplers judged against one density pay
// for its quadrature once).
inline directional_result directional_chi_square(domain d, int t_cells, int phi_cells, const std::vector<double>& cell_probability,
                                                 const std::vector<glm::dvec3>& samples, std::size_t failures, double min_expected = 5.0) {
    if (cell_probability.size() != static_cast<std::size_t>(t_cells) * static_cast<std::size_t>(phi_cells))
        throw std::invalid_argument("glint::testing::directional_chi_square: " + std::to_string(cell_probability.size()) + " cell probabilities for " +
                                    std::to_string(t_cells) + " x " + std::to_string(phi_cells) + " cells");
    directional_result r;
    r.expected_probability = cell_probability;
    for (const double p : r.expected_probability) r.integral += p;
    if (!(r.integral <= 1 + 1e-3)) {
        std::ostringstream m;
        m << "glint::testing::directional_chi_square: the density integrates to " << r.integral << " over the domain (above 1)";
        throw std::invalid_argument(m.str());
    }
    r.expected_probability.push_back(std::max(0.0, 1 - r.integral));
    // Renormalise the rounding (at most 1e-3) so that the kit's 1e-9 check holds.
    double total = 0;
    for (const double p : r.expected_probability) total += p;
    for (double& p : r.expected_probability) p /= total;
    r.observed.assign(r.expected_probability.size(), 0.0);
    for (const auto& v : samples) {
        const int c = cell_of(d, t_cells, phi_cells, v);
        r.observed[c < 0 ? r.observed.size() - 1 : static_cast<std::size_t>(c)] += 1;
    }
    r.observed.back() += static_cast<double>(failures);
    r.chi2 = chi_square(r.observed, r.expected_probability, min_expected);
    return r;
}

// The test of `samples` against `density`, integrated over the cells with at most `depth` splits.
inline directional_result directional_chi_square(domain d, int t_cells, int phi_cells, const std::function<double(const glm::dvec3&)>& density,
                                                 const std::vector<glm::dvec3>& samples, std::size_t failures, double min_expected = 5.0,
                                                 int depth = 4) {
    return directional_chi_square(d, t_cells, phi_cells, cell_probabilities(d, t_cells, phi_cells, density, depth), samples, failures, min_expected);
}

}  // namespace testing
}  // namespace glint
