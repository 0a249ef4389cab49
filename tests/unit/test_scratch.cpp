// Scratched materials (glint/scratch.hpp, kernels/scratch.glsl) without statistics: the cone
// parametrization's round trip and frame, profiles and their bad input, the table's exact cases
// (flat profile, furnace), Eq. 2 at its fitted angles, the sampler's zero-variance mirror case,
// the light cull, the layer mix of Eq. 4, the scratch indicator and float hard cases.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glint/scratch.hpp>

#include "../support/errors.hpp"

namespace {

template <class real>
using K = glint::detail::glsl::kernels<real>;

const double pi = 3.14159265358979323846;
const double deg = pi / 180;

double rnd(std::uint32_t i, std::uint32_t salt) { return (glint::pcg3d(glm::uvec3(i, salt, 0x5c1u)).x + 0.5) * 2.3283064365386962890625e-10; }

glm::dvec3 random_unit(std::uint32_t i, std::uint32_t salt) {
    const double z = 2 * rnd(i, salt) - 1, a = 2 * pi * rnd(i, salt + 1), r = std::sqrt(1 - z * z);
    return {r * std::cos(a), r * std::sin(a), z};
}

// Largest component error of from_cone(to_cone(w)) against w, in units of the precision's epsilon.
template <class real>
double round_trip_error_in_eps(std::size_t count) {
    using v3 = glm::vec<3, real, glm::defaultp>;
    double worst = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const auto f = glint::make_scratch_frame<real>(v3(random_unit(i, 1)), v3(random_unit(i, 3)));
        glm::dvec3 wd = random_unit(i, 5);
        // A quarter of the cases at the hard places: near the poles w = +-u, and near the horizon.
        const int kind = static_cast<int>(i % 8);
        const glm::dvec3 n(f.n), u(f.u), v(f.v);
        if (kind == 0) wd = glm::normalize((rnd(i, 7) < 0.5 ? 1.0 : -1.0) * u + 1e-4 * rnd(i, 8) * v + 1e-4 * rnd(i, 9) * n);
        if (kind == 1) wd = glm::normalize(wd - glm::dot(wd, n) * n + 1e-7 * n);
        const v3 w(wd);
        const v3 back = glint::from_cone<real>(f, glint::to_cone<real>(f, w));
        const glm::dvec3 wr(w), br(back);
        const double e = std::max({std::fabs(wr.x - br.x), std::fabs(wr.y - br.y), std::fabs(wr.z - br.z)});
        worst = std::max(worst, e / static_cast<double>(std::numeric_limits<real>::epsilon()));
    }
    return worst;
}

glint::scratch_table small_table(const glint::scratch_profile& p, const glint::scratch_fresnel& f, int M = 32, int N = 4000, bool sym = true) {
    glint::scratch_table_options o;
    o.resolution = M, o.rays_per_row = N, o.symmetrize = sym;
    return glint::build_scratch_table(p, f, o);
}

}  // namespace

TEST_CASE("scratch cone: round trip over the whole sphere within a few ulp, float and double") {
    // 100,000 directions each, a quarter near the poles and the horizon. Measured worst: 2.75 eps
    // in both precisions (atan2's 2.6 ulp, then sin and cos of the angles and the frame's dot
    // products); the bound is the notes' 4 ulp.
    const double ef = round_trip_error_in_eps<float>(100000), ed = round_trip_error_in_eps<double>(100000);
    MESSAGE("round trip: worst component error " << ef << " float eps, " << ed << " double eps");
    CHECK(ef < 4);
    CHECK(ed < 4);
}

TEST_CASE("scratch cone: |phi| <= pi/2 exactly where w.n >= 0, theta = asin(w.u)") {
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const auto f = glint::make_scratch_frame<double>(random_unit(i, 11), random_unit(i, 13));
        const glm::dvec3 w = random_unit(i, 15);
        const glm::dvec2 c = glint::to_cone<double>(f, w);
        CHECK((std::fabs(c.y) <= pi / 2) == (glm::dot(w, f.n) >= 0));
        CHECK(std::fabs(c.x - std::asin(glm::dot(w, f.u))) < 1e-12);
    }
}

