// Normal maps: construction and its errors, interpolation and its analytic Jacobian, wrap modes,
// the height-map conversion, and the procedural patterns (periodicity, analytic normals, the
// noise's exact slope variance).
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glint/normal_map.hpp>
#include <glint/patterns.hpp>

#include "../support/errors.hpp"

namespace {

using glint_test::contains;
using glint_test::error_of;

std::vector<glm::vec3> flat(int w, int h) { return std::vector<glm::vec3>(static_cast<std::size_t>(w * h), glm::vec3(0, 0, 1)); }

}  // namespace

TEST_CASE("normal_map: bad input raises glint::error naming the source, texel and value") {
    glint::normal_map_options o;
    o.source = "test.png";
    CHECK(contains(error_of([&] { glint::normal_map(0, 4, {}, o); }), "test.png: size 0 x 4 is empty"));
    CHECK(contains(error_of([&] { glint::normal_map(2, 2, flat(2, 1), o); }), "2 normals given for 2 x 2 texels (4 expected)"));
    auto n = flat(2, 2);
    n[3] = glm::vec3(0, std::nanf(""), 1);
    CHECK(contains(error_of([&] { glint::normal_map(2, 2, n, o); }), "texel (1, 1)"));
    CHECK(contains(error_of([&] { glint::normal_map(2, 2, n, o); }), "is not finite"));
    n[3] = glm::vec3(0);
    CHECK(contains(error_of([&] { glint::normal_map(2, 2, n, o); }), "has zero length"));
    n[3] = glm::vec3(0.6f, 0, -0.8f);
    const std::string below = error_of([&] { glint::normal_map(2, 2, n, o); });
    CHECK(contains(below, "texel (1, 1) normal (0.600000, 0.000000, -0.800000)"));
    CHECK(contains(below, "z must exceed"));
    // clamp_z: raised to min_z, unit length, counted.
    o.clamp_z = true;
    const glint::normal_map m(2, 2, n, o);
    CHECK(m.clamped() == 1);
    CHECK(m.texel(1, 1).z == doctest::Approx(1e-3).epsilon(1e-6));
    CHECK(glm::length(m.texel(1, 1)) == doctest::Approx(1).epsilon(1e-6));
    CHECK(m.texel(1, 1).x > 0.99f);
    // Non-unit normals are renormalised and counted.
    auto scaled = flat(2, 2);
    scaled[0] = glm::vec3(0, 0, 3);
    scaled[1] = glm::vec3(0.3f, 0.4f, 1.2f);
    const glint::normal_map r(2, 2, scaled);
    CHECK(r.renormalised() == 2);
    CHECK(r.texel(1, 0).x == doctest::Approx(0.3 / 1.3));
    CHECK(contains(error_of([&] { glint::normal_map::from_heights(2, 2, {0, 0, 0, INFINITY}); }), "height at texel (1, 1) is not finite"));
}

TEST_CASE("normal_map: interpolation hits the texels, is periodic, and its Jacobian is the interpolant's derivative") {
    glint::pattern_params p;
    p.kind = glint::pattern::noise;
    p.width = 32, p.height = 16;
    p.slope_rms = 0.3;
    const glint::normal_map m = glint::make_normal_map(p);
    for (int y = 0; y < 16; y += 5)
        for (int x = 0; x < 32; x += 7) {
            const glm::dvec2 c(x + 0.5, y + 0.5);
            const glm::dvec3 t = glm::normalize(glm::dvec3(m.texel(x, y)));  // float texels, renormalised in double
            CHECK(glm::length(m.bicubic(c).normal() - t) < 1e-12);
            CHECK(glm::length(m.bilinear(c).normal() - t) < 1e-12);
        }
    double worst_cubic = 0, worst_linear = 0, worst_period = 0;
    for (int i = 0; i < 400; ++i) {
        // Points within one period: far from the origin the difference quotient would cancel.
        const glm::dvec2 u(std::fmod(0.173 * i + 0.05, 32.0), std::fmod(0.0711 * i * i / 7.0 + 0.3, 16.0));
        const auto q = m.bicubic(u);
        // Step 1e-7: Catmull-Rom is only C1, so a quotient straddling a texel centre errs by
        // about the step times the jump in the second derivative.
        const double d = 1e-7;
        for (int axis = 0; axis < 2; ++axis) {
            glm::dvec2 e(0);
            e[axis] = d;
            const glm::dvec2 fd = (m.bicubic(u + e).s - m.bicubic(u - e).s) / (2 * d);
            worst_cubic = std::max(worst_cubic, glm::length(fd - q.jacobian[axis]));
            // Bilinear away from the kinks at texel centres.
            const glm::dvec2 f = u - glm::floor(u - 0.5) - 0.5;
            if (f.x > 0.01 && f.x < 0.99 && f.y > 0.01 && f.y < 0.99) {
                const glm::dvec2 fl = (m.bilinear(u + e).s - m.bilinear(u - e).s) / (2 * d);
                worst_linear = std::max(worst_linear, glm::length(fl - m.bilinear(u).jacobian[axis]));
            }
        }
        worst_period = std::max(worst_period, glm::length(m.bicubic(u + glm::dvec2(32, -48)).s - q.s));
    }
    MESSAGE("Jacobian against central differences: bicubic " << worst_cubic << ", bilinear " << worst_linear);
    CHECK(worst_cubic < 1e-7);
    CHECK(worst_linear < 1e-7);
    CHECK(worst_period < 1e-12);
    // Clamp mode extends the border texels.
    std::vector<glm::vec3> n = flat(4, 4);
    n[3] = glm::normalize(glm::vec3(0.3f, 0, 1));
    const glint::normal_map c(4, 4, n, glint::normal_map_options{glint::wrap_mode::clamp});
    CHECK(glm::length(c.bicubic(glm::dvec2(9.0, 0.5)).normal() - glm::dvec3(n[3])) < 1e-7);
    CHECK(glm::length(c.texel(-5, 0) - n[0]) == 0);
}

