// Inverse bin maps (glint/bin_map.hpp, AKKW): the bins, the tree's counts and areas against brute
// force over every texel, normalisation of every kernel, the global histogram, periodicity, hard
// footprints, bad input, and no allocation per query.
// This file's binary counts allocations (tests/support/count_allocations.hpp).

#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include <glint/bin_map.hpp>
#include <glint/patterns.hpp>

#include "../support/bin_map_support.hpp"
#include "../support/count_allocations.hpp"
#include "../support/errors.hpp"

using glint_test::allocations;
using glint_test::counting;

namespace {

using glint_test::texel_parallelogram;
using bmap = glint::bin_map<double>;

glint::normal_map random_normals(int w, int h, std::uint32_t seed, double spread = 0.8) {
    std::vector<glm::vec3> n(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::size_t k = 0; k < n.size(); ++k) {
        const glm::uvec3 r = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(k), seed, 0x1b3u));
        const double a = spread * (2 * glint::unit_from_bits<double>(r.x) - 1), b = spread * (2 * glint::unit_from_bits<double>(r.y) - 1);
        const double s = std::min(1.0, 0.95 / std::max(1e-9, std::sqrt(a * a + b * b)));
        const glm::dvec2 xy = glm::dvec2(a, b) * std::min(1.0, s);
        n[k] = glm::vec3(static_cast<float>(xy.x), static_cast<float>(xy.y), static_cast<float>(std::sqrt(1 - glm::dot(xy, xy))));
    }
    return glint::normal_map(w, h, std::move(n));
}

glint::bin_map_options opts(int n, int leaf, glint::coverage_rule rule = glint::coverage_rule::exact_area) {
    glint::bin_map_options o;
    o.bins_per_side = n, o.leaf_size = leaf, o.rule = rule;
    return o;
}

}  // namespace

TEST_CASE("bin_map: the bins are the equal-area concentric cells of the hemisphere") {
    // Round trip square -> hemisphere -> square, and a constant Jacobian of 2 pi (so every bin has
    // solid angle 2 pi / n^2), by central differences at random points.
    double worst_trip = 0, worst_jac = 0;
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const glm::uvec3 r = glint::pcg3d(glm::uvec3(i, 5u, 0u));
        const glm::dvec2 q(0.001 + 0.998 * glint::unit_from_bits<double>(r.x), 0.001 + 0.998 * glint::unit_from_bits<double>(r.y));
        const glm::dvec3 h = bmap::square_to_hemisphere(q);
        CHECK(std::fabs(glm::length(h) - 1) < 1e-12);
        CHECK(h.z >= 0);
        worst_trip = std::max(worst_trip, glm::length(bmap::hemisphere_to_square(h) - q));
        const double e = 1e-6;
        const glm::dvec3 dx = (bmap::square_to_hemisphere(q + glm::dvec2(e, 0)) - bmap::square_to_hemisphere(q - glm::dvec2(e, 0))) / (2 * e);
        const glm::dvec3 dy = (bmap::square_to_hemisphere(q + glm::dvec2(0, e)) - bmap::square_to_hemisphere(q - glm::dvec2(0, e))) / (2 * e);
        // Points on the concentric map's diagonals have one-sided derivatives: skip them.
        const double a = std::fabs(2 * q.x - 1), b = std::fabs(2 * q.y - 1);
        if (std::fabs(a - b) > 1e-4) worst_jac = std::max(worst_jac, std::fabs(glm::length(glm::cross(dx, dy)) / (2 * 3.141592653589793) - 1));
    }
    CHECK(worst_trip < 1e-12);
    CHECK(worst_jac < 1e-6);
    // The square's edge is the horizon, its centre the pole.
    CHECK(bmap::square_to_hemisphere({0.5, 0.5}).z == doctest::Approx(1));
    CHECK(std::fabs(bmap::square_to_hemisphere({1.0, 0.3}).z) < 1e-15);
    // bin_of and bin_center agree; every bin has the same solid angle.
    const auto m = bmap::build(random_normals(8, 8, 1), opts(16, 16));
    for (std::uint32_t j = 0; j < m.bin_count(); ++j) CHECK(m.bin_of(m.bin_center(j)) == j);
    CHECK(m.bin_solid_angle() == doctest::Approx(2 * 3.141592653589793 / 256).epsilon(1e-14));
}

