// Tiny-example NDF maps (glint/ndf_map.hpp): the builder's checks and invariants, the map against
// the element path (the direct P-NDF) of the same layout, transforms, continuity, periodicity,
// stochastic ownership, the coated BRDF and float hard cases.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glint/ndf_map.hpp>
#include <glint/patterns.hpp>

#include "../support/ndf_map_support.hpp"
#include "../support/pndf_support.hpp"

namespace {

using map_t = glint::ndf_map<float>;
using placement = glint::ndf_placement<float>;

float rnd(std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, salt, 0x4d1u)).x); }

glint::normal_map example(glint::pattern kind, int n) { return glint::make_normal_map(glint_test::example_pattern(kind, n)); }

map_t small_map(glint::pattern kind, int n = 16, double sigma_r = 0.02, int res = 64) {
    glint::ndf_map_params mp;
    mp.sigma_r = sigma_r, mp.resolution = res;
    return map_t::build(example(kind, n), mp);
}

glint::texel_footprint<float> fp_at(glm::vec2 c, float a, float b, float t) { return glint_test::rotated_footprint(c, a, b, t); }

glm::mat2 rotation(float t) { return glm::mat2(std::cos(t), std::sin(t), -std::sin(t), std::cos(t)); }

// The P-NDF's second moments about the mean over an s-grid.
glm::dvec3 moments(const map_t& m, const placement& pl, const glint::texel_footprint<float>& fp) {
    double w = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
    const int g = 96;
    for (int y = 0; y < g; ++y)
        for (int x = 0; x < g; ++x) {
            const glm::vec2 s(-0.9f + 1.8f * (static_cast<float>(x) + 0.5f) / g, -0.9f + 1.8f * (static_cast<float>(y) + 0.5f) / g);
            const double d = m.eval(pl, fp, s);
            const glm::dvec2 t(s);
            w += d, mx += d * t.x, my += d * t.y, xx += d * t.x * t.x, yy += d * t.y * t.y, xy += d * t.x * t.y;
        }
    mx /= w, my /= w;
    return {xx / w - mx * mx, yy / w - my * my, xy / w - mx * my};
}

}  // namespace

TEST_CASE("ndf_map: the builder rejects bad input, naming it") {
    glint::ndf_map_params mp;
    CHECK_THROWS_WITH_AS(map_t::build(glint::make_normal_map(glint_test::example_pattern(glint::pattern::noise, 12)), mp), doctest::Contains("power of two"),
                         glint::error);
    glint::pattern_params rect = glint_test::example_pattern(glint::pattern::noise, 16);
    rect.height = 8;
    CHECK_THROWS_WITH_AS(map_t::build(glint::make_normal_map(rect), mp), doctest::Contains("square"), glint::error);
    CHECK_THROWS_WITH_AS(map_t::build(glint::normal_map(2, 2, std::vector<glm::vec3>(4, glm::vec3(0, 0, 1))), mp), doctest::Contains("[4, 256]"),
                         glint::error);
    glint::pattern_params ramp = glint_test::example_pattern(glint::pattern::ramp, 16);
    CHECK_THROWS_WITH_AS(map_t::build(glint::make_normal_map(ramp), mp), doctest::Contains("periodic"), glint::error);
    const auto ex = example(glint::pattern::noise, 16);
    const auto bad = [&](auto set, const char* what) {
        glint::ndf_map_params q;
        set(q);
        CHECK_THROWS_WITH_AS(map_t::build(ex, q), doctest::Contains(what), glint::error);
    };
    bad([](glint::ndf_map_params& q) { q.resolution = 4; }, "resolution");
    bad([](glint::ndf_map_params& q) { q.sigma_r = 0; }, "sigma_r");
    bad([](glint::ndf_map_params& q) { q.sigma_r = std::nan(""); }, "sigma_r");
    bad([](glint::ndf_map_params& q) { q.tau = 0; }, "tau");
    bad([](glint::ndf_map_params& q) { q.cull = 1; }, "cull");
    bad([](glint::ndf_map_params& q) { q.max_tiles = 2; }, "max_tiles");
    bad([](glint::ndf_map_params& q) { q.direct_below = 0; }, "direct_below");
    bad([](glint::ndf_map_params& q) { q.blend = 0; }, "blend");
    bad([](glint::ndf_map_params& q) { q.elements_per_texel = 3; }, "elements_per_texel");
    CHECK_THROWS_WITH_AS(placement::tiled(glm::mat2(1, 2, 2, 4)), doctest::Contains("singular"), glint::error);
    CHECK_THROWS_WITH_AS(placement::tiled(glm::mat2(1), glm::vec2(std::nanf(""), 0)), doctest::Contains("origin"), glint::error);
    CHECK_THROWS_WITH_AS(placement::stochastic(0.5f, 1), doctest::Contains("cell"), glint::error);
    CHECK_THROWS_WITH_AS(placement::stochastic(16.0f, 1, glm::vec2(0, 1), glm::vec2(2, 1)), doctest::Contains("scale"), glint::error);
    CHECK_THROWS_WITH_AS(placement::stochastic(16.0f, 1, glm::vec2(0, 1), glm::vec2(1), 1.5f), doctest::Contains("flip"), glint::error);
}

