// Microfacet basics against double-precision quadrature: normalisation of D and of the visible
// NDF (which checks Smith's Lambda), D_H, the radial closed forms, D_Omega for cones and
// rectangles (tests/support/microfacet_reference.hpp), Fresnel against complex arithmetic, and
// hard inputs in float.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <glint/microfacet.hpp>

#include "../support/microfacet_reference.hpp"

using glint_test::dvec2;
using glint_test::dvec3;
using glint_test::integrate_1d;

namespace {

const glint::ndf both_ndfs[] = {glint::ndf::ggx, glint::ndf::beckmann};

dvec3 spherical(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Integral over the hemisphere of f(m) dm, in theta = atan(alpha_max t) style substitution-free
// nested adaptive quadrature with a break point near the lobe's width.
// With `wo`, the inner integral also breaks where m becomes back-facing to wo (the visible
// NDF's kink).
template <class F>
double hemisphere(F f, double width, dvec3 wo = dvec3(0, 0, 1)) {
    auto outer = [&](double phi) {
        auto inner = [&](double theta) { return f(spherical(theta, phi)) * std::sin(theta); };
        std::vector<double> breaks{std::min(width, 1.0), std::min(4 * width, 1.4)};
        const double horizontal = wo.x * std::cos(phi) + wo.y * std::sin(phi);
        if (horizontal < 0) breaks.push_back(std::atan2(wo.z, -horizontal));
        return integrate_1d(inner, 0.0, M_PI / 2, breaks, 1e-12);
    };
    return integrate_1d(outer, 0.0, 2 * M_PI, {M_PI / 2, M_PI, 3 * M_PI / 2}, 1e-11);
}

const dvec2 roughnesses[] = {{0.01, 0.01}, {0.05, 0.2}, {0.3, 0.3}, {0.7, 0.35}, {1.0, 1.0}, {0.02, 0.32}};

}  // namespace

TEST_CASE("D integrates to 1 in projected area, and D_H is the integral of D") {
    // Beckmann's D_H goes through the erfc fit (relative error 1.2e-7, core.glsl); GGX's is exact.
    double worst_norm = 0, worst_dh[2] = {0, 0};
    for (glint::ndf d : both_ndfs)
        for (dvec2 a : roughnesses) {
            const double w = std::max(a.x, a.y);
            const double projected = hemisphere([&](const dvec3& m) { return glint::ndf_value(d, m, a) * m.z; }, w);
            const double area = hemisphere([&](const dvec3& m) { return glint::ndf_value(d, m, a); }, w);
            worst_norm = std::max(worst_norm, std::fabs(projected - 1));
            double& wd = worst_dh[static_cast<int>(d)];
            wd = std::max(wd, std::fabs(glint::total_area(d, a) - area) / area);
            CHECK(glint::total_area(d, a) >= 1.0);
        }
    MESSAGE("max |integral D cos - 1| = " << worst_norm << ", max relative error of D_H: GGX " << worst_dh[0] << ", Beckmann "
                                         << worst_dh[1]);
    CHECK(worst_norm < 1e-8);
    CHECK(worst_dh[0] < 1e-9);
    CHECK(worst_dh[1] < 2e-7);
}

TEST_CASE("the visible NDF integrates to 1 (Smith's Lambda is consistent with D), including grazing views") {
    // Beckmann's Lambda goes through the erfc fit (relative error 1.2e-7); GGX's is exact.
    double worst[2] = {0, 0};
    for (glint::ndf d : both_ndfs)
        for (dvec2 a : roughnesses)
            for (double theta_o : {0.0, 0.7, 1.3, 1.55}) {
                const dvec3 wo = spherical(theta_o, 0.4);
                const double s = hemisphere([&](const dvec3& m) { return glint::vndf(d, wo, m, a); }, std::max(a.x, a.y), wo);
                double& w = worst[static_cast<int>(d)];
                w = std::max(w, std::fabs(s - 1));
            }
    MESSAGE("max |integral of D_wo - 1|: GGX " << worst[0] << ", Beckmann " << worst[1]);
    CHECK(worst[0] < 1e-9);
    CHECK(worst[1] < 3e-7);
}

TEST_CASE("the radial mass and tail closed forms agree with quadrature, and with each other") {
    using K = glint::detail::glsl::kernels<double>;
    using KF = glint::detail::glsl::kernels<float>;
    // GGX's forms are exact; Beckmann's use the erfc fit (1.2e-7), amplified at most about 2x.
    double worst[2] = {0, 0}, worst_float = 0;
    for (int d = 0; d < 2; ++d)
        for (double a2 : {1e-8, 1e-4, 0.04, 0.5, 1.0, 3.0, 16.0})
            for (double T : {1e-9, 1e-4, 0.01, 0.3, 1.0, 4.0, 30.0, 1e3, 1e6}) {
                auto density = [&](double t) { return std::sqrt(1 + a2 * t) * (d == 0 ? 1 / ((1 + t) * (1 + t)) : std::exp(-t)) / (2 * M_PI); };
                const double mass = integrate_1d(density, 0.0, T, {1.0, 10.0, 100.0}, 1e-13);
                // t = T + (x / (1 - x))^2 keeps the integrand finite as x -> 1 (GGX decays as t^-1.5).
                const double tail = integrate_1d([&](double x) { const double y = x / (1 - x); return density(T + y * y) * 2 * x / ((1 - x) * (1 - x) * (1 - x)); },
                                                 0.0, 1.0, {0.5, 0.9, 0.99}, 1e-13);
                const double total = mass + tail;
                const double m = K::glint_radial_mass_over_t(d, T, a2) * T;
                const double t = K::glint_radial_tail(d, T, a2);
                double& w = worst[d];
                w = std::max({w, std::fabs(m - mass) / mass, std::fabs(K::glint_radial_tail(d, 0.0, a2) - total) / total});
                if (tail > 1e-300) w = std::max(w, std::fabs(t - tail) / std::max(tail, 1e-12 * total));
                const double mf = static_cast<double>(KF::glint_radial_mass_over_t(d, static_cast<float>(T), static_cast<float>(a2))) * T;
                worst_float = std::max(worst_float, std::fabs(mf - mass) / mass);
            }
    MESSAGE("radial closed forms: max relative error GGX " << worst[0] << ", Beckmann " << worst[1] << " (double), mass "
                                                             << worst_float << " (float)");
    CHECK(worst[0] < 1e-9);
    CHECK(worst[1] < 3e-7);
    CHECK(worst_float < 2e-6);
}


// The documented accuracy (docs/grid.md): with the default 8 pieces per edge the worst relative
// error over these lights is 2.0e-4 (sharp lobes at 80 degrees under lights cut by the horizon),
// 9.3e-6 with 16 and 4.1e-8 with 32; in float at least 1.5e-4, set by the rounding of wi + wo at
// grazing angles for roughness 0.002 (a relative error of 1e-4 in the half vector's slope).
TEST_CASE("D_Omega for cones and rectangles agrees with 2D adaptive quadrature over the light") {
    const auto cases = glint_test::light_cases(true);
    std::vector<double> refs;
    for (const auto& c : cases) refs.push_back(glint_test::reference(c));
    for (int pieces : {8, 32}) {
        double worst = 0, worst_float = 0;
        std::string worst_what;
        int compared = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto& c = cases[i];
            const double ref = refs[i];
            const double m = glint_test::d_omega<double>(c, pieces);
            const float mf = glint_test::d_omega<float>(c, pieces);
            if (ref < 1e-30) {
                CHECK(m < 1e-30);
                continue;
            }
            ++compared;
            // Relative error, with an absolute floor of 1e-9 D_H (a result that small is invisible).
            const double floor = 1e-9 * glint::total_area(c.d, c.alpha);
            const double e = std::fabs(m - ref) / std::max(ref, floor);
            const double ef = std::fabs(static_cast<double>(mf) - ref) / std::max(ref, floor);
            if (e > worst) {
                worst = e;
                worst_what = c.what + " " + glint::name(c.d) + " alpha (" + std::to_string(c.alpha.x) + ", " +
                             std::to_string(c.alpha.y) + "), view " + std::to_string(std::acos(c.wo.z)) + " rad, reference " + std::to_string(ref);
            }
            worst_float = std::max(worst_float, ef);
        }
        MESSAGE(pieces << " pieces, " << compared << " lights: max relative error " << worst << " in double (" << worst_what << "), "
                       << worst_float << " in float");
        CHECK(compared > 400);
        CHECK(worst < (pieces == 8 ? 2.5e-4 : 1e-7));
        CHECK(worst_float < (pieces == 8 ? 2.5e-4 : 2e-4));
    }
}