TEST_CASE("bin_map: no point of a cell is farther than 2.7 / n from its centre (the lobe search's margin)") {
    // The cell boundary sampled at 64 points per edge; the largest angle over all cells.
    for (const int n : {1, 2, 3, 8, 33, 128}) {
        double worst = 0;
        for (int iy = 0; iy < n; ++iy)
            for (int ix = 0; ix < n; ++ix) {
                const glm::dvec3 c = bmap::square_to_hemisphere(glm::dvec2(ix + 0.5, iy + 0.5) / double(n));
                for (int k = 0; k <= 64; ++k) {
                    const double t = k / 64.0;
                    const glm::dvec2 pts[4] = {{ix + t, iy}, {ix + t, iy + 1}, {ix, iy + t}, {ix + 1, iy + t}};
                    for (const auto& p : pts) worst = std::max(worst, std::acos(std::clamp(glm::dot(c, bmap::square_to_hemisphere(p / double(n))), -1.0, 1.0)));
                }
            }
        INFO("n = " << n << ", largest angle x n = " << worst * n);
        CHECK(worst * n < 2.7);
    }
}

TEST_CASE("bin_map: tree counts equal brute-force counts exactly, for every bin, over random footprints") {
    // texel_center: integers. Maps from 1 x 1 to 257^2, leaf sizes 1 to 64, n = 1, 8, 64, and
    // the "all in one bin" (n = 1) and "about one bin per texel" (7 x 13 at n = 64) extremes.
    struct config {
        int w, h, n, leaf, footprints;
    };
    const config configs[] = {{1, 1, 8, 1, 500}, {1, 37, 8, 2, 1000}, {7, 13, 64, 1, 1500}, {64, 64, 1, 16, 500},
                              {64, 64, 8, 1, 2000}, {64, 64, 8, 16, 1500}, {64, 64, 64, 2, 1000}, {257, 257, 8, 64, 1000}, {257, 257, 8, 16, 1000}};
    long footprints = 0, mismatches = 0, nonzero = 0;
    for (const auto& c : configs) {
        const auto map = random_normals(c.w, c.h, static_cast<std::uint32_t>(c.w * 131 + c.h));
        const auto m = bmap::build(map, opts(c.n, c.leaf, glint::coverage_rule::texel_center));
        const double big = std::max(c.w, c.h);
        for (int i = 0; i < c.footprints; ++i) {
            const auto A = glint_test::random_parallelogram<double>(static_cast<std::uint32_t>(i), 77u, c.w, c.h, 0.3, 2.5 * big + 3, 30);
            const auto P = glint_test::in_texels(A, c.w, c.h);
            const auto ref = glint_test::brute_counts(m, P);
            for (std::uint32_t j = 0; j < m.bin_count(); ++j) {
                const std::uint64_t got = m.count(A, j);
                if (got != ref[j]) ++mismatches;
                if (ref[j] > 0) ++nonzero;
            }
            ++footprints;
        }
    }
    INFO(footprints << " footprints, " << nonzero << " nonzero counts");
    CHECK(footprints == 10000);
    CHECK(nonzero > 100000);
    CHECK(mismatches == 0);
}

TEST_CASE("bin_map: exact-area coverages against a double clip of every texel, they sum to 1") {
    for (const auto& [w, h, n, leaf] : std::vector<std::tuple<int, int, int, int>>{{7, 13, 8, 1}, {64, 64, 8, 16}, {100, 37, 16, 4}}) {
        const auto map = random_normals(w, h, 9u);
        const auto m = bmap::build(map, opts(n, leaf));
        const auto mf = glint::bin_map<float>::build(map, opts(n, leaf));
        double worst = 0, worst_float = 0, worst_sum = 0;
        for (std::uint32_t i = 0; i < 300; ++i) {
            const auto A = glint_test::random_parallelogram<double>(i, 31u, w, h, 0.2, 3.0 * std::max(w, h), 50);
            const auto ref = glint_test::brute_coverages(m, glint_test::in_texels(A, w, h));
            glint::uv_parallelogram<float> Af{glm::vec2(A.origin), glm::vec2(A.e0), glm::vec2(A.e1)};
            const auto ref_f = glint_test::brute_coverages(mf, glint_test::in_texels(Af, w, h));
            double sum = 0;
            for (std::uint32_t j = 0; j < m.bin_count(); ++j) {
                const double c = m.coverage(A, j);
                sum += c;
                worst = std::max(worst, std::fabs(c - ref[j]));
                worst_float = std::max(worst_float, std::fabs(static_cast<double>(mf.coverage(Af, j)) - ref_f[j]));
            }
            worst_sum = std::max(worst_sum, std::fabs(sum - 1));
        }
        INFO(w << " x " << h << ": largest |c - clip| " << worst << " (float " << worst_float << "), |sum - 1| " << worst_sum);
        CHECK(worst < 1e-12);
        CHECK(worst_float < 1e-5);
        CHECK(worst_sum < 1e-12);
    }
}

