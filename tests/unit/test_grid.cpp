// The grid's deterministic properties: lattice weights (non-negative, sum 1, continuous across
// every kind of lattice boundary), triangle-grid barycentrics (linear precision, hence
// continuity), determinism, continuity of R as the footprint moves, the smooth-result gate and
// its bound, point-light expectations, hard inputs, and C++'s vector paths against the scalar
// ones GLSL runs (the skip test's AVX2 masks, the four lattice points' lanes, lists of lights and
// batches of pixels in AVX2 lanes).
#include <doctest/doctest.h>

#include "../support/lanes_paths.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glint/grid.hpp>
#include <glint/ibl.hpp>

#include "../support/grid_scene.hpp"

namespace {

using K = glint::detail::glsl::kernels<float>;
using lattice_map = std::map<std::tuple<int, int, int>, double>;

glm::vec2 random_unit(std::uint32_t i, std::uint32_t salt) {
    const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, salt, 0x9e1u));
    return {glint::unit_from_bits<float>(h.x), glint::unit_from_bits<float>(h.y)};
}

// The footprint with major axis `major` along `angle`, aspect ratio `ratio`.
void footprint(float major, float ratio, float angle, glm::vec2& dx, glm::vec2& dy) {
    dx = glm::vec2(std::cos(angle), std::sin(angle)) * major;
    dy = glm::vec2(-std::sin(angle), std::cos(angle)) * (major / ratio);
}

lattice_map weights_of(float major, float ratio, float angle) {
    glm::vec2 dx, dy;
    footprint(major, ratio, angle, dx, dy);
    const auto l = glint::lattice_of(dx, dy, 1.5f);
    lattice_map m;
    for (int i = 0; i < 4; ++i) m[{l.lod[i], l.level[i], l.bin[i]}] += static_cast<double>(l.weight[i]);
    return m;
}

double l1_distance(const lattice_map& a, const lattice_map& b) {
    double d = 0;
    for (const auto& [k, w] : a) d += std::fabs(w - (b.count(k) ? b.at(k) : 0.0));
    for (const auto& [k, w] : b)
        if (!a.count(k)) d += w;
    return d;
}

}  // namespace

TEST_CASE("lattice: weights are non-negative, sum to 1, and are continuous across LOD, ratio, angle and triangle boundaries") {
    double worst_sum = 0, worst_jump = 0;
    int negative = 0;
    const float eps = 1e-4f;
    // Random footprints, and footprints placed on every kind of boundary: integer LOD, integer
    // log2 ratio, rotation bin edges of each level, and the A/B/C triangle edges.
    std::vector<std::tuple<float, float, float>> cases;
    for (std::uint32_t i = 0; i < 4000; ++i) {
        const glm::vec2 u = random_unit(i, 1), v = random_unit(i, 2);
        cases.emplace_back(std::exp2(-10.0f + 20.0f * u.x), std::exp2(5.0f * u.y), 3.14159265f * v.x);
    }
    for (int lod = -3; lod <= 3; ++lod)
        for (int level = 0; level <= 4; ++level)
            for (int k = 0; k < 16; ++k) {
                const float ratio = std::exp2(static_cast<float>(level));
                const float minor = std::exp2(static_cast<float>(lod)) / 1.5f;
                cases.emplace_back(minor * ratio, ratio, 3.14159265f * static_cast<float>(k) / 16.0f);
                cases.emplace_back(minor * ratio, ratio * 1.3f, 3.14159265f * (static_cast<float>(k) + 0.3f) / 16.0f);
            }
    for (const auto& [major, ratio, angle] : cases) {
        const lattice_map w = weights_of(major, ratio, angle);
        double sum = 0;
        for (const auto& kv : w) sum += kv.second, negative += kv.second < 0;
        worst_sum = std::max(worst_sum, std::fabs(sum - 1));
        // Perturbations of relative size eps in each parameter: the weights move by O(eps).
        for (const auto& [dm, dr, da] : {std::make_tuple(1 + eps, 1.0f, 0.0f), std::make_tuple(1 - eps, 1.0f, 0.0f),
                                          std::make_tuple(1.0f, 1 + eps, 0.0f), std::make_tuple(1.0f, 1 - eps, 0.0f),
                                          std::make_tuple(1.0f, 1.0f, eps), std::make_tuple(1.0f, 1.0f, -eps)}) {
            const float a2 = angle + da < 0 ? angle + da + 3.14159265f : angle + da;
            worst_jump = std::max(worst_jump, l1_distance(w, weights_of(major * dm, std::max(1.0f, ratio * dr), a2)) / static_cast<double>(eps));
        }
    }
    MESSAGE(cases.size() << " footprints: max |sum - 1| " << worst_sum << ", max L1 change of the weights per unit relative change "
                         << worst_jump);
    CHECK(negative == 0);
    CHECK(worst_sum < 1e-6);
    // The weights are piecewise linear in (log2 minor, log2 ratio, angle / bin width); the steepest
    // slope is 2 (the triangles' 2 fx) times 32 bins / pi per radian at level 4, plus float
    // rounding of the footprint. A discontinuity would show as a jump of order 1 / eps = 1e4.
    CHECK(worst_jump < 100);
}

TEST_CASE("lattice rotations: cos and sin of bin pi / 2^(level + 1) from the table are the correctly rounded values") {
    // Every rotation of the lattice (levels 0..4, 2^(level + 1) bins each). The reference is long
    // double cos and sin of the long double angle, rounded once to float and to double: the table
    // must give exactly those in float, and within 1 ulp in double (the long double angle is
    // itself rounded, 2^-64 relative).
    using KD = glint::detail::glsl::kernels<double>;
    int checked = 0, float_differ = 0, double_far = 0;
    for (int level = 0; level <= 4; ++level)
        for (int bin = 0; bin < (2 << level); ++bin) {
            const long double angle = static_cast<long double>(bin) * 3.14159265358979323846264338327950288L / static_cast<long double>(2 << level);
            // cos(pi / 2) is exactly 0; the long double angle's rounding leaves -2.5e-20 there.
            auto exact = [](long double x) { return std::fabs(x) < 1e-18L ? 0.0L : x; };
            const long double c_ref = exact(std::cos(angle)), s_ref = exact(std::sin(angle));
            const glm::vec2 f = K::glint_lattice_rotation(level, bin);
            const glm::dvec2 d = KD::glint_lattice_rotation(level, bin);
            float_differ += (f.x != static_cast<float>(c_ref)) + (f.y != static_cast<float>(s_ref));
            for (int c = 0; c < 2; ++c) {
                const double ref = static_cast<double>(c == 0 ? c_ref : s_ref);
                const double ulp = std::nextafter(std::fabs(ref), 2.0) - std::fabs(ref);
                double_far += std::fabs(d[c] - ref) > ulp;
            }
            ++checked;
        }
    CHECK(checked == 62);
    CHECK(float_differ == 0);
    CHECK(double_far == 0);
}