TEST_CASE("ndf_map: layout, parent = mean of children, moments, tile masses, build progress") {
    glint::ndf_map_params mp;
    mp.sigma_r = 0.01, mp.resolution = 32;
    int calls = 0, last = 0;
    int totals = 0;
    mp.progress = [&](int done, int total) {
        ++calls, last = done;
        totals += total == 64;
    };
    const auto m = map_t::build(example(glint::pattern::leather, 16), mp);
    CHECK(calls == 64);
    CHECK(totals == 64);
    CHECK(last == 64);
    CHECK(m.levels() == 4);
    CHECK(m.layers() == 64 + 16 + 4 + 1);
    CHECK(m.layer(3, 0, 0) == 84);
    CHECK(m.images().size() == 4u * 85u * 32u * 32u);
    double worst_mean = 0, worst_moment = 0, peak = 0;
    for (int l = 1; l < m.levels(); ++l)
        for (int ty = 0; ty < (16 >> (l + 1)); ++ty)
            for (int tx = 0; tx < (16 >> (l + 1)); ++tx)
                for (int y = 0; y < 32; ++y)
                    for (int x = 0; x < 32; ++x) {
                        double mean = 0, mx = 0;
                        for (int q = 0; q < 4; ++q) {
                            const double c = m.bin(l - 1, 2 * tx + (q & 1), 2 * ty + (q >> 1), x, y);
                            mean += 0.25 * c;
                            mx += 0.25 * (0.5 * static_cast<double>(m.bin(l - 1, 2 * tx + (q & 1), 2 * ty + (q >> 1), x, y, 1)) + ((q & 1) ? 0.25 : -0.25) * c);
                        }
                        peak = std::max(peak, mean);
                        worst_mean = std::max(worst_mean, std::fabs(static_cast<double>(m.bin(l, tx, ty, x, y)) - mean));
                        worst_moment = std::max(worst_moment, std::fabs(static_cast<double>(m.bin(l, tx, ty, x, y, 1)) - mx));
                    }
    MESSAGE("parent - mean of children: " << worst_mean / peak << " of the peak; x moment " << worst_moment / peak);
    CHECK(worst_mean <= 1e-6 * peak);
    CHECK(worst_moment <= 1e-6 * peak);
    // Every tile's NDF integrates to 1 but for the lobes' tails outside the fitted window (4.5 sd).
    double lo = 2, hi = 0;
    for (int layer = 0; layer < m.layers(); ++layer) {
        const double mass = m.images()[4 * (static_cast<std::size_t>(layer) * m.bins() + m.bins() - 1) + 3];
        lo = std::min(lo, mass), hi = std::max(hi, mass);
    }
    MESSAGE("tile masses in [" << lo << ", " << hi << "]");
    CHECK(lo > 1 - 1e-4);
    CHECK(hi < 1 + 1e-4);
}

TEST_CASE("ndf_map: the element path of a tiled identity layout is the example's direct P-NDF") {
    const auto m = small_map(glint::pattern::noise);
    const auto pl = placement::tiled();
    double worst = 0;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const float a = std::exp2(-2 + 5 * rnd(i, 1));
        const auto fp = fp_at({100 * rnd(i, 2) - 50, 100 * rnd(i, 3) - 50}, a, a * (0.3f + 0.7f * rnd(i, 4)), 3 * rnd(i, 5));
        const glm::vec2 s(0.5f * rnd(i, 6) - 0.25f, 0.5f * rnd(i, 7) - 0.25f);
        const double ref = m.elements().eval_direct(fp, s), got = m.eval_direct(pl, fp, s);
        worst = std::max(worst, std::fabs(got - ref) / std::max(ref, 1e-3));
    }
    MESSAGE("largest relative difference " << worst);
    CHECK(worst < 1e-5);
}