TEST_CASE("bin_map: texel_center coverages sum to 1 exactly, and sample the same rule") {
    const auto m = bmap::build(random_normals(50, 40, 4u), opts(8, 4, glint::coverage_rule::texel_center));
    for (std::uint32_t i = 0; i < 300; ++i) {
        const auto A = glint_test::random_parallelogram<double>(i, 8u, 50, 40, 0.05, 200, 100);
        double sum = 0;
        for (std::uint32_t j = 0; j < m.bin_count(); ++j) sum += m.coverage(A, j);
        CHECK(sum == doctest::Approx(1).epsilon(1e-14));
    }
}

TEST_CASE("bin_map: whole tiles give the global histogram, partial tiles converge as 1/k") {
    const int w = 48, h = 32;
    const auto m = bmap::build(random_normals(w, h, 12u), opts(8, 16));
    std::vector<double> global(m.bin_count());
    for (std::uint32_t j = 0; j < m.bin_count(); ++j) global[j] = static_cast<double>(m.bin_texels(j)) / (w * h);
    for (const double k : {1.0, 3.0}) {
        const auto A = glint::uv_parallelogram<double>::rect({0.25, -0.5}, {0.25 + k, -0.5 + k});
        for (std::uint32_t j = 0; j < m.bin_count(); ++j) CHECK(m.coverage(A, j) == doctest::Approx(global[j]).epsilon(1e-13).scale(1e-13));
    }
    // (k + 0.37)^2 tiles: L1 against the global histogram falls at least as 1/k.
    std::vector<double> l1;
    for (const double k : {1.0, 2.0, 4.0, 8.0}) {
        const auto A = glint::uv_parallelogram<double>::rect({0.1, 0.2}, {0.1 + k + 0.37, 0.2 + k + 0.37});
        double e = 0;
        for (std::uint32_t j = 0; j < m.bin_count(); ++j) e += std::fabs(m.coverage(A, j) - global[j]);
        l1.push_back(e);
    }
    INFO("L1 at k = 1, 2, 4, 8: " << l1[0] << " " << l1[1] << " " << l1[2] << " " << l1[3]);
    for (std::size_t i = 1; i < l1.size(); ++i) CHECK(l1[i] < 0.75 * l1[i - 1]);
    CHECK(l1.back() * 8 < 2 * l1.front());
}

TEST_CASE("bin_map: more tile copies than max_tile_copies give the global histogram") {
    glint::bin_map_options o = opts(8, 16);
    o.max_tile_copies = 4;
    const auto m = bmap::build(random_normals(16, 16, 3u), o);
    const auto A = glint::uv_parallelogram<double>::rect({0.3, 0.3}, {2.9, 2.2});  // 3 x 3 copies
    for (std::uint32_t j = 0; j < m.bin_count(); ++j) CHECK(m.coverage(A, j) == static_cast<double>(m.bin_texels(j)) / 256.0);
    // and sampling draws from the same histogram: every sample's pdf is eval's.
    for (std::uint32_t i = 0; i < 200; ++i) {
        const auto s = m.sample(A, {glint::unit_from_bits<double>(i * 2654435761u), (i + 0.5) / 200}, {0.5, 0.5});
        REQUIRE(s.valid);
        CHECK(s.pdf == m.eval(A, s.h).pdf);
    }
}