TEST_CASE("lattice scalings: glint_exp2_int(n) is exactly 2^n for |n| <= 30, in float and double") {
    // The lattice's cell scalings 2^-(lod + level) reach n from -29 to 24; the reference is ldexp.
    using KD = glint::detail::glsl::kernels<double>;
    int differ = 0;
    for (int n = -30; n <= 30; ++n) differ += (K::glint_exp2_int(n) != std::ldexp(1.0f, n)) + (KD::glint_exp2_int(n) != std::ldexp(1.0, n));
    CHECK(differ == 0);
}

TEST_CASE("triangle grid: barycentrics reproduce the point (so interpolation is continuous across edges)") {
    double worst = 0;
    for (std::uint32_t i = 0; i < 100000; ++i) {
        const glm::vec2 q = (random_unit(i, 3) - 0.5f) * 200.0f;
        const auto t = K::glint_triangle_grid(q);
        glm::dvec2 r(0);
        double sum = 0;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec2 s(t.vertex[k].x, t.vertex[k].y);
            const glm::dvec2 pos(s.x + 0.5 * s.y, s.y * 0.8660254037844386);  // unskewed vertex position
            r += static_cast<double>(t.weight[k]) * pos;
            sum += static_cast<double>(t.weight[k]);
            CHECK(t.weight[k] >= 0.0f);
        }
        worst = std::max({worst, std::fabs(sum - 1), glm::length(r - glm::dvec2(q))});
    }
    MESSAGE("max |sum of weights - 1| or |interpolated position - q|: " << worst);
    CHECK(worst < 1e-4);
}

TEST_CASE("grid: the same inputs give the same output, other seeds other glints") {
    glint_test::grid_scene s;
    s.kind = glint_test::light_kind::sphere, s.log_density = 4.0f, s.footprint = 0.5f;
    s.prepare();
    int differing_seeds = 0;
    for (std::uint32_t i = 0; i < 200; ++i) {
        const glm::vec2 uv = random_unit(i, 4) * 50.0f;
        const auto a = s.estimate(i, uv), b = s.estimate(i, uv), c = s.estimate(i + 1000, uv);
        CHECK(a.value == b.value);
        CHECK(a.draws == b.draws);
        differing_seeds += a.value != c.value;
    }
    CHECK(differing_seeds > 150);
}

TEST_CASE("grid: R is continuous as the footprint slides over the surface (no jumps between cells)") {
    // R along a line crossing about 20 cells in steps of 1e-3 of a cell: with piecewise-linear
    // interpolation a step moves R by about 1e-3 of its range; a change of vertices or random
    // numbers at a cell edge (a nearest-vertex lookup) would jump by a sizeable part of it.
    glint_test::grid_scene s;
    s.kind = glint_test::light_kind::sphere, s.log_density = 3.0f, s.footprint = 1.0f, s.alpha = 0.1f;
    s.prepare();
    glm::vec2 dx, dy;
    s.derivatives(dx, dy);
    const auto g = s.params(11u);
    double lo = 1e30, hi = -1e30, max_step = 0, prev = 0;
    for (int i = 0; i <= 20000; ++i) {
        const glm::vec2 uv = glm::vec2(3.0f, 1.0f) + static_cast<float>(i) * 1e-3f * glm::vec2(0.83f, 0.56f);
        const double r = static_cast<double>(glint::grid_sample(uv, dx, dy, g, s.light).value);
        lo = std::min(lo, r), hi = std::max(hi, r);
        if (i > 0) max_step = std::max(max_step, std::fabs(r - prev));
        prev = r;
    }
    MESSAGE("range of R along the path " << lo << " .. " << hi << ", largest step " << max_step);
    REQUIRE(hi > lo);
    CHECK(max_step < 0.01 * (hi - lo));
}

TEST_CASE("grid: the smooth-result gate returns E[R] without drawing exactly where its bound is below the tolerance, and the bound holds") {
    glint_test::grid_scene s;
    s.kind = glint_test::light_kind::sphere, s.footprint = 1.0f, s.alpha = 0.2f;
    s.prepare();
    glm::vec2 dx, dy;
    s.derivatives(dx, dy);
    const double area = std::fabs(static_cast<double>(dx.x * dy.y - dx.y * dy.x));
    const double tol = 0.05;
    // The bound (1 - p) / (N p) < tol^2 holds from N > (1 - p) / (p tol^2).
    const double n_gate = (1 - static_cast<double>(s.p)) / (static_cast<double>(s.p) * tol * tol);
    for (double factor : {0.5, 0.9, 1.1, 2.0}) {
        glint::grid_params<float> g = s.params(5u);
        g.smooth_tolerance = static_cast<float>(tol);
        g.log_density = static_cast<float>(std::log(factor * n_gate / area));
        double sum = 0, sq = 0;
        int drew = 0;
        const int n = 4000;
        for (int i = 0; i < n; ++i) {
            g.seed = static_cast<std::uint32_t>(i) * 747796405u;
            const auto e = glint::grid_sample(random_unit(static_cast<std::uint32_t>(i), 6) * 100.0f, dx, dy, g, s.light);
            const double m = static_cast<double>(glint::modulation(e));
            sum += m, sq += m * m, drew += e.draws > 0;
        }
        const double mean = sum / n, sd = std::sqrt(std::max(0.0, sq / n - mean * mean));
        MESSAGE("N = " << factor << " x the gate: " << drew << " of " << n << " sampled, relative sd " << sd);
        if (factor > 1) {
            CHECK(drew == 0);
            CHECK(sd == 0.0);
        } else {
            CHECK(drew == n);
            // Just below the gate the relative sd must still be below the bound, here
            // sqrt((1 - p) / (N p)) = tol / sqrt(factor).
            CHECK(sd <= tol / std::sqrt(factor));
        }
    }
}

