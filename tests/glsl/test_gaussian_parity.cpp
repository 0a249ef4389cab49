// The Gaussian-element kernels through Mesa llvmpipe against the C++ float path on the same
// inputs: the footprint frame, one element's Eq. 6 term, the normal marginal, the taper's mass and
// the BRDF; then the direct P-NDF over an element buffer (std430 SSBO) on a noise map. Builtins
// (exp, sqrt, atan) differ by a few ulp, and a P-NDF value is a sum of exponentials of
// Mahalanobis distances up to cull_s^2 = 16, so relative differences of a few 1e-6 are expected;
// the share of P-NDF values that differ by more than 1e-3 relative (the mismatch rate) is bounded.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glint/gaussian.hpp>
#include <glint/glsl.hpp>
#include <glint/patterns.hpp>

#include "parity.hpp"
#include "tolerances.hpp"

namespace {

float rnd(std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, salt, 0x6au)).x); }

double max_relative(const std::vector<float>& gpu, const std::vector<float>& cpu, double floor, std::size_t& non_finite, std::size_t& over,
                    double over_threshold) {
    double worst = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        non_finite += !std::isfinite(gpu[i]);
        const double d = std::fabs(static_cast<double>(gpu[i]) - static_cast<double>(cpu[i])) / std::max(std::fabs(static_cast<double>(cpu[i])), floor);
        worst = std::max(worst, d);
        over += d > over_threshold;
    }
    return worst;
}

using K = glint::detail::glsl::kernels<float>;

}  // namespace