TEST_CASE("D_Omega of a light cut by the horizon counts only its part above it") {
    const dvec3 wo = spherical(1.2, 0.0);
    const dvec2 a(0.3, 0.3);
    for (glint::ndf d : both_ndfs) {
        // A cone whose axis is 5 degrees above the horizon, radius 20 degrees.
        const dvec3 axis = spherical(M_PI / 2 - 5 * M_PI / 180, M_PI);
        const double ref = glint_test::reference_cone(d, wo, a, axis, 20 * M_PI / 180);
        const double m = glint::integrated_ndf_cone(d, wo, a, axis, 20 * M_PI / 180, 32);
        CHECK(std::fabs(m - ref) / ref < 1e-7);
        // A rectangle standing on the horizon plane, half below it.
        const dvec3 p0(-2, -0.5, -0.5), e1(0, 1, 0), e2(0, 0, 1);
        const double rr = glint_test::reference_rect(d, wo, a, p0, e1, e2);
        const double mr = glint::integrated_ndf_rect(d, wo, a, p0, e1, e2, 32);
        CHECK(std::fabs(mr - rr) / rr < 1e-7);
        // Entirely below: 0.
        CHECK(glint::integrated_ndf_cone(d, wo, a, spherical(M_PI / 2 + 0.5, 1.0), 0.3) == 0.0);
        // Seen from behind: 0.
        CHECK(glint::integrated_ndf_rect(d, wo, a, p0, e2, e1) == 0.0);
    }
}