TEST_CASE("grid: point lights expect the bilinear mix of the slope cell's corner probabilities, lights that cannot reflect cost nothing") {
    glint_test::grid_scene s;
    s.kind = glint_test::light_kind::point, s.alpha = 0.3f;
    s.prepare();
    const auto e = s.estimate(3u, glm::vec2(1.0f));
    // Recompute E[R] from the definition.
    const float cell = 0.02f;
    const glm::vec2 slope = s.light.slope / cell;
    const glm::vec2 base = glm::floor(slope), f = slope - base;
    const float dh = glint::total_area(glint::ndf::ggx, glm::vec2(s.alpha));
    double expected = 0;
    for (int j = 0; j < 4; ++j) {
        const glm::vec2 corner = (base + glm::vec2(static_cast<float>(j & 1), static_cast<float>(j >> 1))) * cell;
        const double w = static_cast<double>(((j & 1) ? f.x : 1 - f.x) * ((j >> 1) ? f.y : 1 - f.y));
        expected += w * static_cast<double>(cell * cell * glint::slope_area_density(glint::ndf::ggx, corner, glm::vec2(s.alpha)) / dh);
    }
    CHECK(static_cast<double>(e.expected) == doctest::Approx(expected).epsilon(1e-5));
    // An extended light with p = 0 (below the horizon, behind): no draws, R = 0.
    const auto none = glint::grid_sample(glm::vec2(1.0f), glm::vec2(0.1f, 0), glm::vec2(0, 0.1f), s.params(1u),
                                         glint::grid_extended_light(0.0f, glm::vec3(0, 0, 1)));
    CHECK(none.draws == 0);
    CHECK(none.value == 0.0f);
}

namespace {

// R from its definition (the header of kernels/grid.glsl): every triangle vertex draws at every
// slope corner that can reflect, with no skip test and no cache, summed in the kernel's order.
K::glint_grid_estimate estimate_by_definition(glm::vec2 uv, glm::vec2 dx, glm::vec2 dy, const K::glint_grid_params& g,
                                              const K::glint_grid_light& light) {
    K::glint_grid_estimate o{0.0f, 0.0f, 0};
    auto px = K::glint_grid_pixel_setup(uv, dx, dy, g);
    K::glint_grid_pixel_vertices(px, g);
    glm::ivec2 base;
    const glm::vec4 mu = K::glint_slope_weights(light.slope, g.slope_cell, base);
    const glm::vec4 p = K::glint_grid_corner_probabilities(g, light, base);
    for (int k = 0; k < px.v.count; ++k)
        for (int j = 0; j < 4; ++j) {
            const int i = K::glint_grid_draw_slot(px.v.count, k);  // the kernel's order: lattice point by lattice point
            const glm::ivec2 c = base + glm::ivec2(j & 1, j >> 1);
            const float pj = p[j];
            if (!(px.v.weight[i] > 0)) continue;  // a slot without a vertex
            if (!(mu[j] > 0) || !(pj > 0)) continue;
            const std::uint32_t h1 = K::glint_cell_draw_word(px.v.hash_x[i], K::glint_slope_cell_key(c));
            const float u1 = K::glint_open_unit_from_bits(h1);
            const float u2 = K::glint_open_unit_from_bits(K::glint_cell_draw_second_word(h1, px.v.hash_y[i]));
            const auto b = K::glint_binomial_variant(g.variant, px.N * px.v.share[i], pj, u1, u2, g.pow_method);
            o.value += px.v.weight[i] * mu[j] * b.positive / px.N;
            ++o.draws;
        }
    return o;
}

}  // namespace