TEST_CASE("gaussian kernels: GLSL against C++ (frame, element term, marginal, taper mass, BRDF)") {
    const std::size_t n = 20000;
    std::vector<std::uint32_t> in;
    struct input {
        glm::vec4 us, jac, cov;
        glm::vec2 mean, s;
        float sigma_r;
    };
    std::vector<input> v(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        input& x = v[i];
        x.us = {10 * rnd(i, 1), 10 * rnd(i, 2), 0.6f * rnd(i, 3) - 0.3f, 0.6f * rnd(i, 4) - 0.3f};
        x.jac = {rnd(i, 5) - 0.5f, rnd(i, 6) - 0.5f, rnd(i, 7) - 0.5f, rnd(i, 8) - 0.5f};
        const float a = std::exp2(-4 + 12 * rnd(i, 9)), b = a * std::exp2(-10 * rnd(i, 10)), t = 6.28f * rnd(i, 11);
        const float c = std::cos(t), sn = std::sin(t);
        x.cov = {a * a * c * c + b * b * sn * sn, (a * a - b * b) * c * sn, a * a * sn * sn + b * b * c * c, a * a * b * b};
        x.mean = glm::vec2(x.us.x, x.us.y) + glm::vec2(a * (rnd(i, 12) - 0.5f), a * (rnd(i, 13) - 0.5f));
        x.s = glm::vec2(x.us.z, x.us.w) + 0.1f * glm::vec2(rnd(i, 14) - 0.5f, rnd(i, 15) - 0.5f);
        x.sigma_r = std::exp2(-12 + 9 * rnd(i, 16));
        glint_test::append_words(in, {x.us.x, x.us.y, x.us.z, x.us.w, x.jac.x, x.jac.y, x.jac.z, x.jac.w, x.cov.x, x.cov.y, x.cov.z, x.cov.w,
                                      x.mean.x, x.mean.y, x.s.x, x.s.y, x.sigma_r});
    }
    const std::string body =
        "uint b = 17u * i;"
        " glint_gaussian_element el; el.us = vec4(in_vec2(b), in_vec2(b + 2u)); el.jac = vec4(in_vec2(b + 4u), in_vec2(b + 6u));"
        " vec4 cov = vec4(in_vec2(b + 8u), in_vec2(b + 10u)); vec2 mu = in_vec2(b + 12u); vec2 s = in_vec2(b + 14u); float sr = in_float(b + 16u);"
        " glint_pndf_params p; p.sigma_h = 0.4246609; p.sigma_r = sr; p.spacing = 1.0; p.area = 1.0; p.cull_u = 3.5; p.cull_s = 4.0;"
        " p.width = 1; p.height = 1; p.periodic = 1; p.max_side = 1;"
        " glint_pndf_frame f = glint_pndf_prepare(mu, cov, p.sigma_h, p.cull_u, p.cull_s);"
        " p.cull_u = 0.0; p.cull_s = 0.0;"
        " out0[6u*i] = floatBitsToUint(glint_pndf_element(el, el.us.xy, f, s, p));"
        " out0[6u*i+1u] = floatBitsToUint(glint_pndf_element_marginal(el, s, p));"
        " out0[6u*i+2u] = floatBitsToUint(f.lambda.y / max(f.lambda.x, 1e-30));"
        " out0[6u*i+3u] = floatBitsToUint(glint_pndf_window_mass(2.0 + 6.0 * fract(float(i) * 0.618034)));"
        " vec3 wo = normalize(vec3(s, 0.5)); vec3 wi = normalize(vec3(-s.yx, 0.8));"
        " out0[6u*i+4u] = floatBitsToUint(glint_pndf_brdf(1.5, wi, wo, 1, vec2(0.1 + sr * 50.0), 0.2, 3.0));"
        " out0[6u*i+5u] = floatBitsToUint(f.norm);";
    const auto gpu = glint_test::from_words<float>(glint_test::map_words({"core.glsl", "microfacet.glsl", "gaussian.glsl"}, body, in, n, 6));
    std::vector<std::vector<float>> g(6), c(6);
    for (std::uint32_t i = 0; i < n; ++i) {
        const input& x = v[i];
        K::glint_gaussian_element el{x.us, x.jac};
        K::glint_pndf_params p{};
        p.sigma_h = 0.4246609f, p.sigma_r = x.sigma_r, p.spacing = 1, p.area = 1, p.cull_u = 3.5f, p.cull_s = 4, p.width = 1, p.height = 1, p.periodic = 1,
        p.max_side = 1;
        const auto f = K::glint_pndf_prepare(x.mean, x.cov, p.sigma_h, p.cull_u, p.cull_s);
        p.cull_u = 0, p.cull_s = 0;
        const glm::vec2 s = x.s;
        const glm::vec3 wo = glm::normalize(glm::vec3(s.x, s.y, 0.5f)), wi = glm::normalize(glm::vec3(-s.y, -s.x, 0.8f));
        const float cpu[6] = {K::glint_pndf_element(el, glm::vec2(x.us.x, x.us.y), f, s, p), K::glint_pndf_element_marginal(el, s, p),
                              f.lambda.y / std::max(f.lambda.x, 1e-30f),
                              K::glint_pndf_window_mass(2.0f + 6.0f * glm::fract(static_cast<float>(i) * 0.618034f)),
                              K::glint_pndf_brdf(1.5f, wi, wo, 1, glm::vec2(0.1f + x.sigma_r * 50.0f), 0.2f, 3.0f), f.norm};
        for (int k = 0; k < 6; ++k) g[static_cast<std::size_t>(k)].push_back(gpu[6 * i + static_cast<std::size_t>(k)]), c[static_cast<std::size_t>(k)].push_back(cpu[k]);
    }
    const char* names[] = {"element term", "marginal", "lambda ratio", "taper mass", "BRDF", "frame norm"};
    for (std::size_t k = 0; k < 6; ++k) {
        std::size_t non_finite = 0, over = 0;
        // Relative to the result; terms below 1e-20 of the largest are invisible in a sum.
        const double worst = max_relative(g[k], c[k], k < 2 ? 1e-20 : 1e-30, non_finite, over, 1e-3);
        MESSAGE(std::string(names[k]) << ": max relative difference " << worst);
        CHECK(non_finite == 0u);
        CHECK(worst < GAUSSIAN_GLSL_MAX_RELATIVE);
    }
}