TEST_CASE("normal_map: at texel centres the bicubic reads 5 taps and equals the 16-tap sum bit for bit") {
    // The 5-tap path (interpolate_with) must give what the full Catmull-Rom loop gives: the loop at
    // t = 0 adds only zeros besides the cross's terms. The reference here is that loop, written out.
    glint::pattern_params p;
    p.kind = glint::pattern::noise;
    p.width = p.height = 16;
    p.slope_rms = 0.4;
    const glint::normal_map m = glint::make_normal_map(p);
    const double t = 0, t2 = t * t, t3 = t2 * t;  // Catmull-Rom's weights at t = 0, as normal_map computes them
    const double w[4] = {0.5 * (-t3 + 2 * t2 - t), 0.5 * (3 * t3 - 5 * t2 + 2), 0.5 * (-3 * t3 + 4 * t2 + t), 0.5 * (t3 - t2)};
    const double dw[4] = {0.5 * (-3 * t2 + 4 * t - 1), 0.5 * (9 * t2 - 10 * t), 0.5 * (-9 * t2 + 8 * t + 1), 0.5 * (3 * t2 - 2 * t)};
    int mismatches = 0, checked = 0;
    for (int y = -1; y < 17; y += 3)
        for (int x = -2; x < 18; x += 5) {
            int fetched = 0;
            const auto fetch = [&](long i, long j) -> const glm::vec3& { return ++fetched, m.texel(i, j); };
            const auto q = glint::normal_map::interpolate_with<double, 4>(fetch, glm::dvec2(x + 0.5, y + 0.5));
            CHECK(fetched == 5);
            glm::dvec3 v(0), vx(0), vy(0);
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    const glm::dvec3 n(m.texel(x - 1 + i, y - 1 + j));
                    v += (w[i] * w[j]) * n, vx += (dw[i] * w[j]) * n, vy += (w[i] * dw[j]) * n;
                }
            const double len = std::max(std::sqrt(glm::dot(v, v)), 1e-6);
            const glm::dvec3 n = v / len, dx = (vx - n * glm::dot(n, vx)) / len, dy = (vy - n * glm::dot(n, vy)) / len;
            ++checked;
            if (!(q.s == glm::dvec2(n.x, n.y) && q.jacobian[0] == glm::dvec2(dx.x, dx.y) && q.jacobian[1] == glm::dvec2(dy.x, dy.y))) ++mismatches;
        }
    MESSAGE("texel centres checked: " << checked);
    CHECK(mismatches == 0);
}

TEST_CASE("normal_map: bicubic approximates a smooth analytic field to third order, from_heights matches the gradient") {
    glint::pattern_params p;
    p.kind = glint::pattern::sinusoid;
    p.slope_rms = 0.2;
    double err[2];
    for (int k = 0; k < 2; ++k) {
        p.width = p.height = 64 << k;
        const glint::normal_map m = glint::make_normal_map(p);
        err[k] = 0;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec2 u(p.width * (i + 0.37) / 300.0, 3.3);
            err[k] = std::max(err[k], glm::length(m.bicubic(u).normal() - glint::pattern_normal(p, u)));
        }
    }
    MESSAGE("bicubic error, 16 and 32 texels per period: " << err[0] << ", " << err[1]);
    CHECK(err[0] < 1e-3);
    CHECK(err[1] < err[0] / 6);  // third order: 8x, allowing for the sampling of the maximum
    // Heights h = A sin(2 pi x / W): central differences against the analytic gradient (error
    // (2 pi / W)^2 / 6 relative).
    const int w = 64;
    std::vector<float> h(static_cast<std::size_t>(w * 4));
    const double a = 2.0, k = 6.283185307179586 / w;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < w; ++x) h[static_cast<std::size_t>(x + w * y)] = static_cast<float>(a * std::sin(k * (x + 0.5)));
    const glint::normal_map m = glint::normal_map::from_heights(w, 4, h, 1.0f);
    double worst = 0;
    for (int x = 0; x < w; ++x) {
        const glm::dvec3 exact = glm::normalize(glm::dvec3(-a * k * std::cos(k * (x + 0.5)), 0, 1));
        worst = std::max(worst, glm::length(glm::dvec3(m.texel(x, 2)) - exact));
    }
    CHECK(worst < a * k * k * k / 6 + 1e-6);
}