// The skip test (kernels/grid.glsl) leaves out draws that are surely 0, judged on the hash word
// against an integer threshold. Were that threshold too low, a draw that gives n >= 1 would be
// left out and R would differ; with it 4x too low, this test fails (checked by hand). 4000 footprints
// over ln densities -2 to 9 (N p from about 1e-4 to past 1/2, where every corner draws), point lights
// of roughness 0.05 to 0.5 and extended lights of p 1e-4 to 0.3, with and without the log-normal factor.
TEST_CASE("grid: the skip test never changes R: grid_sample equals R from its definition, every vertex drawing at every corner") {
    int compared = 0, skipped_pairs = 0, lit = 0;
    for (std::uint32_t i = 0; i < 4000; ++i) {
        const glm::vec2 r1 = random_unit(i, 1), r2 = random_unit(i, 2), r3 = random_unit(i, 3);
        glint::grid_params<float> gp;
        gp.log_density = -2.0f + 11.0f * r1.x;
        gp.density_sigma = (i % 4 == 3) ? 0.5f : 0.0f;
        gp.smooth_tolerance = 0.0f;  // sample every footprint
        gp.seed = i;
        const auto g = glint::detail::to_kernel(gp);
        glm::vec2 dx, dy;
        footprint(0.05f + 2.0f * r1.y, 1.0f + 15.0f * r2.x, 3.14159265f * r2.y, dx, dy);
        const glm::vec2 uv(100.0f * r3.x, 100.0f * r3.y);
        const float theta = 0.7f * random_unit(i, 4).x, phi = 6.2831853f * random_unit(i, 4).y;
        const glm::vec3 h(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        const float alpha = 0.05f + 0.45f * random_unit(i, 5).x;
        const auto light = (i % 3 == 2) ? glint::grid_extended_light(std::pow(10.0f, -4.0f + 3.5f * random_unit(i, 5).y), h)
                                        : glint::grid_point_light(glint::ndf::ggx, glm::vec2(alpha), glint::total_area(glint::ndf::ggx, glm::vec2(alpha)), h);
        const auto fast = K::glint_grid_sample(uv, dx, dy, g, light);
        const auto reference = estimate_by_definition(uv, dx, dy, g, light);
        CHECK(fast.expected > 0);
        CHECK(fast.value == reference.value);
        ++compared;
        skipped_pairs += reference.draws - fast.draws;
        lit += reference.value > 0;
    }
    MESSAGE(compared << " footprints; pairs the skip test left out: " << skipped_pairs << "; footprints with a glint: " << lit);
    CHECK(skipped_pairs > 10 * compared);  // the test is exercised: most pairs are skipped
    CHECK(lit > compared / 10);            // and many footprints reflect
}

// The skip test's AVX2 version (C++ with GCC on x86-64, where the CPU has AVX2) against the
// portable loops that GLSL and the baseline build run: the same bits for every vertex and corner.
// 3000 pixels, four or one lattice point, ln densities -2 to 9 (N from about 0.01 to 2e4),
// corner probabilities 1e-5 to 0.5 with some corners dead (p = 0 or outside `live`), with and
// without the skip test. That the comparison sees a difference: the same masks with one corner's p
// doubled differ in many pixels.
TEST_CASE("grid: the skip test's AVX2 masks equal the portable loops' bit for bit") {
    glint_test::for_each_lanes_path([&](int) {
        const bool avx2 = K::glint_cpu_avx2();
        MESSAGE("AVX2 masks: " << std::string(avx2 ? "compared" : "not compared (a CPU without AVX2, or a build without the AVX2 path): the portable loops against themselves"));
        auto same_masks = [](const K::glint_draw_masks& a, const K::glint_draw_masks& b) {
            bool same = a.any == b.any;
            for (int v = 0; v < 12; ++v) same = same && a.bits[v] == b.bits[v];
            return same;
        };
        int pixels = 0, differ = 0, set_bits = 0, clear_bits = 0, wrong_caught = 0;
        for (std::uint32_t i = 0; i < 3000; ++i) {
            const glm::vec2 r1 = random_unit(i, 61), r2 = random_unit(i, 62), r3 = random_unit(i, 63), r4 = random_unit(i, 64);
            glint::grid_params<float> gp;
            gp.log_density = -2.0f + 11.0f * r1.x;
            gp.density_sigma = (i % 5 == 4) ? 0.5f : 0.0f;
            gp.seed = i;
            const auto g = glint::detail::to_kernel(gp);
            glm::vec2 dx, dy;
            footprint(0.05f + 2.0f * r1.y, 1.0f + 15.0f * r2.x, 3.14159265f * r2.y, dx, dy);
            auto px = glint::grid_pixel_setup(100.0f * r3, dx, dy, gp, (i % 2) ? r4.x : -1.0f);
            K::glint_grid_pixel_vertices(px, g);
            std::uint32_t key[4];
            float p[4];
            int live = 0;
            for (int j = 0; j < 4; ++j) {
                const glm::vec2 r = random_unit(i, 70 + static_cast<std::uint32_t>(j));
                key[j] = glint::pcg3d(glm::uvec3(i, static_cast<std::uint32_t>(j), 0x5eu)).x;
                p[j] = (r.x < 0.1f) ? 0.0f : std::pow(10.0f, -5.0f + 4.7f * r.y);
                live |= (r.x < 0.9f) ? (1 << j) : 0;
            }
            const bool skip_test = i % 7 != 6;
            const auto fast = K::glint_skip_test_masks(px, key, p, live, skip_test);
            const auto portable = K::glint_skip_test_masks_inline(px, key, p, live, skip_test);
            for (int v = 0; v < px.v.count; ++v)
                for (int j = 0; j < 4; ++j) ((portable.bits[v] >> j) & 1 ? set_bits : clear_bits) += 1;
            differ += !same_masks(fast, portable);
            ++pixels;
            float doubled[4] = {p[0], p[1], p[2], p[3]};
            doubled[i % 4] = std::min(1.0f, 2.0f * p[i % 4]);
            wrong_caught += !same_masks(K::glint_skip_test_masks(px, key, doubled, live, skip_test), portable);
        }
        MESSAGE(pixels << " pixels, " << differ << " with other masks; vertex-corner bits set " << set_bits << ", clear " << clear_bits
                       << "; pixels where one corner's p doubled changes the masks: " << wrong_caught);
        CHECK(differ == 0);
        CHECK(set_bits > 1000);
        CHECK(clear_bits > 1000);
        CHECK(wrong_caught > 100);
    });
}

TEST_CASE("grid: finite and non-negative on hard inputs: zero and huge footprints, grazing and horizon half vectors, roughness 1e-4, extreme densities") {
    std::size_t bad = 0, total = 0;
    const glm::vec2 zero(0.0f);
    for (int v = 0; v <= 4; ++v)
        for (float logd : {-80.0f, -4.0f, 0.0f, 6.0f, 80.0f})
            for (float fp : {0.0f, 1e-20f, 1e-3f, 1.0f, 1e6f})
                for (float hz : {1.0f, 1e-4f, 0.0f, -0.5f})
                    for (float alpha : {1e-4f, 0.3f})
                        for (int kind = 0; kind < 2; ++kind) {
                            glint::grid_params<float> g;
                            g.log_density = logd;
                            g.variant = static_cast<glint::binomial_variant>(v);
                            g.density_sigma = 0.5f;
                            const glm::vec3 h = glm::normalize(glm::vec3(std::sqrt(std::max(0.0f, 1 - hz * hz)), 0.0f, hz));
                            const auto light = kind ? glint::grid_extended_light(0.3f, h)
                                                    : glint::grid_point_light(glint::ndf::ggx, glm::vec2(alpha), 1.0f, h);
                            for (const glm::vec2& dy : {glm::vec2(0.0f, fp), zero}) {
                                const auto e = glint::grid_sample(glm::vec2(12.5f, -3.0f), glm::vec2(fp, 0.0f), dy, g, light);
                                const float m = glint::modulation(e);
                                ++total;
                                bad += !(std::isfinite(e.value) && std::isfinite(e.expected) && std::isfinite(m) && e.value >= 0 && m >= 0);
                            }
                        }
    MESSAGE(bad << " non-finite or negative of " << total);
    CHECK(bad == 0u);
}

namespace {

// Lights for the footprint test: point lights and extended ones, half vectors near the normal.
template <class real>
std::vector<glint::grid_light<real>> test_lights(std::uint32_t i) {
    std::vector<glint::grid_light<real>> lights;
    for (std::uint32_t k = 0; k < 6; ++k) {
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, k, 0x71u));
        const real a = real(0.3) * glint::unit_from_bits<real>(h.x), b = real(6.2831853) * glint::unit_from_bits<real>(h.y);
        const glint::vec3_t<real> half = glm::normalize(glint::vec3_t<real>(a * std::cos(b), a * std::sin(b), real(1)));
        if (k % 2 == 0) lights.push_back(glint::grid_point_light(glint::ndf::ggx, glint::vec2_t<real>(real(0.2), real(0.15)), real(1), half));
        else lights.push_back(glint::grid_extended_light(real(1e-3) * glint::unit_from_bits<real>(h.z), half));
    }
    return lights;
}