TEST_CASE("bin_map: translation by whole periods changes nothing") {
    const auto m = bmap::build(random_normals(30, 20, 6u), opts(8, 2));
    for (std::uint32_t i = 0; i < 200; ++i) {
        const auto A = glint_test::random_parallelogram<double>(i, 3u, 30, 20, 0.5, 40);
        auto B = A;
        B.origin += glm::dvec2(1 + (i % 3), -2.0 * (i % 2));
        const glm::dvec3 hv = bmap::square_to_hemisphere({glint::unit_from_bits<double>(i * 747796405u), glint::unit_from_bits<double>(i * 2891336453u)});
        CHECK(m.eval(A, hv).pdf == doctest::Approx(m.eval(B, hv).pdf).epsilon(1e-12));
        // (uv + 3 rounds the origin by up to 4e-16 uv, 1e-14 texels: so 1e-12, not bit-equality)
        for (std::uint32_t j = 0; j < m.bin_count(); j += 5) CHECK(std::fabs(m.coverage(A, j) - m.coverage(B, j)) < 1e-12);
    }
}

TEST_CASE("bin_map: each kernel integrates to 1 over the hemisphere") {
    const auto map = random_normals(32, 32, 21u, 0.5);
    const auto A = glint::uv_parallelogram<double>::from_differentials({0.4, 0.7}, {0.21, 0.05}, {-0.04, 0.17});
    // box: sum_j pdf(centre_j) |H_j| = 1.
    {
        const auto m = bmap::build(map, opts(16, 16));
        double s = 0;
        for (std::uint32_t j = 0; j < m.bin_count(); ++j) s += m.eval(A, m.bin_center(j)).pdf * m.bin_solid_angle();
        CHECK(s == doctest::Approx(1).epsilon(1e-12));
    }
    // tent: bilinear between cell centres, so the midpoint rule on half-cells (whose edges hold
    // every kink) is exact: 2 pi times the mean over the square.
    {
        glint::bin_map_options o = opts(16, 16);
        o.kernel = glint::bin_kernel::tent;
        const auto m = bmap::build(map, o);
        const int g = 32;
        double s = 0;
        for (int y = 0; y < g; ++y)
            for (int x = 0; x < g; ++x) s += m.eval(A, bmap::square_to_hemisphere({(x + 0.5) / g, (y + 0.5) / g})).pdf;
        CHECK(s * 2 * 3.141592653589793 / (g * g) == doctest::Approx(1).epsilon(1e-12));
    }
    // beckmann: normals within 30 degrees of the pole, lobes 3.4 degrees wide: none reaches the
    // horizon, so the integral is 1; 512^2 stratified points over the square (error about 1e-4).
    {
        glint::bin_map_options o = opts(64, 16);
        o.kernel = glint::bin_kernel::beckmann, o.alpha = 0.05;
        const auto m = bmap::build(map, o);
        const int g = 512;
        double s = 0;
        for (int y = 0; y < g; ++y)
            for (int x = 0; x < g; ++x) s += m.eval(A, bmap::square_to_hemisphere({(x + 0.5) / g, (y + 0.5) / g})).pdf;
        CHECK(s * 2 * 3.141592653589793 / (g * g) == doctest::Approx(1).epsilon(1e-3));
        // the microfacet convention: the integral of ndf cos theta_h is the same.
        const glm::dvec3 h = glm::normalize(glm::dvec3(0.1, 0.05, 1));
        const auto e = m.eval(A, h);
        CHECK(e.ndf * h.z == doctest::Approx(e.pdf).epsilon(1e-14));
    }
}