TEST_CASE("ndf_map: L1 against the direct P-NDF of the same tiled example at the map's resolution, five examples") {
    // 32^2 examples, sigma_r = 0.02, 64^2 bins, tau = 1, up to 256 tiles. Reference: the example's
    // direct P-NDF (glint::gaussian_pndf with its hierarchy; the same elements and culling), each
    // bin's mean from 3 x 3 sub-samples (spacing 0.4 sigma_r); the map at the bin centres (its stored bin mixture). The
    // issue's target: at most 5% from a footprint sd of 4 texels, falling with the footprint.
    for (const auto kind : glint_test::example_kinds) {
        const auto ex = example(kind, 32);
        glint::ndf_map_params mp;
        mp.sigma_r = 0.02, mp.resolution = 64;
        const auto m = map_t::build(ex, mp);
        glint::gaussian_params<float> g;
        g.sigma_r = 0.02f;
        const auto ref = glint::gaussian_pndf<float>::build(ex, g);
        const auto pl = placement::tiled();
        std::string row;
        std::vector<double> l1s;
        for (const float sd : {4.0f, 8.0f, 64.0f, 512.0f}) {
            const auto fp = fp_at({13.3f, 7.7f}, sd, 0.7f * sd, 0.4f);
            const double l1 = glint_test::binned_l1(
                m, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, fp, s)); }, [&](glm::vec2 s) { return static_cast<double>(ref.eval(fp, s)); }, 3);
            row += " sd " + std::to_string(static_cast<int>(sd)) + ": " + std::to_string(l1);
            CHECK(l1 <= 0.05);
            l1s.push_back(l1);
        }
        // Falling with the footprint: from the small ones (tiles of about the footprint's sd) to the
        // wide ones (coarse levels, then the top image, exact but for its bins).
        CHECK(l1s[2] < std::max(l1s[0], l1s[1]));
        CHECK(l1s[3] <= l1s[2] * 1.0001);
        MESSAGE(std::string(glint::pattern_name(kind)) << ":" << row);
    }
}

TEST_CASE("ndf_map: transforms keep the mass, rotate the NDF, and stretch grooves across their axis") {
    const auto m = small_map(glint::pattern::brushed, 16, 0.01, 64);
    const auto fp = fp_at({5.3f, 9.1f}, 6, 4, 0.3f);
    // Mass under every kind of map (its integral over s by quadrature, and mass()).
    const glm::mat2 maps[] = {glm::mat2(1), rotation(0.7f), glm::mat2(2, 0, 0, 2), glm::mat2(1.5f, 0, 0, 0.6f), glm::mat2(1, 0, 0.5f, 1),
                              glm::mat2(1, 0, 0, -1), rotation(2.1f) * glm::mat2(1.3f, 0.2f, -0.4f, 0.8f)};
    for (const auto& a : maps) {
        const auto pl = placement::tiled(a);
        double integral = 0;
        const int g = 400;
        const double ds = 2.0 / g;
        for (int y = 0; y < g; ++y)
            for (int x = 0; x < g; ++x) integral += static_cast<double>(m.eval(pl, fp, glm::vec2(-1 + (x + 0.5) * ds, -1 + (y + 0.5) * ds))) * ds * ds;
        CHECK(std::fabs(integral - 1) < 2e-3);
        CHECK(std::fabs(m.mass(pl, fp) - 1) < 1e-4);
    }
    // Rotating the layout by theta and the footprint with it rotates the P-NDF: D'(R s) = D(s).
    const float theta = 0.9f;
    const glm::mat2 R = rotation(theta);
    glint::texel_footprint<float> rf;
    rf.center = R * fp.center, rf.covariance = R * fp.covariance * glm::transpose(R);
    double worst = 0;
    for (std::uint32_t i = 0; i < 400; ++i) {
        const glm::vec2 s(0.6f * rnd(i, 11) - 0.3f, 0.6f * rnd(i, 12) - 0.3f);
        const double a = m.eval(placement::tiled(), fp, s), b = m.eval(placement::tiled(R), rf, R * s);
        worst = std::max(worst, std::fabs(a - b) / std::max(a, 1e-2));
    }
    MESSAGE("rotation: largest relative difference " << worst);
    CHECK(worst < 1e-4);
    // A pure scale of layout and footprint changes nothing (heights scale with the example).
    glint::texel_footprint<float> sf;
    sf.center = 2.0f * fp.center, sf.covariance = 4.0f * fp.covariance;
    worst = 0;
    for (std::uint32_t i = 0; i < 200; ++i) {
        const glm::vec2 s(0.6f * rnd(i, 13) - 0.3f, 0.6f * rnd(i, 14) - 0.3f);
        const double a = m.eval(placement::tiled(), fp, s), b = m.eval(placement::tiled(glm::mat2(2)), sf, s);
        worst = std::max(worst, std::fabs(a - b) / std::max(a, 1e-2));
    }
    CHECK(worst < 1e-4);
    // brushed: grooves along x (heights vary along y), so normals spread along y. Rotated by 90
    // degrees the spread must move to x: a transform that swapped u and v would fail one of these.
    const auto wide = fp_at({3.0f, 3.0f}, 40, 40, 0);
    const glm::dvec3 v0 = moments(m, placement::tiled(), wide), v90 = moments(m, placement::tiled(rotation(1.5707963f)), wide);
    MESSAGE("brushed: var s_x " << v0.x << ", var s_y " << v0.y << "; rotated 90 degrees: " << v90.x << ", " << v90.y);
    CHECK(v0.y > 4 * v0.x);
    CHECK(v90.x > 4 * v90.y);
    // A shear y += 0.8 x tilts the grooves, and with them the spread of normals: s_x and s_y correlate.
    const glm::dvec3 vs = moments(m, placement::tiled(glm::mat2(1, 0.8f, 0, 1)), wide);
    CHECK(std::fabs(vs.z) > 0.2 * std::sqrt(vs.x * vs.y));
}