template <class real>
void check_shared_footprint() {
    using KR = glint::detail::glsl::kernels<real>;
    std::size_t estimates = 0, with_draws = 0, differ = 0;
    for (std::uint32_t i = 0; i < 3000; ++i) {
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, 5u, 0x72u));
        const glint::vec2_t<real> uv(real(50) * glint::unit_from_bits<real>(h.x), real(50) * glint::unit_from_bits<real>(h.y));
        const real size = std::exp2(real(-8) + real(6) * glint::unit_from_bits<real>(h.z));
        const glint::vec2_t<real> dx(size, real(0.3) * size), dy(real(-0.2) * size, real(0.5) * size);
        glint::grid_params<real> g;
        g.log_density = real(4) + real(8) * glint::unit_from_bits<real>(glint::pcg3d(glm::uvec3(i, 6u, 0x73u)).x);
        g.density_sigma = (i % 3 == 0) ? real(0.3) : real(0);
        g.seed = i;
        const auto lights = test_lights<real>(i);
        std::vector<glint::grid_estimate<real>> together(lights.size());
        glint::grid_sample_lights(uv, dx, dy, g, lights.data(), lights.size(), together.data());
        auto px = glint::grid_pixel_setup(uv, dx, dy, g);
        // The environment on the same pixel, between the lights.
        typename KR::glint_ibl_levels lv;
        lv.count = 4;
        typename KR::glint_ibl_indicators ind;
        for (int k = 0; k < 8; ++k) lv.radiance[k] = real(k < 4 ? k : 0), ind.w[k] = real(k < 4 ? 0.25 : 0);
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const auto alone = glint::grid_sample(uv, dx, dy, g, lights[k]);
            const auto shared = glint::grid_sample(px, g, lights[k]);
            if (k == 2) {
                const auto env_alone = glint::ibl_sample(uv, dx, dy, g, lv, ind, real(0.01), real(1));
                const auto env_shared = glint::ibl_sample(px, g, lv, ind, real(0.01), real(1));
                differ += env_alone.value != env_shared.value || env_alone.expected != env_shared.expected || env_alone.draws != env_shared.draws;
            }
            ++estimates;
            with_draws += alone.draws > 0;
            for (const auto& e : {together[k], shared})
                differ += e.value != alone.value || e.expected != alone.expected || e.draws != alone.draws;
        }
    }
    MESSAGE(estimates << " estimates (" << with_draws << " with draws) on shared footprints, " << differ << " differ from the single-light call");
    CHECK(with_draws > estimates / 10);  // the comparison covers the draws, not only the smooth gate
    CHECK(differ == 0u);
}

}  // namespace

TEST_CASE("one footprint for every light: grid_sample_lights, grid_sample and ibl_sample on a grid_pixel give exactly the single-light results") {
    check_shared_footprint<float>();
    check_shared_footprint<double>();
}

namespace {

// The list of lights in batches (glint_grid_sample_pixel_lights: eight lights a pass in AVX2
// lanes where the CPU has them, in float) against grid_sample per light on its own copy of the
// pixel, bit for bit: 1 to 19 lights (partial and whole batches), point lights of random
// anisotropic GGX roughness and D_H, half vectors up to about 84 degrees from the normal (slopes
// to 10, past the roughness clamp's reach), extended lights with p from 0 to above 1, a Beckmann
// point light in every 7th pixel (that batch takes the single-light path), one lattice point in
// every 3rd, a published variant (no skip test) in every 5th, the log-normal density factor in
// every 4th, and slope cells from 0.005 to 0.08.
template <class real>
void check_light_batches() {
    using vec2 = glint::vec2_t<real>;
    using vec3 = glint::vec3_t<real>;
    std::size_t estimates = 0, with_draws = 0, differ = 0;
    for (std::uint32_t i = 0; i < 2500; ++i) {
        auto r = [&](std::uint32_t salt) { return glint::unit_from_bits<real>(glint::pcg3d(glm::uvec3(i, salt, 0x7au)).x); };
        const vec2 uv(real(80) * r(1), real(80) * r(2));
        const real size = std::exp2(real(-7) + real(6) * r(3));
        const vec2 dx(size, real(0.2) * size), dy(real(-0.3) * size, real(0.6) * size);
        glint::grid_params<real> g;
        g.log_density = real(2) + real(10) * r(4);
        g.density_sigma = (i % 4 == 1) ? real(0.4) : real(0);
        g.slope_cell = real(0.005) * std::exp2(real(4) * r(5));
        g.variant = (i % 5 == 4) ? glint::binomial_variant::gated : glint::binomial_variant::unbiased;
        g.seed = i;
        const int count = 1 + static_cast<int>(i % 19);
        std::vector<glint::grid_light<real>> lights;
        for (int k = 0; k < count; ++k) {
            const auto salt = 100 + 8 * static_cast<std::uint32_t>(k);
            const real a = real(1.47) * r(salt) * r(salt + 1), b = real(6.2831853) * r(salt + 2);
            const vec3 h(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a));
            const vec2 alpha(real(0.03) + real(0.6) * r(salt + 3), real(0.03) + real(0.6) * r(salt + 4));
            const bool beckmann = i % 7 == 3 && k == count / 2;
            const glint::ndf d = beckmann ? glint::ndf::beckmann : glint::ndf::ggx;
            if (k % 3 != 2) lights.push_back(glint::grid_point_light(d, alpha, glint::total_area(d, alpha) * (real(0.5) + r(salt + 5)), h));
            else lights.push_back(glint::grid_extended_light(real(1.2) * r(salt + 6) * r(salt + 6) * r(salt + 6), h));
        }
        const real lattice_u = (i % 3 == 2) ? r(7) : real(-1);
        auto batch_px = glint::grid_pixel_setup(uv, dx, dy, g, lattice_u);
        auto single_px = glint::grid_pixel_setup(uv, dx, dy, g, lattice_u);
        std::vector<glint::grid_estimate<real>> batch(lights.size());
        glint::grid_sample_lights(batch_px, g, lights.data(), lights.size(), batch.data());
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const auto alone = glint::grid_sample(single_px, g, lights[k]);
            ++estimates;
            with_draws += alone.draws > 0;
            differ += batch[k].value != alone.value || batch[k].expected != alone.expected || batch[k].draws != alone.draws;
        }
    }
    MESSAGE(estimates << " estimates (" << with_draws << " with draws) in batches of lights, " << differ << " differ from the single-light call");
    CHECK(with_draws > estimates / 10);  // the comparison covers the draws, not only the gates
    CHECK(differ == 0u);
}

}  // namespace

TEST_CASE("a list of lights on one pixel (eight a pass in AVX2 lanes) gives exactly grid_sample per light, in float and double") {
    glint_test::for_each_lanes_path([&](int) {
        check_light_batches<float>();
        check_light_batches<double>();
    });
}