TEST_CASE("direct P-NDF over an element buffer: GLSL against C++ on a noise map") {
    glint::pattern_params pp;
    pp.kind = glint::pattern::noise, pp.width = pp.height = 32, pp.slope_rms = 0.15;
    glint::gaussian_params<float> gp;
    gp.sigma_r = 0.01f, gp.direct_max_side = 24;
    const auto pndf = glint::gaussian_pndf<float>::build(glint::make_normal_map(pp), gp);
    const auto& k = pndf.kernel_params();
    const std::size_t n = 4000;
    std::vector<std::uint32_t> in;
    std::vector<glint::texel_footprint<float>> fps(n);
    std::vector<glm::vec2> ss(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const float a = std::exp2(-3 + 8 * rnd(i, 20)), b = a * std::exp2(-4 * rnd(i, 21)), t = 6.28f * rnd(i, 22);
        const float c = std::cos(t), sn = std::sin(t);
        fps[i].center = {100 * rnd(i, 23) - 50, 100 * rnd(i, 24) - 50};
        fps[i].covariance = glm::mat2(a * a * c * c + b * b * sn * sn, (a * a - b * b) * c * sn, (a * a - b * b) * c * sn, a * a * sn * sn + b * b * c * c);
        ss[i] = {0.5f * rnd(i, 25) - 0.25f, 0.5f * rnd(i, 26) - 0.25f};
        const auto& cv = fps[i].covariance;
        const float det = static_cast<float>(static_cast<double>(cv[0][0]) * static_cast<double>(cv[1][1]) - static_cast<double>(cv[1][0]) * static_cast<double>(cv[1][0]));
        glint_test::append_words(in, {fps[i].center.x, fps[i].center.y, cv[0][0], cv[1][0], cv[1][1], std::max(det, 0.0f), ss[i].x, ss[i].y});
    }
    const auto bits = glint_test::glsl_float_bits;
    const std::string body =
        "    uint b = 8u * i;\n"
        "    glint_pndf_params p; p.sigma_h = " + bits(k.sigma_h) + "; p.sigma_r = " + bits(k.sigma_r) + "; p.spacing = " + bits(k.spacing) +
        "; p.area = " + bits(k.area) + "; p.cull_u = " + bits(k.cull_u) + "; p.cull_s = " + bits(k.cull_s) + "; p.width = " + std::to_string(k.width) +
        "; p.height = " + std::to_string(k.height) + "; p.periodic = " + std::to_string(k.periodic) + "; p.max_side = " + std::to_string(k.max_side) +
        ";\n"
        "    glint_pndf_frame f = glint_pndf_prepare(vec2(in_float(b), in_float(b + 1u)), vec4(in_float(b + 2u), in_float(b + 3u), in_float(b + 4u), in_float(b + 5u)), p.sigma_h, p.cull_u, p.cull_s);\n"
        "    out0[i] = floatBitsToUint(glint_pndf_direct(f, vec2(in_float(b + 6u), in_float(b + 7u)), p));";
    const auto out = glint_test::from_words<float>(glint_test::map_words_with_data({"core.glsl", "microfacet.glsl"}, "gaussian.glsl", "glint_element_data",
                                                                                   "GLINT_ELEMENT_BUFFER_DECLARED", body, in, glint_test::to_words(pndf.element_data()), n, 1));
    std::vector<float> cpu(n);
    std::size_t positive = 0;
    for (std::uint32_t i = 0; i < n; ++i) cpu[i] = pndf.eval_direct(fps[i], ss[i]), positive += cpu[i] > 0;
    std::size_t non_finite = 0, over = 0;
    // Values below 1e-6 of the map's peak density (about 1e3) are invisible: a floor of 1e-3.
    const double worst = max_relative(out, cpu, 1e-3, non_finite, over, 1e-3);
    MESSAGE("direct P-NDF: " << n << " queries (" << positive << " positive), max relative difference " << worst << ", " << over
                             << " beyond 1e-3 (rate " << static_cast<double>(over) / n << ")");
    CHECK(positive > n / 4);
    CHECK(non_finite == 0u);
    CHECK(worst < PNDF_GLSL_MAX_RELATIVE);
    CHECK(static_cast<double>(over) / n <= PNDF_GLSL_MAX_MISMATCH_RATE);
}