TEST_CASE("ndf_map: continuous as the footprint grows by 1% and moves across tile and example seams") {
    const auto m = small_map(glint::pattern::noise, 32, 0.02, 64);
    const auto pl = placement::tiled();
    const glm::dvec2 worst = glint_test::largest_growth_step(m, pl, {9.3f, 20.6f}, 0.7f, 0.3f, 0.5f, 600, 16);
    MESSAGE("footprint growing by 1%: largest L1 step " << worst.x << " (at sd " << worst.y << ")");
    CHECK(worst.x <= 0.02);
    // Across the tile seams at x = 8, 16 and the example's seam at x = 32, in steps of 1/32 texel.
    for (const float sd : {2.5f, 5.0f, 12.0f}) {
        const double move = glint_test::largest_move_step(m, pl, sd, 6, 34, 11.2f, 16);
        MESSAGE("moving by 1/32 texel at sd " << sd << ": largest L1 step " << move);
        CHECK(move <= 0.01);
    }
}

TEST_CASE("ndf_map: a tiled layout is periodic") {
    const auto m = small_map(glint::pattern::flakes);
    const auto pl = placement::tiled(rotation(0.4f) * glm::mat2(1.2f, 0, 0, 0.9f), glm::vec2(3.5f, -2));
    const glm::mat2 a = rotation(0.4f) * glm::mat2(1.2f, 0, 0, 0.9f);
    double worst = 0;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const auto fp = fp_at({10 * rnd(i, 1), 10 * rnd(i, 2)}, 0.5f + 8 * rnd(i, 3), 0.5f + 4 * rnd(i, 4), rnd(i, 5));
        auto moved = fp;
        moved.center += a * glm::vec2(16.0f * static_cast<float>(static_cast<int>(6 * rnd(i, 6)) - 3), 16.0f * static_cast<float>(static_cast<int>(6 * rnd(i, 7)) - 3));
        const glm::vec2 s(0.4f * rnd(i, 8) - 0.2f, 0.4f * rnd(i, 9) - 0.2f);
        const double x = m.eval(pl, fp, s), y = m.eval(pl, moved, s);
        worst = std::max(worst, std::fabs(x - y) / std::max(x, 1e-2));
    }
    MESSAGE("largest relative difference one to three periods away: " << worst);
    CHECK(worst < 1e-3);
}

