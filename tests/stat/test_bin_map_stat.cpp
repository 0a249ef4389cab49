// The bin-map sampler (glint/bin_map.hpp) against its own evaluation: for each kernel and rule,
// samples binned in cells whose probabilities come from eval alone, and a chi-square test; and
// the test's power against an off-by-one bin and against the wrong coverage rule.
//
// Significance: family-wise 0.01 over the 4 acceptance tests of this file (Sidak). Box and tent:
// 1e5 samples in the square's 2n x 2n half-cells (n = 8: 256 cells, pooled to >= 5 expected;
// the footprint's texels fill about 40 bins, so about 600 samples per occupied half-cell, a
// relative sd of 4%). The cells' probabilities are exact: a box cell holds c_j / 4 of its bin,
// and the tent density is bilinear on each half-cell, so its midpoint value times the area is
// its integral. Beckmann: 1e5 samples on the hemisphere in 16 x 16 equal-solid-angle cells with
// the density integrated adaptively (the kit's quadrature with 2 splits: the lobes are smooth
// but for their 1.1% step at the cap, and 3 splits moved the integral by 1e-5, far below what
// 1e5 samples resolve), plus a cell for the draws that fall below the horizon.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glint/bin_map.hpp>
#include <glint/core.hpp>
#include <glint/testing/directional.hpp>
#include <glint/testing/stats.hpp>

namespace gt = glint::testing;

namespace {

using bmap = glint::bin_map<double>;
const double alpha = gt::sidak_alpha(0.01, 4);
const int samples = 100000;

// Normals spread over the hemisphere down to z = 0.3.
glint::normal_map spread_normals(int w, int h, std::uint32_t seed) {
    std::vector<glm::vec3> n(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::size_t k = 0; k < n.size(); ++k) {
        const glm::uvec3 r = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(k), seed, 0x5a1u));
        const double t = 0.95 * std::sqrt(glint::unit_from_bits<double>(r.x)), p = 6.283185307179586 * glint::unit_from_bits<double>(r.y);
        n[k] = glm::vec3(static_cast<float>(t * std::cos(p)), static_cast<float>(t * std::sin(p)), static_cast<float>(std::sqrt(1 - t * t)));
    }
    return glint::normal_map(w, h, std::move(n));
}

glm::dvec2 u2(std::uint32_t i, std::uint32_t k) {
    const glm::uvec3 r = glint::pcg3d(glm::uvec3(i, k, 0x3c7u));
    return {glint::unit_from_bits<double>(r.x), glint::unit_from_bits<double>(r.y)};
}

// A footprint of about 7 x 5 texels, rotated and sheared, across the map's corner seam.
const glint::uv_parallelogram<double> footprint{{0.93, 0.95}, {0.17, 0.06}, {-0.05, 0.14}};

// The square's half-cell of a direction (2n per side).
int half_cell(const glm::dvec3& h, int n) {
    const glm::dvec2 q = bmap::hemisphere_to_square(h);
    const int x = std::min(2 * n - 1, static_cast<int>(q.x * 2 * n)), y = std::min(2 * n - 1, static_cast<int>(q.y * 2 * n));
    return x + 2 * n * y;
}

// The half-cells' probabilities from eval alone: the density at each half-cell's midpoint
// times its solid angle (exact for box and tent).
std::vector<double> half_cell_probabilities(const bmap& m, const glint::uv_parallelogram<double>& A) {
    const int n = m.bins_per_side(), g = 2 * n;
    std::vector<double> p(static_cast<std::size_t>(g * g));
    for (int y = 0; y < g; ++y)
        for (int x = 0; x < g; ++x)
            p[static_cast<std::size_t>(x + g * y)] = m.eval(A, bmap::square_to_hemisphere({(x + 0.5) / g, (y + 0.5) / g})).pdf * 2 * 3.141592653589793 / (g * g);
    return p;
}