namespace {

// The footprints of a batch (glint_grid_pixels_setup: eight a pass in AVX2 lanes where the CPU has
// them, in float) against grid_pixel_setup one pixel at a time, bit for bit (the footprint's four
// numbers, N, lattice_u, uv): derivatives of magnitudes 2^-40 to 2^40 at every angle, degenerate
// (parallel, zero, -0) and rotated pairs (a - c = 0 = b: the angle's atan2(0, 0)), lattice_u from
// -0.1 to 1.1 in every third pixel and none (a null pointer) in every fifth batch, batches of 1 to
// 23 pixels. Returns {pixels, differing}.
template <class real>
std::array<std::size_t, 2> pixels_setup_mismatches() {
    using vec2 = glint::vec2_t<real>;
    std::array<std::size_t, 2> n = {0, 0};
    glint::grid_params<real> g;
    g.log_density = real(5);
    for (std::uint32_t batch = 0; batch < 8000; ++batch) {
        const std::size_t count = 1 + batch % 23;
        std::vector<vec2> uv, dx, dy;
        std::vector<real> lu;
        for (std::uint32_t k = 0; k < count; ++k) {
            auto r = [&](std::uint32_t salt) { return glint::unit_from_bits<real>(glint::pcg3d(glm::uvec3(batch, k, salt)).x); };
            const real scale = std::exp2(real(-40) + real(80) * r(1));
            vec2 a(r(2) * 2 - 1, r(3) * 2 - 1), b(r(4) * 2 - 1, r(5) * 2 - 1);
            if (k % 7 == 1) b = a * (r(6) * 2 - 1);  // parallel: zero area
            if (k % 11 == 2) a = vec2(0), b = vec2(0);
            if (k % 13 == 3) b = vec2(-a.y, a.x);  // round: a - c = 0 = b
            if (k % 17 == 4) a.x = real(-0.0);
            uv.push_back(vec2(real(100) * r(7), real(100) * r(8)));
            dx.push_back(a * scale), dy.push_back(b * scale);
            lu.push_back(k % 3 == 0 ? real(1.2) * r(9) - real(0.1) : real(-1));
        }
        const bool no_u = batch % 5 == 4;
        std::vector<glint::grid_pixel<real>> batched(count);
        glint::grid_pixels_setup(count, uv.data(), dx.data(), dy.data(), g, no_u ? nullptr : lu.data(), batched.data());
        for (std::size_t k = 0; k < count; ++k) {
            const auto one = no_u ? glint::grid_pixel_setup(uv[k], dx[k], dy[k], g) : glint::grid_pixel_setup(uv[k], dx[k], dy[k], g, lu[k]);
            const auto& b = batched[k];
            ++n[0];
            n[1] += std::memcmp(&one.f, &b.f, sizeof(one.f)) != 0 || std::memcmp(&one.N, &b.N, sizeof(one.N)) != 0 ||
                    std::memcmp(&one.lattice_u, &b.lattice_u, sizeof(one.lattice_u)) != 0 || one.uv != b.uv || b.ready || b.v.count != 0;
        }
    }
    return n;
}

}  // namespace

TEST_CASE("a batch of footprints (eight a pass in AVX2 lanes) gives exactly grid_pixel_setup per pixel, in float and double") {
    glint_test::for_each_lanes_path([&](int) {
        const auto f = pixels_setup_mismatches<float>(), d = pixels_setup_mismatches<double>();
        MESSAGE("float: " << f[0] << " pixels, " << f[1] << " differ from grid_pixel_setup; double: " << d[0] << ", " << d[1] << " differ");
        CHECK(f[1] == 0u);
        CHECK(d[1] == 0u);
    });
}

namespace {

// A batch of pixels, each under its own light (glint_grid_sample_pixels: eight pixels a pass in
// AVX2 lanes where the CPU has them, in float), against grid_sample on each pixel's own copy, bit
// for bit: rows of 1 to 37 pixels (partial and whole batches, and the batches of one or two that
// go one at a time), footprints of every angle, aspect 1 to 24 (past the clamp at 16) and sizes
// from 1/128 to 1/2 of a uv unit, point lights of random anisotropic GGX roughness and D_H,
// extended lights with p from 0 to above 1 in every third pixel, one lattice point in every
// fourth pixel (mixed with four-point pixels in one batch), a Beckmann point light in every 7th
// row (its batch takes the single-pixel path), a published variant (no skip test) in every 5th,
// the log-normal density factor in every 6th (one pixel at a time), densities over ten e-folds
// (so that the smooth-result gate returns E[R] in some pixels). Returns {estimates, with draws,
// differing}.
template <class real>
std::array<std::size_t, 3> pixel_batch_mismatches() {
    using vec2 = glint::vec2_t<real>;
    using vec3 = glint::vec3_t<real>;
    std::array<std::size_t, 3> n = {0, 0, 0};
    for (std::uint32_t row = 0; row < 900; ++row) {
        auto r = [&](std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<real>(glint::pcg3d(glm::uvec3(row, salt, 0x5e1u + 64 * i)).x); };
        glint::grid_params<real> g;
        g.log_density = real(2) + real(10) * r(0, 1);
        g.density_sigma = (row % 6 == 5) ? real(0.4) : real(0);
        g.slope_cell = real(0.005) * std::exp2(real(4) * r(0, 2));
        g.variant = (row % 5 == 4) ? glint::binomial_variant::gated : glint::binomial_variant::unbiased;
        g.seed = row;
        const int count = 1 + static_cast<int>(row % 37);
        std::vector<glint::grid_pixel<real>> batch_px, single_px;
        std::vector<glint::grid_light<real>> lights;
        for (int k = 0; k < count; ++k) {
            const auto i = static_cast<std::uint32_t>(k);
            const vec2 uv(real(80) * r(i, 3), real(80) * r(i, 4));
            const real minor = std::exp2(real(-7) + real(6) * r(i, 5)), aspect = real(1) + real(23) * r(i, 6), angle = real(3.14159265) * r(i, 7);
            const vec2 major_axis(std::cos(angle), std::sin(angle)), minor_axis(-std::sin(angle), std::cos(angle));
            const vec2 dx = minor * aspect * major_axis, dy = minor * (major_axis * real(0.3) + minor_axis);  // sheared: every triangle case
            const real lattice_u = (k % 4 == 3) ? r(i, 8) : real(-1);
            batch_px.push_back(glint::grid_pixel_setup(uv, dx, dy, g, lattice_u));
            single_px.push_back(batch_px.back());
            const real a = real(1.47) * r(i, 9) * r(i, 10), b = real(6.2831853) * r(i, 11);
            const vec3 h(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a));
            const vec2 alpha(real(0.03) + real(0.6) * r(i, 12), real(0.03) + real(0.6) * r(i, 13));
            const glint::ndf d = (row % 7 == 3 && k == count / 2) ? glint::ndf::beckmann : glint::ndf::ggx;
            if (k % 3 != 2) lights.push_back(glint::grid_point_light(d, alpha, glint::total_area(d, alpha) * (real(0.5) + r(i, 14)), h));
            else lights.push_back(glint::grid_extended_light(real(1.2) * r(i, 15) * r(i, 15) * r(i, 15), h));
        }
        std::vector<glint::grid_estimate<real>> batch(lights.size());
        glint::grid_sample_pixels(batch_px.data(), g, lights.data(), lights.size(), batch.data());
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const auto alone = glint::grid_sample(single_px[k], g, lights[k]);
            ++n[0];
            n[1] += alone.draws > 0;
            n[2] += batch[k].value != alone.value || batch[k].expected != alone.expected || batch[k].draws != alone.draws;
        }
    }
    return n;
}

}  // namespace