TEST_CASE("conductor Fresnel equals the complex-amplitude formula, Schlick's end points") {
    double worst = 0;
    for (double eta : {0.2, 1.0, 1.5, 2.9})
        for (double k : {0.0, 0.5, 3.0, 8.0})
            for (int i = 0; i <= 50; ++i) {
                const double c = i / 50.0, s2 = 1 - c * c;
                const std::complex<double> n(eta, k);
                const std::complex<double> ct = std::sqrt(1.0 - s2 / (n * n));
                const std::complex<double> rs = (c - n * ct) / (c + n * ct), rp = (n * c - ct) / (n * c + ct);
                const double exact = 0.5 * (std::norm(rs) + std::norm(rp));
                worst = std::max(worst, std::fabs(glint::fresnel_conductor(eta, k, c) - exact));
            }
    MESSAGE("conductor Fresnel: max absolute error " << worst);
    CHECK(worst < 1e-12);
    CHECK(glint::fresnel_schlick(0.04, 1.0) == doctest::Approx(0.04));
    CHECK(glint::fresnel_schlick(0.04, 0.0) == doctest::Approx(1.0));
}

TEST_CASE("float kernels are finite and non-negative on hard inputs: grazing, horizon, roughness 1e-4, huge lights") {
    std::size_t bad = 0, total = 0;
    for (int d = 0; d < 2; ++d)
        for (float ax : {1e-4f, 1e-3f, 0.1f, 1.0f, 4.0f, 0.0f, 100.0f})
            for (float ay : {1e-4f, 0.5f})
                for (float tz : {1.0f, 0.5f, 1e-3f, 1e-7f, 0.0f, -0.1f}) {
                    const glm::vec2 a(ax, ay);
                    const glm::vec3 w = glm::normalize(glm::vec3(std::sqrt(std::max(0.0f, 1 - tz * tz)), 0.0f, tz));
                    const glint::ndf n = d ? glint::ndf::beckmann : glint::ndf::ggx;
                    const glm::vec3 m = glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f));
                    const float v[] = {glint::ndf_value(n, w, a), glint::smith_lambda(n, w, a), glint::smith_g1(n, w, m, a),
                                       glint::smith_g2(n, w, w, m, a), glint::vndf(n, w, m, a), glint::total_area(n, a),
                                       glint::integrated_ndf_cone(n, w, a, m, 0.00454f), glint::integrated_ndf_cone(n, w, a, w, 1.5f),
                                       glint::integrated_ndf_rect(n, w, a, glm::vec3(-1, -1, 1), glm::vec3(0, 2, 0), glm::vec3(2, 0, 0)),
                                       glint::integrated_ndf_rect(n, w, a, glm::vec3(-1e4, -1e4, 1), glm::vec3(0, 2e4, 0), glm::vec3(2e4, 0, 0))};
                    for (float x : v) {
                        ++total;
                        bad += !(std::isfinite(x) && x >= 0);
                    }
                    const glm::vec3 h = glint::sample_vndf_ggx(w, a, 0.3f, 0.999f);
                    bad += !(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z));
                }
    MESSAGE(bad << " non-finite or negative of " << total);
    CHECK(bad == 0u);
}