TEST_CASE("bin_map: the lobe search finds every bin whose centre lies in the cap") {
    // Against the sum over all bins, for random h, n from 16 to 128 and alpha up to the reach
    // that check_options allows.
    const auto map = random_normals(16, 16, 2u, 1.2);
    for (const auto& [n, alpha] : std::vector<std::pair<int, double>>{{16, 0.01}, {16, 0.3}, {64, 0.05}, {128, 0.0025}, {128, 0.1}}) {
        glint::bin_map_options o = opts(n, 4);
        o.kernel = glint::bin_kernel::beckmann, o.alpha = alpha;
        const auto m = bmap::build(map, o);
        const auto A = glint::uv_parallelogram<double>::rect({0.1, 0.1}, {0.9, 0.8});
        std::vector<double> c(m.bin_count());
        for (std::uint32_t j = 0; j < m.bin_count(); ++j) c[j] = m.coverage(A, j);
        const double tan2c = alpha * alpha * std::log(1 / o.epsilon), cos_cap = 1 / std::sqrt(1 + tan2c);
        double worst = 0;
        for (std::uint32_t i = 0; i < 300; ++i) {
            // directions near the bins' centres, where most of the density is
            const std::uint32_t j0 = m.texel_bin(static_cast<int>(i % 16), static_cast<int>((i / 16) % 16));
            const glm::uvec3 r = glint::pcg3d(glm::uvec3(i, 9u, 1u));
            const glm::dvec3 h = glm::normalize(glm::dvec3(m.bin_center(j0)) +
                                                1.5 * std::atan(std::sqrt(tan2c)) * glm::dvec3(glint::unit_from_bits<double>(r.x) - 0.5,
                                                                                               glint::unit_from_bits<double>(r.y) - 0.5, 0));
            if (!(h.z > 0)) continue;
            double ref = 0;
            for (std::uint32_t j = 0; j < m.bin_count(); ++j) {
                const glm::dvec3 mj = m.bin_center(j);
                const double cj = glm::dot(mj, h);
                if (c[j] == 0 || cj < cos_cap) continue;
                const double t2 = (1 - cj * cj) / (cj * cj);
                ref += c[j] * std::exp(-t2 / (alpha * alpha)) / (3.141592653589793 * alpha * alpha * cj * cj * cj) / (1 - o.epsilon);
            }
            const double got = m.eval(A, h).pdf;
            worst = std::max(worst, std::fabs(got - ref) / std::max(ref, 1e-300));
        }
        // Rounding alone: eval renormalises h (1 ulp), and 1 - cos^2 at angles of alpha = 0.0025
        // cancels to a relative 1e-10 in tan^2. A bin the search missed would change the sum by at
        // least epsilon times its share of the lobes at h, orders of magnitude more.
        INFO("n " << n << " alpha " << alpha << ": largest relative difference " << worst);
        CHECK(worst < 1e-8);
    }
}

TEST_CASE("bin_map: visiting the texels directly gives the tree walks' result") {
    // direct_texels = 0 always walks the lists, 2^20 always visits the texels under the box.
    const auto map = random_normals(40, 30, 14u, 1.0);
    for (const auto kernel : {glint::bin_kernel::box, glint::bin_kernel::tent, glint::bin_kernel::beckmann})
        for (const auto rule : {glint::coverage_rule::exact_area, glint::coverage_rule::texel_center}) {
            glint::bin_map_options o = opts(16, 2, rule);
            o.kernel = kernel, o.alpha = 0.1;
            o.direct_texels = 0;
            const auto walk = bmap::build(map, o);
            o.direct_texels = 1 << 20;
            const auto visit = bmap::build(map, o);
            o.direct_texels = -1;  // chosen per query: the visit, the walks, or a visit given up
            const auto automatic = bmap::build(map, o);
            double worst = 0;
            int nonzero = 0;
            for (std::uint32_t i = 0; i < 400; ++i) {
                const auto A = glint_test::random_parallelogram<double>(i, 12u, 40, 30, 0.3, 200);
                const std::uint32_t k = glint::pcg3d(glm::uvec3(i, 2u, 3u)).x;
                // h near a texel's normal under A's centre, so that most values are not 0
                const glm::dvec2 c = (A.origin + 0.5 * (A.e0 + A.e1)) * glm::dvec2(40, 30);
                const glm::dvec3 n = walk.bin_center(walk.texel_bin(((static_cast<int>(std::floor(c.x)) % 40) + 40) % 40,
                                                                     ((static_cast<int>(std::floor(c.y)) % 30) + 30) % 30));
                const glm::dvec3 h = glm::normalize(n + 0.05 * glm::dvec3(glint::unit_from_bits<double>(k) - 0.5, glint::unit_from_bits<double>(k * 747796405u) - 0.5, 0));
                const double a = walk.eval(A, h).pdf, b = visit.eval(A, h).pdf, chosen = automatic.eval(A, h).pdf;
                if (a > 0) ++nonzero;
                worst = std::max(worst, std::max(std::fabs(a - b), std::fabs(a - chosen)) / std::max(a, 1e-300));
            }
            INFO("kernel " << static_cast<int>(kernel) << " rule " << static_cast<int>(rule) << ": " << nonzero << " nonzero, largest relative difference " << worst);
            CHECK(nonzero > 200);
            CHECK(worst < 1e-12);
        }
}