TEST_CASE("a batch of pixels under their own lights (eight a pass in AVX2 lanes) gives exactly grid_sample per pixel, in float and double") {
    glint_test::for_each_lanes_path([&](int) {
        const auto f = pixel_batch_mismatches<float>(), d = pixel_batch_mismatches<double>();
        MESSAGE("float: " << f[0] << " pixels (" << f[1] << " with draws), " << f[2] << " differ from grid_sample; double: " << d[0] << " ("
                          << d[1] << "), " << d[2] << " differ");
        for (const auto& n : {f, d}) {
            CHECK(n[1] > n[0] / 10);  // the comparison covers the draws, not only the gates
            CHECK(n[2] == 0u);
        }
    });
}

TEST_CASE("the grid's bounded floor equals std::floor over its range, in float and double") {
    using KF = glint::detail::glsl::kernels<float>;
    using KD = glint::detail::glsl::kernels<double>;
    std::vector<double> xs = {0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 1e-7, -1e-7, 2.999999, -2.999999, 1073741824.0, -1073741824.0,
                              1073741823.5, -1073741823.5, 8388607.5, -8388607.5, 24.0, -24.0};
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, 31u, 7u));
        const double u = glint::unit_from_bits<double>(h.x) * 2 - 1;
        xs.push_back(u * std::pow(2.0, 30.0 * glint::unit_from_bits<double>(h.y)));  // magnitudes 1 to 2^30, both signs
        xs.push_back(std::nextafter(std::round(xs.back()), 0.0));                       // just inside an integer
    }
    long differ = 0;
    for (double x : xs) {
        const float xf = static_cast<float>(x);
        differ += KF::glint_floor_bounded(xf) != std::floor(xf);
        differ += KD::glint_floor_bounded(x) != std::floor(x);
    }
    MESSAGE(xs.size() << " values, " << differ << " differ from std::floor");
    CHECK(differ == 0);
}

// One lattice point per pixel (glint_grid_pixel_setup_stochastic): at u spread evenly over [0, 1)
// each lattice point is picked for a share of the u equal to its weight (to 1 / 4096, the u
// spacing), its three triangle vertices hold the whole footprint (share 1, weights summing to 1),
// and a negative u gives exactly the four points' estimate.
TEST_CASE("grid: one lattice point per pixel is picked with probability w_L, draws with share 1, and u < 0 keeps the four points") {
    const int m = 4096;
    double worst_share = 0;
    int pixels = 0, spread = 0, differ = 0;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const glm::vec2 r = random_unit(i, 41), q = random_unit(i, 42);
        glm::vec2 dx, dy;
        footprint(std::exp2(-4.0f + 12.0f * r.x), std::exp2(5.0f * r.y), 3.1415926f * q.x, dx, dy);
        const glm::vec2 uv = 50.0f * random_unit(i, 43);
        glint::grid_params<float> g;
        g.log_density = 3, g.seed = i;
        const auto k = glint::detail::to_kernel(g);
        const auto lat = K::glint_footprint_lattice(K::glint_footprint_from_derivatives(dx, dy), g.lod_scale);
        double picked[4] = {0, 0, 0, 0};
        for (int j = 0; j < m; ++j) {
            const float u = (static_cast<float>(j) + 0.5f) / static_cast<float>(m);
            const int l = K::glint_lattice_choice(lat, u);
            REQUIRE(l >= 0);
            REQUIRE(lat.weight[l] > 0.0f);
            picked[l] += 1.0 / m;
            if (j % 512 != 0) continue;
            auto px = glint::grid_pixel_setup(uv, dx, dy, g, u);
            K::glint_grid_pixel_vertices(px, k);
            REQUIRE(px.v.count == 3);
            float weights = 0;
            for (int t = 0; t < px.v.count; ++t) {
                weights += px.v.weight[t];
                CHECK(px.v.share[t] == (px.v.weight[t] > 0 ? 1.0f : 0.0f));
            }
            CHECK(std::fabs(weights - 1.0f) < 1e-6f);
        }
        int positive = 0;
        for (int l = 0; l < 4; ++l) {
            worst_share = std::max(worst_share, std::fabs(picked[l] - static_cast<double>(lat.weight[l])));
            positive += lat.weight[l] > 0.0f;
        }
        spread += positive >= 2;
        ++pixels;
        auto all = glint::grid_pixel_setup(uv, dx, dy, g, -1.0f);
        glint_test::grid_scene s;
        s.kind = glint_test::light_kind::point, s.prepare();
        const auto a = glint::grid_sample(all, g, s.light), b = glint::grid_sample(uv, dx, dy, g, s.light);
        differ += a.value != b.value || a.expected != b.expected || a.draws != b.draws;
    }
    MESSAGE(pixels << " footprints (" << spread << " with two or more lattice points): each point picked within " << worst_share
                   << " of its weight over " << m << " evenly spread u");
    CHECK(spread > pixels / 2);  // the choice is tested where there is one to make
    CHECK(worst_share <= 1.0 / m + 1e-6);
    CHECK(differ == 0);
}

namespace {

// glint_lattice_triangles_x4 (C++: the four lattice points in vector lanes) against the scalar
// path GLSL runs, glint_lattice_rotation and glint_triangle_grid one lattice point at a time, over
// footprints of every LOD, ratio and angle at uv of magnitudes 1e-3 to 1e6, both signs.
// Returns the lattice points compared and the number that differ in a vertex's weight or hash
// (PCG3D of its cell and its lattice point's key, which C++ computes with the triangles);
// `skew` moves the scalar path's uv by one unit in the last place (a wrong variant the comparison
// must catch).
template <class real>
std::pair<long, long> lattice_triangles_mismatches(bool skew) {
    using KR = glint::detail::glsl::kernels<real>;
    long points = 0, differ = 0;
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const glm::vec2 r1 = random_unit(i, 81), r2 = random_unit(i, 82), r3 = random_unit(i, 83);
        glm::vec2 dx, dy;
        footprint(std::pow(2.0f, -20.0f + 40.0f * r1.x), 1.0f + 20.0f * r1.y, 3.14159265f * r2.x, dx, dy);
        const auto f = KR::glint_footprint_from_derivatives(glm::vec<2, real>(dx), glm::vec<2, real>(dy));
        const auto lat = KR::glint_footprint_lattice(f, real(1.5));
        const real scale = std::pow(real(10), real(-3) + real(9) * real(r2.y));
        const glm::vec<2, real> uv(scale * (real(2) * real(r3.x) - 1), scale * (real(2) * real(r3.y) - 1));
        const std::uint32_t seed = i * 2654435761u;
        const auto tris = KR::glint_lattice_triangles_x4(uv, lat, seed);
        const glm::vec<2, real> at = skew ? glm::vec<2, real>(std::nextafter(uv.x, real(1e30)), uv.y) : uv;
        for (int l = 0; l < 4; ++l) {
            const glm::vec<2, real> rot = KR::glint_lattice_rotation(lat.level[l], lat.bin[l]);
            const glm::vec<2, real> r(rot.x * at.x + rot.y * at.y, -rot.y * at.x + rot.x * at.y);
            const auto tri = KR::glint_triangle_grid(glm::vec<2, real>(r.x * KR::glint_exp2_int(-lat.lod[l] - lat.level[l]), r.y * KR::glint_exp2_int(-lat.lod[l])));
            const std::uint32_t key = (static_cast<std::uint32_t>(lat.lod[l] + 64) | (static_cast<std::uint32_t>(lat.level[l]) << 8u) |
                                       (static_cast<std::uint32_t>(lat.bin[l]) << 12u)) ^ seed;
            bool same = true;
            for (int t = 0; t < 3; ++t) {
                const glm::uvec3 h = KR::glint_pcg3d(glm::uvec3(static_cast<std::uint32_t>(tri.vertex[t].x), static_cast<std::uint32_t>(tri.vertex[t].y), key));
                same = same && tris.hash[0][4 * t + l] == h.x && tris.hash[1][4 * t + l] == h.y && tris.hash[2][4 * t + l] == h.z && tris.weight[t][l] == tri.weight[t];
            }
            differ += !same;
            ++points;
        }
    }
    return {points, differ};
}

}  // namespace