// Samples binned in half-cells; `shift` moves each sample by that many bins along x (wrapping),
// a deliberately wrong sampler.
std::vector<double> binned_samples(const bmap& m, const glint::uv_parallelogram<double>& A, int shift = 0) {
    const int n = m.bins_per_side();
    std::vector<double> counts(static_cast<std::size_t>(4 * n * n), 0.0);
    for (int i = 0; i < samples; ++i) {
        const auto s = m.sample(A, u2(static_cast<std::uint32_t>(i), 1u), u2(static_cast<std::uint32_t>(i), 2u));
        REQUIRE(s.valid);
        int c = half_cell(s.h, n);
        if (shift) c = (c % (2 * n) + 2 * shift) % (2 * n) + (c / (2 * n)) * 2 * n;
        counts[static_cast<std::size_t>(c)] += 1;
    }
    return counts;
}

bmap make(glint::bin_kernel k, glint::coverage_rule r, int n = 8, double a = 0.01) {
    glint::bin_map_options o;
    o.bins_per_side = n, o.kernel = k, o.rule = r, o.alpha = a, o.leaf_size = 4;
    return bmap::build(spread_normals(40, 40, 3u), o);
}

}  // namespace

TEST_CASE("bin_map sampler: box and tent against eval, both coverage rules") {
    struct setup {
        const char* what;
        glint::bin_kernel kernel;
        glint::coverage_rule rule;
    };
    for (const setup st : {setup{"box, exact area", glint::bin_kernel::box, glint::coverage_rule::exact_area},
                           setup{"box, texel centre", glint::bin_kernel::box, glint::coverage_rule::texel_center},
                           setup{"tent, exact area", glint::bin_kernel::tent, glint::coverage_rule::exact_area}}) {
        const auto m = make(st.kernel, st.rule);
        const auto p = half_cell_probabilities(m, footprint);
        double total = 0;
        for (const double v : p) total += v;
        CHECK(total == doctest::Approx(1).epsilon(1e-12));
        const auto r = gt::chi_square(binned_samples(m, footprint), p);
        MESSAGE(std::string(st.what) << ": p = " << r.p_value << " (" << r.cells << " cells)");
        CHECK_FALSE(r.rejects(alpha));
    }
}

TEST_CASE("bin_map sampler: Beckmann lobes against eval on the hemisphere, mass below the horizon as failures") {
    // alpha 0.3 at n = 12: lobes 33 degrees wide around normals down to 72 degrees from the
    // pole, so some of the mass crosses the horizon.
    const auto m = make(glint::bin_kernel::beckmann, glint::coverage_rule::exact_area, 12, 0.3);
    std::vector<glm::dvec3> points;
    std::size_t failures = 0;
    for (int i = 0; i < samples; ++i) {
        const auto s = m.sample(footprint, u2(static_cast<std::uint32_t>(i), 1u), u2(static_cast<std::uint32_t>(i), 2u));
        if (s.valid) {
            points.push_back(glm::dvec3(s.h));
            if (i % 100 == 0) CHECK(s.pdf == doctest::Approx(m.eval(footprint, s.h).pdf).epsilon(1e-12));
        } else ++failures;
    }
    const auto r = gt::directional_chi_square(gt::domain::hemisphere, 16, 16, [&](const glm::dvec3& h) { return static_cast<double>(m.eval(footprint, h).pdf); },
                                              points, failures, 5.0, 2);
    MESSAGE("beckmann: p = " << r.chi2.p_value << " (" << r.chi2.cells << " cells), " << failures << " draws below the horizon, density integral " << r.integral);
    // The failure cell is exercised: at least 20 draws expected below the horizon.
    CHECK((1 - r.integral) * samples >= 20);
    CHECK_FALSE(r.rejects(alpha));
}

TEST_CASE("bin_map sampler: the chi-square rejects an off-by-one bin and the wrong coverage rule") {
    const auto m = make(glint::bin_kernel::box, glint::coverage_rule::exact_area);
    const auto p = half_cell_probabilities(m, footprint);
    const auto shifted = gt::chi_square(binned_samples(m, footprint, 1), p);
    MESSAGE("off by one bin: p = " << shifted.p_value);
    CHECK(shifted.rejects(alpha));
    // Texels drawn by area (exact_area's sampler) tested against texel_center's coverages.
    const auto centre = make(glint::bin_kernel::box, glint::coverage_rule::texel_center);
    const auto wrong_rule = gt::chi_square(binned_samples(m, footprint), half_cell_probabilities(centre, footprint));
    MESSAGE("area sampler against centre coverages: p = " << wrong_rule.p_value);
    CHECK(wrong_rule.rejects(alpha));
}