TEST_CASE("scratch frame: orthonormal to 1e-6 in float for a tangent along n, zero, non-unit or not finite") {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
    const glm::vec3 tangents[] = {n, -n, 3.0f * n, glm::vec3(0), glm::vec3(inf, 0, 0), glm::vec3(nan), n + glm::vec3(1e-7f, 0, 0), glm::vec3(5, 0.1f, -2)};
    const glm::vec3 normals[] = {n, 7.0f * n, glm::vec3(0, 0, -1), glm::vec3(0)};
    for (const auto& nn : normals)
        for (const auto& t : tangents) {
            const auto f = glint::make_scratch_frame<float>(nn, t);
            CHECK(std::fabs(glm::length(f.n) - 1) < 1e-6f);
            CHECK(std::fabs(glm::length(f.u) - 1) < 1e-6f);
            CHECK(std::fabs(glm::length(f.v) - 1) < 1e-6f);
            CHECK(std::fabs(glm::dot(f.n, f.u)) < 1e-6f);
            CHECK(std::fabs(glm::dot(f.n, f.v)) < 1e-6f);
            CHECK(std::fabs(glm::dot(f.u, f.v)) < 1e-6f);
        }
    // A good tangent is kept (made orthogonal to n).
    const auto f = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 2), glm::dvec3(1, 0, 0.5));
    CHECK(f.u.x == doctest::Approx(1).epsilon(1e-15));
    CHECK(f.v.y == doctest::Approx(1).epsilon(1e-15));
}

TEST_CASE("scratch profiles: makers, tabulated profiles with bulges, and bad input named") {
    using glint_test::contains;
    using glint_test::error_of;
    const auto v = glint::make_v_groove(30 * deg);
    CHECK(v.symmetric);
    CHECK(v.h[1] == doctest::Approx(-0.5 * std::tan(30 * deg)));
    const auto q = glint::make_quartic_groove(0.5, 64);
    CHECK(q.x.size() == 65u);
    CHECK(q.h[32] == doctest::Approx(-0.5));
    CHECK(q.symmetric);
    const auto r = glint::make_ramp_profile(20 * deg);
    CHECK_FALSE(r.symmetric);
    CHECK_FALSE(r.periodic);
    // Bulges: the highest point becomes the base, the profile periodic.
    const auto b = glint::make_tabulated_profile({0, 1, 2, 3, 4}, {0.1, -0.2, -0.5, -0.2, 0.1});
    CHECK(b.periodic);
    CHECK(b.symmetric);
    CHECK(b.h.front() == 0);
    CHECK(b.h[2] == doctest::Approx(-0.15));  // (-0.5 - 0.1) / width 4
    CHECK(contains(error_of([] { glint::make_v_groove(0.5 * deg); }), "facet_angle"));
    CHECK(contains(error_of([] { glint::make_quartic_groove(2); }), "depth_over_width = 2"));
    CHECK(contains(error_of([] { glint::make_quartic_groove(0.5, 1); }), "segments = 1"));
    CHECK(contains(error_of([] { glint::make_tabulated_profile({0, 1, 1}, {0, -1, 0}); }), "not strictly increasing at point 2"));
    CHECK(contains(error_of([] { glint::make_tabulated_profile({0, 1}, {0}); }), "as many heights"));
    CHECK(contains(error_of([] { glint::make_tabulated_profile({0, 1, 2}, {0, std::nan(""), 0}); }), "point 1 is not finite"));
    CHECK(contains(error_of([] { glint::make_tabulated_profile({0, 1, 2}, {-0.1, -1, 0}); }), "starts and ends on the base"));
    CHECK(contains(error_of([] { glint::make_tabulated_profile({0, 1, 2}, {0.1, -1, 0}); }), "ends where it starts"));
    glint::scratch_profile bad = glint::make_v_groove(30 * deg);
    bad.h[1] = 0.2;
    CHECK(contains(error_of([&] { glint::build_scratch_table(bad, {}); }), "h = 0.2 > 0 at point 1"));
    glint::scratch_table_options o;
    o.resolution = 4;
    CHECK(contains(error_of([&] { glint::build_scratch_table(v, {}, o); }), "resolution = 4"));
    o = {};
    o.rays_per_row = 3;
    CHECK(contains(error_of([&] { glint::build_scratch_table(v, {}, o); }), "rays_per_row = 3"));
    o = {};
    o.max_bounces = 0;
    CHECK(contains(error_of([&] { glint::build_scratch_table(v, {}, o); }), "max_bounces = 0"));
    glint::scratch_fresnel f = glint::scratch_fresnel::iron();
    f.k.y = -1;
    CHECK(contains(error_of([&] { glint::build_scratch_table(v, f); }), "Fresnel k = -1"));
    f = glint::scratch_fresnel::schlick(glm::dvec3(1.5));
    CHECK(contains(error_of([&] { glint::build_scratch_table(v, f); }), "Schlick f0 = 1.5"));
    f = glint::scratch_fresnel::plastic();
    f.eta.z = 0;
    CHECK(contains(error_of([&] { glint::build_scratch_table(v, f); }), "Fresnel eta = 0"));
}