TEST_CASE("bin_map: hard footprints") {
    const int w = 20, h = 10;
    const auto map = random_normals(w, h, 17u);
    const auto m = bmap::build(map, opts(8, 2));
    const auto mc = bmap::build(map, opts(8, 2, glint::coverage_rule::texel_center));
    // Inside one texel: coverage 1 for its bin, under both rules.
    const auto tiny = glint::uv_parallelogram<double>::rect({(3.2) / w, (7.3) / h}, {(3.6) / w, (7.9) / h});
    CHECK(m.coverage(tiny, m.texel_bin(3, 7)) == doctest::Approx(1));
    CHECK(mc.coverage(tiny, m.texel_bin(3, 7)) == 1);  // no centre in it: the texel holding its centre
    // Straddling two texels 30% / 70%.
    const auto two = glint::uv_parallelogram<double>::rect({4.7 / w, 2.2 / h}, {5.7 / w, 2.4 / h});
    if (m.texel_bin(4, 2) != m.texel_bin(5, 2)) {
        CHECK(m.coverage(two, m.texel_bin(4, 2)) == doctest::Approx(0.3).epsilon(1e-12));
        CHECK(m.coverage(two, m.texel_bin(5, 2)) == doctest::Approx(0.7).epsilon(1e-12));
    }
    // Zero area: a point query at the centre texel.
    const auto line = glint::uv_parallelogram<double>{{2.0 / w, 5.5 / h}, {3.0 / w, 0.0}, {0.0, 0.0}};
    CHECK(m.coverage(line, m.texel_bin(3, 5)) == 1);  // its centre (3.5, 5.5) lies in texel (3, 5)
    // NaN and Inf: pdf 0, no sample, count 0.
    const double nan = std::nan("");
    const glint::uv_parallelogram<double> bad{{nan, 0.1}, {0.1, 0}, {0, 0.1}}, inf{{0.1, 0.1}, {HUGE_VAL, 0}, {0, 0.1}};
    for (const auto& A : {bad, inf}) {
        CHECK(m.eval(A, {0, 0, 1}).pdf == 0);
        CHECK_FALSE(m.sample(A, {0.5, 0.5}, {0.5, 0.5}).valid);
        CHECK(m.count(A, 0) == 0);
    }
    CHECK(m.eval(glint::uv_parallelogram<double>::rect({0, 0}, {0.5, 0.5}), {nan, 0, 1}).pdf == 0);
    CHECK_FALSE(m.sample(glint::uv_parallelogram<double>::rect({0, 0}, {0.5, 0.5}), {nan, 0.5}, {0.5, 0.5}).valid);
    // 1000:1 at 30 degrees: exact against the clip, and sums to 1.
    const double t = 0.5235987755982988;
    const glint::uv_parallelogram<double> thin{{0.31, 0.77}, {40.0 * std::cos(t) / w, 40.0 * std::sin(t) / h}, {-0.04 * std::sin(t) / w, 0.04 * std::cos(t) / h}};
    const auto ref = glint_test::brute_coverages(m, glint_test::in_texels(thin, w, h));
    double sum = 0;
    for (std::uint32_t j = 0; j < m.bin_count(); ++j) {
        CHECK(m.coverage(thin, j) == doctest::Approx(ref[j]).scale(1e-12));
        sum += m.coverage(thin, j);
    }
    CHECK(sum == doctest::Approx(1).epsilon(1e-12));
    // The horizon and beyond: finite, and 0 below.
    for (const auto kernel : {glint::bin_kernel::box, glint::bin_kernel::tent, glint::bin_kernel::beckmann}) {
        glint::bin_map_options o = opts(16, 2);
        o.kernel = kernel;
        const auto mk = bmap::build(random_normals(w, h, 5u, 1.5), o);
        const auto A = glint::uv_parallelogram<double>::rect({0, 0}, {1, 1});
        for (const glm::dvec3 hv : {glm::dvec3(1, 0, 0), glm::dvec3(0.6, 0.8, 0), glm::dvec3(0.7, 0.7, 1e-9)}) {
            const auto e = mk.eval(A, hv);
            CHECK(std::isfinite(e.pdf));
            CHECK(std::isfinite(e.ndf));
            CHECK(e.pdf >= 0);
        }
        CHECK(mk.eval(A, {0.6, 0, -0.8}).pdf == 0);
    }
}