TEST_CASE("ndf_map: stochastic ownership gives every point one owner, its nearest anchor") {
    const auto pl = placement::stochastic(24.0f, 11u);
    double reach = 0;
    int mismatched = 0;
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const glm::vec2 x(2000 * rnd(i, 1) - 1000, 2000 * rnd(i, 2) - 1000);
        const glm::ivec2 o = pl.owner(x);
        // Brute force over 7 x 7 cells: the owner's anchor is the nearest.
        const glm::ivec2 c(static_cast<int>(std::floor(x.x / 24)), static_cast<int>(std::floor(x.y / 24)));
        double best = 1e30;
        glm::ivec2 arg(0);
        for (int j = -3; j <= 3; ++j)
            for (int k = -3; k <= 3; ++k) {
                const glm::vec2 p = glint::detail::glsl::kernels<float>::glint_ndf_cell_anchor(pl.k, c + glm::ivec2(k, j));
                const double d = glm::dot(x - p, x - p);
                if (d < best) best = d, arg = c + glm::ivec2(k, j);
            }
        mismatched += arg != o;
        reach = std::max(reach, std::sqrt(best) / 24);
    }
    MESSAGE("owner = nearest anchor of 7 x 7 cells; farthest owned point " << reach << " cells from its anchor");
    CHECK(mismatched == 0);
    CHECK(reach <= 1.061);
}

TEST_CASE("ndf_map: a stochastic layout keeps the footprint's mass and tracks its element path") {
    const auto m = small_map(glint::pattern::noise, 16, 0.02, 64);
    const auto pl = placement::stochastic(20.0f, 5u, glm::vec2(0, 6.2831853f), glm::vec2(0.8f, 1.25f), 0.5f);
    double lo = 2, hi = 0;
    for (std::uint32_t i = 0; i < 200; ++i) {
        const float sd = std::exp2(1 + 8 * rnd(i, 3));
        const double mass = m.mass(pl, fp_at({500 * rnd(i, 1), 500 * rnd(i, 2)}, sd, sd * (0.2f + 0.8f * rnd(i, 4)), rnd(i, 5)));
        lo = std::min(lo, mass), hi = std::max(hi, mass);
    }
    MESSAGE("mass over sd 2 to 512: [" << lo << ", " << hi << "]");
    CHECK(lo > 0.999);
    CHECK(hi < 1.001);
    // Against the element path at the map's resolution (sigma_r = 0.04 so that 3 x 3 sub-samples
    // resolve the reference's bin means: spacing 0.33 sigma_r).
    const auto wide = small_map(glint::pattern::noise, 16, 0.04, 32);
    for (const float sd : {3.0f, 6.0f}) {
        double l1 = 0;
        const int count = 2;
        for (std::uint32_t i = 0; i < count; ++i) {
            const auto fp = fp_at({300 * rnd(i, 7), 300 * rnd(i, 8)}, sd, sd * 0.8f, rnd(i, 9));
            l1 += glint_test::binned_l1(
                      wide, [&](glm::vec2 s) { return static_cast<double>(wide.eval(pl, fp, s)); },
                      [&](glm::vec2 s) { return static_cast<double>(wide.eval_direct(pl, fp, s)); }, 3) /
                  count;
        }
        MESSAGE("stochastic, sd " << sd << ": mean L1 against its element path " << l1);
        // Tiles are owned by their centres, the element path by each element: a bound that a
        // working layout keeps and a broken one does not (below: another seed's copies).
        CHECK(l1 < 0.1);
    }
    const auto other = placement::stochastic(20.0f, 6u, glm::vec2(0, 6.2831853f), glm::vec2(0.8f, 1.25f), 0.5f);
    const auto fp = fp_at({300 * rnd(0, 7), 300 * rnd(0, 8)}, 3, 2.4f, rnd(0, 9));
    const double wrong = glint_test::binned_l1(
        wide, [&](glm::vec2 s) { return static_cast<double>(wide.eval(other, fp, s)); },
        [&](glm::vec2 s) { return static_cast<double>(wide.eval_direct(pl, fp, s)); }, 3);
    MESSAGE("another seed's copies against this layout's element path: L1 " << wrong);
    CHECK(wrong > 0.3);
}