TEST_CASE("scratch table: the flat profile is the mirror's anti-diagonal, exactly") {
    const int M = 32;
    const auto t = small_table(glint::make_flat_profile(), glint::scratch_fresnel::schlick(glm::dvec3(0.04, 0.5, 0.9)), M, 2000);
    for (int o = 0; o < M; ++o)
        for (int i = 0; i < M; ++i) {
            const std::size_t b = static_cast<std::size_t>(o * M + i);
            const double expect = i == M - 1 - o ? 1 / glint::scratch_table::bin_ds(i, M) : 0;
            CHECK(t.rho_m()[b] == doctest::Approx(expect).epsilon(1e-12));
        }
    CHECK(t.lost_fraction() == 0);
    CHECK(t.max_bounces_seen() == 1);
}

TEST_CASE("scratch table: raw rows are 1 - lost exactly (furnace), Fresnel rows at most that, for any thread count") {
    const int M = 48;
    const glint::scratch_profile profiles[] = {glint::make_v_groove(60 * deg), glint::make_quartic_groove(1.0, 256),
                                               glint::make_tabulated_profile({0, 1, 2, 3, 4, 5, 6}, {0.05, -0.3, -0.6, -0.4, -0.5, -0.1, 0.05})};
    for (const auto& p : profiles) {
        glint::scratch_table_options o;
        o.resolution = M, o.rays_per_row = 3000, o.symmetrize = false, o.max_bounces = 8;
        o.threads = 1;
        const auto t1 = glint::build_scratch_table(p, glint::scratch_fresnel::iron(), o);
        o.threads = 3;
        const auto t3 = glint::build_scratch_table(p, glint::scratch_fresnel::iron(), o);
        CHECK(t1.rho_m() == t3.rho_m());
        CHECK(t1.gamma(0) == t3.gamma(0));
        CHECK(t1.data<float>().size() == t3.data<float>().size());
        double lost_max = 0;
        for (int i = 0; i < M; ++i) {
            double sum = 0, sum0 = 0;
            for (int o2 = 0; o2 < M; ++o2) {
                const std::size_t b = static_cast<std::size_t>(o2 * M + i);
                sum += t1.rho_m()[b] * glint::scratch_table::bin_ds(o2, M);
                sum0 += t1.rho_0(0)[b] * glint::scratch_table::bin_ds(o2, M);
            }
            const double lost = t1.lost_fraction_per_row()[static_cast<std::size_t>(i)];
            lost_max = std::max(lost_max, lost);
            CHECK(sum == doctest::Approx(1 - lost).epsilon(1e-12));
            CHECK(sum0 <= sum * (1 + 1e-12));
        }
        MESSAGE("furnace: worst lost fraction at 8 bounces " << lost_max);
    }
}