TEST_CASE("bin_map: 1e5 random float queries give finite, non-negative results") {
    // Footprints from 1e-6 to 1e6 texels, aspect to 1e6, anywhere within 1e4 periods; h anywhere
    // on the sphere (below the horizon too); every kernel and rule.
    const auto map = random_normals(24, 17, 31u, 1.2);
    long bad = 0, queries = 0;
    for (const auto kernel : {glint::bin_kernel::box, glint::bin_kernel::tent, glint::bin_kernel::beckmann})
        for (const auto rule : {glint::coverage_rule::exact_area, glint::coverage_rule::texel_center}) {
            glint::bin_map_options o = opts(16, 4, rule);
            o.kernel = kernel, o.alpha = 0.05;
            const auto m = glint::bin_map<float>::build(map, o);
            for (std::uint32_t i = 0; i < 16667; ++i) {
                const auto u = [&](std::uint32_t k) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, k, 0x77u)).x); };
                const float size = std::pow(10.0f, -6 + 12 * u(0)) / 24, ratio = std::pow(10.0f, 6 * u(1)), t = 6.2831853f * u(2);
                glint::uv_parallelogram<float> A;
                A.e0 = size * glm::vec2(std::cos(t), std::sin(t)), A.e1 = size / ratio * glm::vec2(-std::sin(t), std::cos(t));
                A.origin = glm::vec2(2e4f * (u(3) - 0.5f), 2e4f * (u(4) - 0.5f));
                const glm::vec3 h = glm::normalize(glm::vec3(2 * u(5) - 1, 2 * u(6) - 1, 2 * u(7) - 0.8f));
                const auto e = m.eval(A, h);
                const auto s = m.sample(A, {u(8), u(9)}, {u(10), u(11)});
                ++queries;
                if (!(std::isfinite(e.pdf) && std::isfinite(e.ndf) && e.pdf >= 0 && e.ndf >= 0 && std::isfinite(s.pdf) && s.pdf >= 0 &&
                      std::isfinite(s.h.x) && std::isfinite(s.h.y) && std::isfinite(s.h.z)))
                    ++bad;
            }
        }
    CHECK(queries == 100002);
    CHECK(bad == 0);
}

TEST_CASE("bin_map: bad input is rejected with an error that names it") {
    using glint_test::contains;
    using glint_test::error_of;
    const auto map = random_normals(4, 4, 1u);
    const auto with = [&](auto change) {
        glint::bin_map_options o;
        change(o);
        return error_of([&] { bmap::build(map, o); });
    };
    CHECK(contains(with([](auto& o) { o.bins_per_side = 0; }), "bins_per_side 0"));
    CHECK(contains(with([](auto& o) { o.bins_per_side = 5000; }), "bins_per_side 5000"));
    CHECK(contains(with([](auto& o) { o.leaf_size = 0; }), "leaf_size 0"));
    CHECK(contains(with([](auto& o) { o.max_tile_copies = 0; }), "max_tile_copies 0"));
    CHECK(contains(with([](auto& o) { o.kernel = glint::bin_kernel::beckmann, o.alpha = 0.001; }), "alpha 0.001"));
    CHECK(contains(with([](auto& o) { o.kernel = glint::bin_kernel::beckmann, o.epsilon = 0.5; }), "epsilon 0.5"));
    CHECK(contains(with([](auto& o) { o.kernel = glint::bin_kernel::beckmann, o.alpha = 0.5, o.bins_per_side = 256; }), "use fewer bins"));
    CHECK(with([](auto& o) { o.kernel = glint::bin_kernel::beckmann, o.alpha = 0.5; }).empty());
    // Maps too large for the 16-bit texel coordinates.
    CHECK(contains(error_of([] { bmap::check_size(65537, 1); }), "width 65537 > 65536"));
    CHECK(contains(error_of([] { bmap::check_size(1, 70000); }), "height 70000 > 65536"));
    CHECK(error_of([] { bmap::check_size(65536, 65536); }).empty());
    std::vector<glm::vec3> row(65537, glm::vec3(0, 0, 1));
    CHECK(contains(error_of([&] { bmap::build(glint::normal_map(65537, 1, row)); }), "width 65537"));
    // Normals with z <= 0 never reach the bin map: the normal map rejects them, or clamps them
    // when asked (normal_map_options::clamp_z), and the bin map bins the clamped normal.
    std::vector<glm::vec3> below(4, glm::vec3(0, 0, 1));
    below[2] = glm::vec3(1, 0, -0.2f);
    CHECK(contains(error_of([&] { glint::normal_map(2, 2, below); }), "texel (0, 1)"));
    glint::normal_map_options clamp;
    clamp.clamp_z = true;
    const auto clamped = bmap::build(glint::normal_map(2, 2, below, clamp), opts(16, 1));
    CHECK(clamped.texel_bin(0, 1) == clamped.bin_of({0.9999995, 0, 1e-3}));
}