TEST_CASE("ndf_map: BRDF and the coated variant (Eq. 1, Eq. 10)") {
    const auto m = small_map(glint::pattern::leather);
    const auto coat = small_map(glint::pattern::scratches);
    const auto pl = placement::tiled();
    const auto fp = fp_at({4.4f, 2.2f}, 3, 2, 0.2f);
    const glm::vec3 wi = glm::normalize(glm::vec3(0.2f, 0.1f, 1)), wo = glm::normalize(glm::vec3(-0.15f, -0.05f, 1));
    const float base = m.brdf(pl, fp, wi, wo, 0.2f, 3.0f);
    CHECK(base > 0);
    CHECK(m.brdf(pl, fp, glm::vec3(0, 0.5f, -0.8f), wo, 0.2f, 3.0f) == 0);
    // A coat of index 1 reflects nothing and transmits everything: the base alone.
    CHECK(m.coated_brdf(pl, coat, pl, fp, wi, wo, 0.2f, 3.0f, 1.0f) == doctest::Approx(base).epsilon(1e-6));
    // Index 1.5: the base times (1 - F_c) plus the coat's own lobe.
    const glm::vec3 h = glm::normalize(wi + wo);
    const float fc = glint::detail::glsl::kernels<float>::glint_fresnel_conductor(1.5f, 0.0f, glm::dot(wi, h));
    const float c = coat.brdf(pl, fp, wi, wo, 1.5f, 0.0f);
    CHECK(m.coated_brdf(pl, coat, pl, fp, wi, wo, 0.2f, 3.0f, 1.5f) == doctest::Approx(base * (1 - fc) + c).epsilon(1e-5));
}

TEST_CASE("ndf_map: float hard cases stay finite and non-negative") {
    glint::ndf_map_params mp;
    mp.sigma_r = 1e-4, mp.resolution = 32;
    const auto sharp = map_t::build(example(glint::pattern::flakes, 8), mp);
    const auto m = small_map(glint::pattern::brushed);
    const placement layouts[] = {placement::tiled(), placement::tiled(glm::mat2(0.3f, 0.1f, -2, 0.5f), glm::vec2(1e5f, -3e4f)),
                                 placement::stochastic(12.0f, 3u, glm::vec2(0, 6.3f), glm::vec2(0.5f, 2))};
    std::size_t bad = 0, positive = 0, total = 0;
    for (int which = 0; which < 2; ++which) {
        const map_t& map = which == 0 ? m : sharp;
        for (int li = 0; li < 3; ++li) {
            const int count = li == 2 ? 3000 : 20000;
            for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(count); ++i) {
                // Footprints from 1e-4 to 1e6 texels, anisotropy up to 1e4, centres up to 1e6 away.
                const float a = std::exp2(-13 + 33 * rnd(i, 1)), b = a * std::exp2(-13 * rnd(i, 2));
                const auto fp = fp_at({2e6f * rnd(i, 3) - 1e6f, 2e6f * rnd(i, 4) - 1e6f}, a, b, 6.3f * rnd(i, 5));
                // s up to the disk's edge (grazing half vectors).
                const float r = std::sqrt(rnd(i, 6)) * (i % 7 == 0 ? 0.9999999f : 1.0f), t = 6.3f * rnd(i, 7);
                const float v = map.eval(layouts[li], fp, glm::vec2(r * std::cos(t), r * std::sin(t)));
                bad += !(std::isfinite(v) && v >= 0), positive += v > 0, ++total;
            }
        }
    }
    MESSAGE(total << " queries, " << positive << " positive, " << bad << " not finite or negative");
    CHECK(bad == 0u);
    CHECK(positive > total / 50);
    // Outside the disk and at non-finite s: 0.
    const auto fp = fp_at({1, 1}, 2, 2, 0);
    CHECK(m.eval(layouts[0], fp, glm::vec2(1, 0)) == 0);
    CHECK(m.eval(layouts[0], fp, glm::vec2(std::nanf(""), 0)) == 0);
    // Non-finite footprints: finite results.
    glint::texel_footprint<float> nf;
    nf.center = {std::nanf(""), 1}, nf.covariance = glm::mat2(std::numeric_limits<float>::infinity());
    CHECK(std::isfinite(m.eval(layouts[0], nf, glm::vec2(0.01f, 0))));
    // The tile cap: a wide thin footprint at a small cap reads at most the cap per level.
    glint::ndf_map_params capped;
    capped.sigma_r = 0.02, capped.resolution = 32, capped.max_tiles = 16;
    const auto c = map_t::build(example(glint::pattern::noise, 64), capped);
    int at_cap = 0;
    for (const float sd : {1.5f, 3.0f, 7.0f, 20.0f}) {
        const auto cost = c.evaluation_cost(layouts[0], fp_at({7, 9}, 16 * sd, sd, 0.5f));
        MESSAGE("sd " << sd << " x " << 16 * sd << ": " << cost.tiles << " tiles (cap 16 per level)");
        CHECK(cost.tiles <= 32);
        CHECK(cost.tiles >= 1);
        at_cap += cost.tiles >= 16;
    }
    CHECK(at_cap >= 1);
}