TEST_CASE("scratch Eq. 2: exact at theta = 0, pi/3 (unclamped bins) and pi/2, even in theta") {
    const int M = 32;
    const auto t = small_table(glint::make_quartic_groove(0.5, 256), glint::scratch_fresnel::schlick(glm::dvec3(0.04, 0.3, 0.8)), M, 4000);
    const auto v = t.view<double>();
    auto nearest = v;
    nearest.filter = glint::scratch_filter::nearest;
    int checked = 0;
    for (int o = 0; o < M; ++o)
        for (int i = 0; i < M; ++i) {
            const std::size_t b = static_cast<std::size_t>(o * M + i);
            const double po = -pi / 2 + (o + 0.5) * pi / M, pi_ = -pi / 2 + (i + 0.5) * pi / M;
            const glm::dvec3 r0 = nearest.rho(0.0, po, pi_), r90 = nearest.rho(pi / 2, po, pi_), r60 = nearest.rho(pi / 3, po, pi_);
            const glm::dvec3 r60n = nearest.rho(-pi / 3, po, pi_);
            for (int c = 0; c < 3; ++c) {
                CHECK(r0[c] == doctest::Approx(t.rho_0(c)[b]).epsilon(1e-13));
                CHECK(r90[c] == doctest::Approx(t.rho_m()[b]).epsilon(1e-13));
                CHECK(r60[c] == r60n[c]);
                const double rm = t.rho_m()[b], rz = t.rho_0(c)[b], rs = t.rho_60(c)[b];
                const double r = rm - rz > 1e-6 * rm ? (rs - rz) / (rm - rz) : 0;
                if (r > 1e-4 && r < 1 - 1e-4) {
                    CHECK(r60[c] == doctest::Approx(rs).epsilon(1e-10));
                    ++checked;
                }
            }
        }
    MESSAGE(checked << " unclamped bins checked at theta = pi/3");
    CHECK(checked > M * M);
}