TEST_CASE("bin_map: queries allocate nothing") {
    const auto map = random_normals(64, 64, 8u);
    for (const auto kernel : {glint::bin_kernel::box, glint::bin_kernel::tent, glint::bin_kernel::beckmann})
        for (const auto rule : {glint::coverage_rule::exact_area, glint::coverage_rule::texel_center}) {
            glint::bin_map_options o = opts(32, 4, rule);
            o.kernel = kernel, o.alpha = 0.05;
            const auto m = bmap::build(map, o);
            double sink = 0;
            allocations = 0;
            counting = true;
            for (std::uint32_t i = 0; i < 200; ++i) {
                const auto A = glint_test::random_parallelogram<double>(i, 4u, 64, 64, 0.5, 300);
                const auto s = m.sample(A, {0.3, 0.6}, {0.2, 0.9});
                sink += s.pdf + m.eval(A, {0.1, 0.2, 0.97}).pdf + m.coverage(A, i % m.bin_count()) + static_cast<double>(m.count(A, 0));
            }
            counting = false;
            CHECK(std::isfinite(sink));
            CHECK(allocations == 0);
        }
}

TEST_CASE("bin_map: build statistics and memory") {
    glint::pattern_params p;
    p.kind = glint::pattern::flakes, p.width = p.height = 256, p.feature = 8, p.slope_rms = 0.15;
    const auto m = bmap::build(glint::make_normal_map(p), opts(32, 16));
    const auto& s = m.statistics();
    CHECK(s.texels == 65536u);
    CHECK(s.bins == 1024u);
    CHECK(s.depth == 16);
    std::uint64_t total = 0, nonempty = 0;
    for (std::uint32_t j = 0; j < m.bin_count(); ++j) total += m.bin_texels(j), nonempty += m.bin_texels(j) > 0 ? 1u : 0u;
    CHECK(total == 65536u);
    CHECK(s.nonempty_bins == nonempty);
    // 3 bytes of list entry per texel (sides up to 4096), the offsets, and the bin map: flakes of 8
    // texels put 1 to 4 bins in most 8 x 8 blocks, 2 bits each with a short palette.
    const std::size_t list_and_offsets = 65536u * 3u + 1u + 1025u * 4u;
    CHECK(m.memory_bytes() > list_and_offsets + 65536u / 8u);
    CHECK(m.memory_bytes() < list_and_offsets + 65536u * 3u / 4u);
}

TEST_CASE("bin_map: the compressed bin map gives every texel its normal's bin") {
    // Palettes of 1 to 48 bins, raw blocks (noise, n = 64 and 512: 16- and 32-bit bins), partial
    // blocks at the edges.
    struct config {
        glint::pattern kind;
        int w, h, n;
    };
    for (const auto& c : {config{glint::pattern::flakes, 77, 45, 32}, config{glint::pattern::noise, 40, 19, 64}, config{glint::pattern::noise, 33, 33, 512},
                          config{glint::pattern::scratched_metal, 64, 72, 255}, config{glint::pattern::flat, 9, 1, 8}}) {
        glint::pattern_params p;
        p.kind = c.kind, p.width = c.w, p.height = c.h, p.slope_rms = 0.4, p.feature = 6, p.count = 20;
        if (c.h == 1) p.height = 2;
        const auto map = glint::make_normal_map(p);
        const auto m = bmap::build(map, opts(c.n, 16));
        long wrong = 0;
        for (int y = 0; y < map.height(); ++y)
            for (int x = 0; x < map.width(); ++x) wrong += m.texel_bin(x, y) != m.bin_of(glm::dvec3(map.texel(x, y))) ? 1 : 0;
        CAPTURE(glint::pattern_name(c.kind));
        CHECK(wrong == 0);
    }
}