TEST_CASE("the four lattice points' triangles at once (C++) equal the scalar rotation and triangle grid bit for bit, in float and double") {
    glint_test::for_each_lanes_path([&](int) {
        const auto f = lattice_triangles_mismatches<float>(false), d = lattice_triangles_mismatches<double>(false);
        const auto f_skew = lattice_triangles_mismatches<float>(true), d_skew = lattice_triangles_mismatches<double>(true);
        MESSAGE("float: " << f.first << " lattice points, " << f.second << " differ; double: " << d.first << ", " << d.second
                          << "; with the scalar path's u one ulp off: " << f_skew.second << " and " << d_skew.second << " differ");
        CHECK(f.second == 0);
        CHECK(d.second == 0);
        CHECK(f_skew.second > 1000);
        CHECK(d_skew.second > 1000);
    });
}

namespace {

// C++'s four-lane versions of glint_grid_skip_inputs and glint_ibl_probabilities against the
// scalar formulas that GLSL runs, written out here: the number of values that differ (bit for bit;
// two NaNs agree). `skew` spoils the reference (the skip bound's 1.0001 as 1.0002, the
// probabilities' total summed from the top level down), so that the comparison is seen to fail:
// each spoilt part alone made about 27000 and 2800 of the float values differ (checked by hand).
template <class real>
std::pair<int, int> vector_path_mismatches(bool skew) {
    using KR = glint::detail::glsl::kernels<real>;
    int values = 0, differ = 0;
    auto same = [](real a, real b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    for (std::uint32_t i = 0; i < 3000; ++i) {
        const glm::vec2 r1 = random_unit(i, 11), r2 = random_unit(i, 12), r3 = random_unit(i, 13);
        // Skip bounds: ln densities -3 to 5 put N w_L on both sides of 2, where the bound's select turns.
        glint::grid_params<real> gp;
        gp.log_density = real(-3.0f + 8.0f * r1.x);
        gp.density_sigma = (i % 5 == 4) ? real(0.5) : real(0);
        gp.seed = i;
        const auto g = glint::detail::to_kernel(gp);
        glm::vec2 dx, dy;
        footprint(0.05f + 2.0f * r1.y, 1.0f + 15.0f * r2.x, 3.14159265f * r2.y, dx, dy);
        const real lattice_u = (i % 3 == 0) ? real(r3.y) : real(-1);
        auto px = KR::glint_grid_pixel_setup_stochastic(glm::vec<2, real>(100.0f * r3.x, 100.0f * r3.x * r3.y), glm::vec<2, real>(dx), glm::vec<2, real>(dy), g,
                                                        lattice_u);
        KR::glint_grid_pixel_vertices(px, g);
        for (int s = 0; s < (px.v.count <= 4 ? 4 : 12); ++s) {
            const real scale = (px.v.weight[s] > real(0)) ? (skew ? real(1.0002) : real(1.0001)) : real(0);
            differ += !same(px.skip_scale[s], KR::glint_binomial_trials_bound(px.N * px.v.share[s]) * scale);
            ++values;
        }
        // Level probabilities: K from 3 to 8, indicators from -0.2 to 1.2 (clamped at both ends), a
        // NaN now and then, E_D / D_H from 0 to 3 (totals above 1 scaled down).
        typename KR::glint_ibl_levels lv;
        lv.count = 3 + static_cast<int>(i % 6);
        typename KR::glint_ibl_indicators ind;
        for (int k = 0; k < 8; ++k) {
            lv.radiance[k] = real(k);
            ind.w[k] = real(-0.2f + 1.4f * random_unit(i, 20 + static_cast<std::uint32_t>(k)).x);
        }
        if (i % 97 == 5) ind.w[i % 3] = std::numeric_limits<real>::quiet_NaN();
        const real e_d = real(3.0f * r3.y), d_h = real(0.5f + 3.5f * random_unit(i, 14).x);
        const auto pr = KR::glint_ibl_probabilities(lv, ind, e_d, d_h);
        real term[8], total = real(0);
        for (int k = 0; k < 8; ++k) term[k] = (k < lv.count) ? glm::clamp(e_d * ind.w[k] / glm::max(d_h, real(1)), real(0), real(1)) : real(0);
        for (int k = 0; k < 8; ++k) total += term[skew ? 7 - k : k];
        const real scale = (total > real(1)) ? real(1) / total : real(1);
        for (int k = 0; k < 8; ++k, ++values) differ += !same(pr.p[k], term[k] * scale);
    }
    return {values, differ};
}

}  // namespace

TEST_CASE("C++'s four-lane skip bounds and IBL level probabilities equal the scalar formulas GLSL runs, in float and double") {
    const auto f = vector_path_mismatches<float>(false), d = vector_path_mismatches<double>(false);
    const auto f_skew = vector_path_mismatches<float>(true), d_skew = vector_path_mismatches<double>(true);
    MESSAGE("float: " << f.first << " values, " << f.second << " differ; double: " << d.first << ", " << d.second
                      << "; against the spoilt references: " << f_skew.second << " and " << d_skew.second << " differ");
    CHECK(f.second == 0);
    CHECK(d.second == 0);
    CHECK(f_skew.second > 1000);
    CHECK(d_skew.second > 1000);
}