TEST_CASE("scratch sampling: with F = 1 in nearest mode every weight is the row albedo (zero variance)") {
    const int M = 32;
    const auto t = small_table(glint::make_quartic_groove(0.3, 128), glint::scratch_fresnel::mirror(), M, 4000);
    auto v = t.view<float>();
    v.filter = glint::scratch_filter::nearest;
    const auto f = glint::make_scratch_frame<float>(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    std::size_t valid = 0;
    for (std::uint32_t k = 0; k < 5000; ++k) {
        glm::dvec3 wd = random_unit(k, 21);
        wd.z = std::fabs(wd.z);
        const glm::vec3 wo(wd);
        const auto s = v.sample(f, wo, static_cast<float>(rnd(k, 23)), static_cast<float>(rnd(k, 24)));
        if (!s.valid) continue;
        ++valid;
        const glm::vec2 co = glint::to_cone<float>(f, wo);
        const float A = static_cast<float>(t.row_albedo()[static_cast<std::size_t>(K<float>::glint_scratch_bin(co.y, M))]);
        CHECK(s.weight.x == doctest::Approx(A).epsilon(1e-6));
        CHECK(s.weight.z == doctest::Approx(A).epsilon(1e-6));
        // On the reflection cone, above the horizon.
        const glm::vec2 ci = glint::to_cone<float>(f, s.wi);
        CHECK(std::fabs(ci.x + co.x) < 2e-6f);
        CHECK(s.wi.z >= 0);
        CHECK(s.pdf_phi == doctest::Approx(v.pdf_phi(co.y, s.phi_i)).epsilon(1e-5));
    }
    CHECK(valid == 5000u);
}

TEST_CASE("scratch light: a culled pair returns 0 without reading the table") {
    // A table of NaN beyond its resolution: any read would make the result NaN.
    std::vector<glm::vec4> poison(1 + 8 + 2 * 64, glm::vec4(std::numeric_limits<float>::quiet_NaN()));
    poison[0] = glm::vec4(8, 0, 0, 0);
    glint::scratch_table::view_t<float> v;
    v.data = poison.data();
    const auto f = glint::make_scratch_frame<float>(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    const glm::vec3 wo = glm::normalize(glm::vec3(0.5f, 0.2f, 1));  // theta_o = asin(wo.x)
    const float psi = 1 * static_cast<float>(deg);
    int culled = 0;
    for (std::uint32_t k = 0; k < 2000; ++k) {
        glm::dvec3 wd = random_unit(k, 31);
        wd.z = std::fabs(wd.z) + 0.01;
        const glm::vec3 wl(glm::normalize(wd));
        if (glint::scratch_light_reaches<float>(f, wo, wl, psi)) continue;
        ++culled;
        const glm::vec3 L = v.light_radiance(f, wo, wl, 1.0f, psi);
        CHECK(L.x == 0);
    }
    CHECK(culled > 1900);
    // The cull is the exact latitude test: a light just inside reaches, just outside does not.
    const glm::vec2 co = glint::to_cone<float>(f, wo);
    const auto at = [&](float theta) { return glint::from_cone<float>(f, glm::vec2(theta, 0.3f)); };
    CHECK(glint::scratch_light_reaches<float>(f, wo, at(-co.x + 0.99f * psi), psi));
    CHECK_FALSE(glint::scratch_light_reaches<float>(f, wo, at(-co.x + 1.01f * psi), psi));
}

TEST_CASE("scratch mix (Eq. 4): weights sum to 1, base only without scratches, continuous at total area 1") {
    const auto none = glint::scratch_mix_weights<float>(0.0f);
    CHECK(none.base_weight == 1.0f);
    for (float a : {0.0f, 0.3f, 0.999f, 1.0f, 1.001f, 2.5f, 64.0f}) {
        const auto m = glint::scratch_mix_weights<float>(a);
        CHECK(m.base_weight + a * m.layer_scale == doctest::Approx(1).epsilon(1e-6));
    }
    const auto below = glint::scratch_mix_weights<double>(1 - 1e-9), above = glint::scratch_mix_weights<double>(1 + 1e-9);
    CHECK(std::fabs(below.layer_scale - above.layer_scale) < 2e-9);
    CHECK(std::fabs(below.base_weight - above.base_weight) < 2e-9);
}

TEST_CASE("scratch layers (Eq. 7): density 0 has no scratch, scratches lie along the layer's direction, bad input named") {
    using glint_test::contains;
    using glint_test::error_of;
    glint::scratch_distribution d;
    d.layers = 4, d.spread_deg = 0, d.main_deg = 30, d.length = 0.1, d.width = 0.002, d.density = 0.3;
    const auto layers = glint::make_scratch_layers<double>(d);
    CHECK(layers.size() == 4u);
    CHECK(layers[0].dir.x == doctest::Approx(std::cos(30 * deg)));
    // Along the direction the indicator stays on over about the scratch's length, across it over
    // its width: the mean run length of 1s along each axis.
    const auto run = [&](glm::dvec2 step) {
        long on = 0, switches = 0;
        double prev = 0;
        for (int k = 0; k < 400000; ++k) {
            const double v = glint::scratch_indicator<double>(layers[0], glm::dvec2(0.123, 0.456) + static_cast<double>(k) * step);
            on += v > 0, switches += (v != prev), prev = v;
        }
        return switches > 0 ? static_cast<double>(on) / (0.5 * static_cast<double>(switches)) * glm::length(step) : 0;
    };
    const glm::dvec2 along = glm::dvec2(std::cos(30 * deg), std::sin(30 * deg)), across = glm::dvec2(-along.y, along.x);
    const double run_along = run(1e-4 * along), run_across = run(2e-6 * across);
    MESSAGE("mean scratch extent along " << run_along << ", across " << run_across);
    CHECK(run_along / run_across > 20);
    d.density = 0;
    for (const auto& L : glint::make_scratch_layers<float>(d))
        for (int k = 0; k < 1000; ++k) CHECK(glint::scratch_indicator<float>(L, glm::vec2(0.001f * static_cast<float>(k), 0.37f)) == 0.0f);
    d = {};
    d.layers = 65;
    CHECK(contains(error_of([&] { glint::make_scratch_layers<float>(d); }), "layers = 65"));
    d = {};
    d.width = 0;
    CHECK(contains(error_of([&] { glint::make_scratch_layers<float>(d); }), "width = 0"));
    d = {};
    d.density = 1.5;
    CHECK(contains(error_of([&] { glint::make_scratch_layers<float>(d); }), "density = 1.5"));
}

TEST_CASE("scratch kernels in float: no NaN or Inf at the hard inputs (horizon, poles, u-n plane, edge bins, Psi limits)") {
    const auto t = small_table(glint::make_quartic_groove(0.5, 256), glint::scratch_fresnel::iron(), 64, 2000);
    const auto v = t.view<float>();
    const auto f = glint::make_scratch_frame<float>(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    std::vector<glm::vec3> dirs = {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, 0, 1e-7f)), glm::normalize(glm::vec3(-1, 0, 1e-7f)),
                                   glm::normalize(glm::vec3(0, 1, 1e-7f)), glm::normalize(glm::vec3(0.6f, 0, 0.8f)),
                                   glm::normalize(glm::vec3(0, -1, 1e-3f)), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1)};
    for (std::uint32_t k = 0; k < 200; ++k) {
        glm::dvec3 w = random_unit(k, 41);
        w.z = std::fabs(w.z) * 1e-6;
        dirs.push_back(glm::vec3(glm::normalize(w)));
    }
    const float psis[] = {1e-4f, 0.0174533f, 0.174533f};
    std::size_t bad = 0, n = 0;
    for (const auto& wo : dirs)
        for (const auto& wl : dirs) {
            for (float u : {0.0f, 0.5f, 0.99999994f}) {
                const auto s = v.sample(f, wo, u, 1 - u);
                bad += !std::isfinite(s.weight.x) || !std::isfinite(s.pdf_phi) || !std::isfinite(s.wi.x);
                ++n;
            }
            for (float psi : psis) {
                const glm::vec3 L = v.light_radiance(f, wo, wl, 1.0f, psi, 32, 0.0f);
                bad += !std::isfinite(L.x) || !std::isfinite(L.y);
                ++n;
            }
            const glm::vec2 co = glint::to_cone<float>(f, wo), cl = glint::to_cone<float>(f, wl);
            const glm::vec3 r = v.rho(co.x, co.y, cl.y);
            bad += !std::isfinite(r.x);
            ++n;
        }
    MESSAGE(n << " hard-case calls");
    CHECK(bad == 0u);
}