TEST_CASE("patterns: periodic, analytic, valid normals, the noise's slope variance is exact") {
    for (int kind = 0; kind <= static_cast<int>(glint::pattern::scratched_metal); ++kind) {
        glint::pattern_params p;
        p.kind = static_cast<glint::pattern>(kind);
        p.width = 48, p.height = 48, p.seed = 7;
        CAPTURE(glint::pattern_name(p.kind));
        CHECK(glint::parse_pattern(glint::pattern_name(p.kind)) == p.kind);
        const glint::normal_map m = glint::make_normal_map(p);
        CHECK(m.width() == 48);
        CHECK(m.renormalised() == 0);
        double zmin = 1, worst_period = 0, spread = 0;
        for (int i = 0; i < 200; ++i) {
            const glm::dvec2 u(0.2397 * i * 1.7, 0.1131 * i * 2.9);
            const glm::dvec3 n = glint::pattern_normal(p, u);
            zmin = std::min(zmin, n.z);
            CHECK(std::fabs(glm::length(n) - 1) < 1e-12);
            if (p.kind != glint::pattern::ramp)
                worst_period = std::max(worst_period, glm::length(glint::pattern_normal(p, u + glm::dvec2(48, -96)) - n));
            spread = std::max(spread, glm::length(glm::dvec2(n.x, n.y)));
        }
        CHECK(zmin > 0.3);
        CHECK(worst_period < 1e-9);
        if (p.kind == glint::pattern::flat) CHECK(spread == 0);
        else CHECK(spread > 0.01);
    }
    for (const auto kind : {glint::pattern::noise, glint::pattern::anisotropic_noise, glint::pattern::brushed, glint::pattern::sinusoid}) {
        glint::pattern_params p;
        p.kind = kind;
        p.width = 64, p.height = 32, p.slope_rms = 0.15;
        CAPTURE(glint::pattern_name(kind));
        const glm::dvec2 v = glint::pattern_slope_variance(p);
        CHECK((v.x + v.y) / 2 == doctest::Approx(p.slope_rms * p.slope_rms).epsilon(1e-12));
        // The texel mean of the analytic gradient squared, from the normals: g = -n.xy / n.z.
        glm::dvec2 mean(0);
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                const glm::dvec3 n = glint::pattern_normal(p, glm::dvec2(x + 0.5, y + 0.5));
                mean += glm::dvec2(n.x * n.x, n.y * n.y) / (n.z * n.z);
            }
        mean /= static_cast<double>(p.width * p.height);
        CHECK(mean.x == doctest::Approx(v.x).epsilon(1e-9).scale(1e-12));
        CHECK(mean.y == doctest::Approx(v.y).epsilon(1e-9).scale(1e-12));
        if (kind == glint::pattern::anisotropic_noise) CHECK(v.y < v.x / 4);
        if (kind == glint::pattern::brushed) CHECK(v.x == doctest::Approx(0.01 * v.y).epsilon(1e-9));
    }
    // Flakes: one normal per cell; pyramids: four normals.
    glint::pattern_params p;
    p.kind = glint::pattern::pyramids;
    const glint::normal_map m = glint::make_normal_map(p);
    std::vector<glm::vec3> distinct;
    for (const auto& n : m.normals()) {
        bool seen = false;
        for (const auto& d : distinct) seen = seen || glm::length(d - n) < 1e-6f;
        if (!seen) distinct.push_back(n);
    }
    CHECK(distinct.size() == 4);
    CHECK(contains(error_of([] { glint::parse_pattern("plaid"); }), "unknown pattern 'plaid' (one of: flat, tilt"));
    p.slope_rms = 0;
    CHECK(contains(error_of([&] { glint::make_normal_map(p); }), "slope_rms = 0"));
}

TEST_CASE("patterns: scratched_metal's map, summed segment by segment, is its normal at the texel centres") {
    for (const int side : {3, 37, 128}) {
        glint::pattern_params p;
        p.kind = glint::pattern::scratched_metal, p.width = side, p.height = side + 5, p.count = 150, p.slope_rms = 0.15, p.seed = 4;
        const glint::normal_map m = glint::make_normal_map(p);
        int grooved = 0;
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < side; ++x) {
                const glm::vec3 n(glint::pattern_normal(p, glm::dvec2(x + 0.5, y + 0.5)));
                CHECK(m.texel(x, y) == n);
                grooved += n.z < 1 ? 1 : 0;
            }
        CAPTURE(side);
        CHECK(grooved > 0);
        CHECK(grooved < side * (side + 5));
    }
}