TEST_CASE("scratch material: no scratches is the base BRDF exactly, the culls change nothing measurable, bad input named") {
    const auto t = small_table(glint::make_v_groove(30 * deg), glint::scratch_fresnel::iron(), 32, 2000);
    glint::scratch_distribution d;
    d.layers = 8, d.spread_deg = 360, d.length = 0.05, d.width = 0.002, d.density = 0, d.period = 16;
    const auto none = glint::scratch_material::build(t, d);
    CHECK(none.mean_coverage() == 0);
    const auto v0 = none.view<float>();
    const auto f = glint::make_scratch_frame<float>(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    for (std::uint32_t k = 0; k < 500; ++k) {
        glm::dvec3 wo = random_unit(k, 51), wl = random_unit(k, 53);
        wo.z = std::fabs(wo.z), wl.z = std::fabs(wl.z);
        const glm::vec2 x(static_cast<float>(rnd(k, 55)), static_cast<float>(rnd(k, 56)));
        const glm::vec2 a(static_cast<float>(1e-3 * rnd(k, 57)), 0), b(0, static_cast<float>(1e-3 * rnd(k, 58)));
        const auto lit = v0.light(f, x, a, b, glm::vec3(wo), glm::vec3(wl), 1.0f);
        CHECK(lit.base_weight == 1.0f);
        CHECK(lit.radiance.x == 0.0f);
        CHECK(lit.layers_shaded == 0);
        CHECK(v0.sample(f, x, a, b, glm::vec3(wo), static_cast<float>(rnd(k, 59)), 0.5f, 0.5f).layer == -1);
    }
    // With scratches: the area cull (1e-6) against none at all, over random pixels.
    d.density = 0.3;
    const auto m = glint::scratch_material::build(t, d);
    auto with = m.view<double>(), without = m.view<double>();
    without.cull = 0;
    double worst = 0;
    for (std::uint32_t k = 0; k < 2000; ++k) {
        glm::dvec3 wo = random_unit(k, 61), wl = random_unit(k, 63);
        wo.z = std::fabs(wo.z) + 0.05, wl.z = std::fabs(wl.z) + 0.05;
        wo = glm::normalize(wo), wl = glm::normalize(wl);
        const glm::dvec2 x(rnd(k, 65), rnd(k, 66)), a(3e-3 * rnd(k, 67), 0), b(0, 3e-3 * rnd(k, 68));
        const auto f2 = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0));
        const auto l1 = with.light(f2, x, a, b, wo, wl, 1.0, 5 * deg), l0 = without.light(f2, x, a, b, wo, wl, 1.0, 5 * deg);
        worst = std::max(worst, std::fabs(l1.radiance.x - l0.radiance.x) / std::max(1e-300, std::fabs(l0.radiance.x)) * (l0.radiance.x > 0));
        worst = std::max(worst, std::fabs(l1.base_weight - l0.base_weight));
    }
    MESSAGE("area cull: worst relative change " << worst);
    CHECK(worst <= 1e-6);
    using glint_test::contains;
    using glint_test::error_of;
    CHECK(contains(error_of([&] { glint::scratch_material::build(t, d, 3); }), "texels_per_cell = 3"));
    d.period = 12;
    CHECK(contains(error_of([&] { glint::scratch_material::build(t, d); }), "period = 12"));
}

TEST_CASE("scratch material: the coverage pyramid's top is the area fraction, and huge footprints read it") {
    const auto t = small_table(glint::make_v_groove(30 * deg), glint::scratch_fresnel::mirror(), 16, 500);
    glint::scratch_distribution d;
    d.layers = 3, d.spread_deg = 90, d.length = 0.1, d.width = 0.01, d.density = 0.35, d.period = 32;
    const auto m = glint::scratch_material::build(t, d, 4);
    CHECK(m.coverage_levels() == 8);  // 32 cells x 4 texels = 128 = 2^7
    // The area fraction by the exact indicator at 1e6 points of one period (noise coordinates).
    const auto& L = m.layers<double>()[0];
    double in = 0;
    const int n = 1000;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            in += K<double>::glint_worley_f1(glm::dvec2((i + 0.5) * d.period / n, (j + 0.5) * d.period / n), L.seed, L.period) <= d.density;
    const double fraction = in / (static_cast<double>(n) * n);
    MESSAGE("area fraction " << fraction << ", pyramid top " << m.mean_coverage());
    CHECK(std::fabs(m.mean_coverage() - fraction) < 2e-3);
    // A footprint of many periods reads the top levels: each layer's alpha is the fraction.
    const auto v = m.view<double>();
    for (int k = 0; k < 3; ++k) {
        const double a = v.alpha(k, glm::dvec2(0.3, 0.4), glm::dvec2(50, 0), glm::dvec2(0, 50));
        CHECK(a == doctest::Approx(m.mean_coverage()).epsilon(1e-9));
    }
}

TEST_CASE("scratch material: the coarse areas of unlit layers move Eq. 4's base weight by little") {
    // 32 layers of the scratched pattern; 2000 random pixels with footprints of 1e-4 to 1e-2: the
    // base weight from glint_scratch_material_light (coarse areas for the layers the light cannot
    // reach) against Eq. 4 from every layer's full area. Measured: mean 0.0105, worst 0.20 (at the
    // smallest footprints, where the full area is the exact indicator's 16-point estimate, in
    // steps of 1/16); base weights about 0.75. Leaving the unlit layers out of the sum would move
    // it by their whole area, about 0.25 on average.
    const auto t = small_table(glint::make_v_groove(30 * deg), glint::scratch_fresnel::iron(), 32, 1000);
    glint::scratch_distribution d;
    d.layers = 32, d.spread_deg = 360, d.length = 0.1, d.width = 2e-4, d.density = 0.05;
    const auto m = glint::scratch_material::build(t, d);
    const auto v = m.view<double>();
    const auto f = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0));
    double worst = 0, mean = 0;
    const int n = 2000;
    for (std::uint32_t k = 0; k < n; ++k) {
        const glm::dvec2 x(rnd(k, 71), rnd(k, 72));
        const double s = std::pow(10.0, -4 + 2 * rnd(k, 73));
        const glm::dvec2 a(s, 0), b(0, 0.6 * s);
        const glm::dvec3 wo = glm::normalize(glm::dvec3(0.3, 0.1, 1)), wl = glm::normalize(glm::dvec3(-0.4, 0.2, 1));
        double sum = 0;
        for (int j = 0; j < 32; ++j) sum += v.alpha(j, x, a, b);
        const double full = glint::scratch_mix_weights<double>(sum).base_weight;
        const double e = std::fabs(v.light(f, x, a, b, wo, wl, 1.0).base_weight - full);
        worst = std::max(worst, e), mean += e / n;
    }
    MESSAGE("base weight: mean difference " << mean << ", worst " << worst);
    CHECK(mean < 0.02);
    CHECK(worst < 0.3);
}

TEST_CASE("scratch table: the tracer's tabulated Fresnel is within 1e-6 of the exact models") {
    glint::scratch_fresnel gold, laz;
    gold.model = glint::fresnel_model::conductor_exact, gold.eta = glm::dvec3(0.18, 0.42, 1.37), gold.k = glm::dvec3(3.42, 2.35, 1.77);
    laz.model = glint::fresnel_model::lazanyi, laz.eta = glm::dvec3(2.91), laz.k = glm::dvec3(3.09), laz.lazanyi_a = 0.3;
    const glint::scratch_fresnel models[] = {glint::scratch_fresnel::iron(), glint::scratch_fresnel::plastic(), glint::scratch_fresnel::schlick(glm::dvec3(0.04, 0.5, 0.95)), gold, laz};
    for (const auto& f : models) {
        const glint::detail::fresnel_table t(f);
        double worst = 0;
        for (std::uint32_t k = 0; k < 100000; ++k) {
            const double c = rnd(k, 81);
            const glm::dvec3 e = f(c), a = t(c);
            worst = std::max({worst, std::fabs(e.x - a.x), std::fabs(e.y - a.y), std::fabs(e.z - a.z)});
        }
        MESSAGE("model " << static_cast<int>(f.model) << ": worst table error " << worst);
        CHECK(worst < 1e-6);
    }
}

TEST_CASE("scratch turned coordinates: circles (pitch 0) and an Archimedean spiral become lines along the first axis") {
    const glm::dvec2 c(0.3, -0.2);
    for (std::uint32_t k = 0; k < 1000; ++k) {
        const double r = 0.01 + rnd(k, 91), a = 6.0 * (rnd(k, 92) - 0.5);
        const glm::dvec2 p = c + r * glm::dvec2(std::cos(a), std::sin(a));
        const auto q = glint::scratch_turned<double>(p, c, 0.0);
        CHECK(q.x.y == doctest::Approx(r).epsilon(1e-12));                     // across: the radius
        CHECK(std::fabs(glm::dot(q.tangent, p - c)) < 1e-12);                 // tangent along the circle
        CHECK(glm::length(q.tangent) == doctest::Approx(1).epsilon(1e-12));
        // On the spiral r = r0 + pitch angle / (2 pi), the second coordinate stays r0.
        const double pitch = 0.05, ang = K<double>::glint_atan2(p.y - c.y, p.x - c.x);
        const double rs = 0.2 + pitch * ang / (2 * pi);
        const auto s = glint::scratch_turned<double>(c + rs * glm::dvec2(std::cos(ang), std::sin(ang)), c, pitch);
        CHECK(s.x.y == doctest::Approx(0.2).epsilon(1e-9));
    }
}
