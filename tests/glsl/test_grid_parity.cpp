// The microfacet and grid kernels through Mesa llvmpipe against the C++ float path on the same
// inputs: the per-pixel microfacet functions, D_Omega for cones and rectangles, and the glint
// estimate R for point and extended lights. Builtins (exp, log, sqrt, pow, sin, cos, atan)
// differ by a few ulp between the two; R is a sum of binomial draws, so a draw whose input sits
// within those ulp of a gate may flip: such estimates are counted and their rate bounded.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glint/grid.hpp>

#include "parity.hpp"
#include "tolerances.hpp"

namespace {

glm::vec3 random_direction(std::uint32_t i, std::uint32_t salt, float min_z) {
    const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, salt, 0x3du));
    const float z = min_z + (1 - min_z) * glint::unit_from_bits<float>(h.x);
    const float phi = 6.2831853f * glint::unit_from_bits<float>(h.y);
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

float rnd(std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, salt, 0x5fu)).x); }

// Largest relative difference, with an absolute floor (values below it are compared absolutely).
double max_relative(const std::vector<float>& gpu, const std::vector<float>& cpu, double floor, std::size_t& non_finite) {
    double worst = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        non_finite += !std::isfinite(gpu[i]);
        const double d = std::fabs(static_cast<double>(gpu[i]) - static_cast<double>(cpu[i]));
        worst = std::max(worst, d / std::max(std::fabs(static_cast<double>(cpu[i])), floor));
    }
    return worst;
}

const std::vector<std::string> grid_files{"core.glsl", "binomial.glsl", "microfacet.glsl", "grid.glsl"};

}  // namespace

TEST_CASE("microfacet kernels: GLSL against C++ (D, Lambda, G2, VNDF, D_H, conductor Fresnel, VNDF sample)") {
    const std::size_t n = 20000;
    std::vector<std::uint32_t> in;
    std::vector<glm::vec3> wo(n), wi(n), m(n);
    std::vector<glm::vec2> alpha(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        wo[i] = random_direction(i, 1, 0.01f), wi[i] = random_direction(i, 2, 0.01f), m[i] = glm::normalize(wo[i] + wi[i]);
        alpha[i] = glm::vec2(std::exp2(-10.0f * rnd(i, 3)), std::exp2(-10.0f * rnd(i, 4)));
        glint_test::append_words(in, {wo[i].x, wo[i].y, wo[i].z, wi[i].x, wi[i].y, wi[i].z, alpha[i].x, alpha[i].y});
    }
    const std::string body =
        "vec3 wo = in_vec3(8u*i); vec3 wi = in_vec3(8u*i+3u); vec2 a = in_vec2(8u*i+6u); vec3 m = normalize(wo + wi);"
        " int d = int(i & 1u);"
        " out0[9u*i] = floatBitsToUint(glint_ndf(d, m, a));"
        " out0[9u*i+1u] = floatBitsToUint(glint_smith_lambda(d, wo, a));"
        " out0[9u*i+2u] = floatBitsToUint(glint_smith_g2(d, wi, wo, m, a));"
        " out0[9u*i+3u] = floatBitsToUint(glint_vndf(d, wo, m, a));"
        " out0[9u*i+4u] = floatBitsToUint(glint_total_area(d, a));"
        " out0[9u*i+5u] = floatBitsToUint(glint_fresnel_conductor(a.x * 3.0, a.y * 5.0, wo.z));"
        " vec3 s = glint_sample_vndf_ggx(wo, a, a.x, a.y);"
        " out0[9u*i+6u] = floatBitsToUint(s.x); out0[9u*i+7u] = floatBitsToUint(s.y); out0[9u*i+8u] = floatBitsToUint(s.z);";
    const auto gpu = glint_test::from_words<float>(glint_test::map_words({"core.glsl", "microfacet.glsl"}, body, in, n, 9));
    using K = glint::detail::glsl::kernels<float>;
    const char* names[] = {"D", "Lambda", "G2", "VNDF", "D_H", "Fresnel", "sample.x", "sample.y", "sample.z"};
    for (int k = 0; k < 9; ++k) {
        std::vector<float> g, c;
        for (std::uint32_t i = 0; i < n; ++i) {
            const int d = static_cast<int>(i & 1u);
            const glm::vec3 s = K::glint_sample_vndf_ggx(wo[i], alpha[i], alpha[i].x, alpha[i].y);
            const float v[] = {K::glint_ndf(d, m[i], alpha[i]), K::glint_smith_lambda(d, wo[i], alpha[i]),
                               K::glint_smith_g2(d, wi[i], wo[i], m[i], alpha[i]), K::glint_vndf(d, wo[i], m[i], alpha[i]),
                               K::glint_total_area(d, alpha[i]), K::glint_fresnel_conductor(alpha[i].x * 3.0f, alpha[i].y * 5.0f, wo[i].z),
                               s.x, s.y, s.z};
            g.push_back(gpu[9 * i + static_cast<std::size_t>(k)]), c.push_back(v[k]);
        }
        std::size_t non_finite = 0;
        // Fresnel and the sample's components lie in [-1, 1]: compared absolutely.
        const double worst = max_relative(g, c, k >= 5 ? 1.0 : 1e-30, non_finite);
        MESSAGE(std::string(names[k]) << ": max relative difference " << worst);
        CHECK(non_finite == 0u);
        CHECK(worst < MICROFACET_GLSL_MAX_RELATIVE);
    }
}

TEST_CASE("D_Omega kernels: GLSL against C++ for cones and rectangles") {
    const std::size_t n = 4000;
    std::vector<std::uint32_t> in;
    std::vector<glm::vec3> wo(n), axis(n);
    std::vector<float> alpha(n), size(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        wo[i] = random_direction(i, 5, 0.05f);
        const glm::vec3 r(-wo[i].x, -wo[i].y, wo[i].z);
        axis[i] = glm::normalize(r + 0.3f * (random_direction(i, 6, -1.0f)));
        alpha[i] = std::exp2(-8.0f * rnd(i, 7));
        size[i] = std::exp2(-7.0f + 7.0f * rnd(i, 8));
        glint_test::append_words(in, {wo[i].x, wo[i].y, wo[i].z, axis[i].x, axis[i].y, axis[i].z, alpha[i], size[i]});
    }
    const std::string body =
        "vec3 wo = in_vec3(8u*i); vec3 c = in_vec3(8u*i+3u); float al = in_float(8u*i+6u); float s = in_float(8u*i+7u);"
        " int d = int(i & 1u);"
        " vec2 a = vec2(al, 0.7 * al);"
        " out0[2u*i] = floatBitsToUint(glint_integrated_ndf_cone(d, wo, a, c, cos(s), sin(s), 8));"
        " vec3 e1 = normalize(cross(c, vec3(0.0, 0.2, 1.0))) * s; vec3 e2 = normalize(cross(e1, c)) * s;"
        " out0[2u*i+1u] = floatBitsToUint(glint_integrated_ndf_rect(d, wo, a, c - 0.5 * e1 - 0.5 * e2, e1, e2, 8));";
    const auto gpu = glint_test::from_words<float>(glint_test::map_words({"core.glsl", "microfacet.glsl"}, body, in, n, 2));
    using K = glint::detail::glsl::kernels<float>;
    std::vector<float> gc, cc, gr, cr;
    for (std::uint32_t i = 0; i < n; ++i) {
        const int d = static_cast<int>(i & 1u);
        const glm::vec2 a(alpha[i], 0.7f * alpha[i]);
        const glm::vec3 c = axis[i];
        cc.push_back(K::glint_integrated_ndf_cone(d, wo[i], a, c, std::cos(size[i]), std::sin(size[i]), 8));
        const glm::vec3 e1 = glm::normalize(glm::cross(c, glm::vec3(0.0f, 0.2f, 1.0f))) * size[i];
        const glm::vec3 e2 = glm::normalize(glm::cross(e1, c)) * size[i];
        cr.push_back(K::glint_integrated_ndf_rect(d, wo[i], a, c - 0.5f * e1 - 0.5f * e2, e1, e2, 8));
        gc.push_back(gpu[2 * i]), gr.push_back(gpu[2 * i + 1]);
    }
    std::size_t non_finite = 0;
    // Relative to the result, with a floor of 1e-6 D_H-ish (1e-6): smaller results are invisible.
    const double cone = max_relative(gc, cc, 1e-6, non_finite), rect = max_relative(gr, cr, 1e-6, non_finite);
    MESSAGE("D_Omega: max relative difference, cones " << cone << ", rectangles " << rect);
    CHECK(non_finite == 0u);
    CHECK(cone < D_OMEGA_GLSL_MAX_RELATIVE);
    CHECK(rect < D_OMEGA_GLSL_MAX_RELATIVE);
}

TEST_CASE("grid estimate: GLSL against C++ for point and extended lights, every variant, and on one lattice point per pixel") {
    const std::size_t n = 20000;
    std::vector<std::uint32_t> in;
    for (std::uint32_t i = 0; i < n; ++i) {
        const float fp = std::exp2(-6.0f + 16.0f * rnd(i, 9));
        const float ratio = std::exp2(5.0f * rnd(i, 10));
        const float ang = 3.1415926f * rnd(i, 11);
        const glm::vec3 h = random_direction(i, 12, 0.7f);
        glint_test::append_words(in, {100.0f * rnd(i, 13), 100.0f * rnd(i, 14), fp * std::cos(ang), fp * std::sin(ang),
                               -fp / ratio * std::sin(ang), fp / ratio * std::cos(ang), h.x, h.y, h.z, -4.0f + 10.0f * rnd(i, 15),
                               0.4f * rnd(i, 16)});
    }
    using K = glint::detail::glsl::kernels<float>;
    // v = 5: the mean-preserving sampler on one lattice point per pixel (glint_grid_pixel_setup_stochastic).
    for (int v = 0; v <= 5; ++v) {
        const bool stochastic = v == 5;
        const int variant = std::min(v, 4);
        const std::string estimate = stochastic ? " glint_grid_pixel px = glint_grid_pixel_setup_stochastic(uv, dx, dy, g, glint_unit_from_bits(glint_hash_u32(i * 2654435761u)));"
                                                  " glint_grid_estimate e = glint_grid_sample_pixel(px, g, l);"
                                                : " glint_grid_estimate e = glint_grid_sample(uv, dx, dy, g, l);";
        const std::string body =
            "uint b = 11u * i; vec2 uv = in_vec2(b); vec2 dx = in_vec2(b+2u); vec2 dy = in_vec2(b+4u); vec3 h = in_vec3(b+6u);"
            " glint_grid_params g; g.log_density = in_float(b+9u); g.density_sigma = ((i & 2u) != 0u) ? 0.3 : 0.0;"
            " g.lod_scale = 1.5; g.slope_cell = 0.02; g.smooth_tolerance = 0.0; g.variant = " + std::to_string(variant) +
            "; g.pow_method = " + std::to_string(static_cast<int>(glint::published_pow_method(static_cast<glint::binomial_variant>(variant)))) +
            "; g.seed = i * 747796405u;"
            " glint_grid_light l; l.kind = int(i & 1u); l.p = in_float(b+10u); l.slope = -h.xy / h.z; l.ndf = 0;"
            " l.alpha = vec2(0.2, 0.1); l.total_area = glint_total_area(0, l.alpha);"
            + estimate + " out0[2u*i] = floatBitsToUint(e.value); out0[2u*i+1u] = floatBitsToUint(e.expected);";
        const auto gpu = glint_test::from_words<float>(glint_test::map_words(grid_files, body, in, n, 2));
        std::size_t differing = 0, non_finite = 0, identical = 0;
        double worst_expected = 0, worst_agreeing = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const auto w = glint_test::from_words<float>(std::vector<std::uint32_t>(in.begin() + 11 * i, in.begin() + 11 * i + 11));
            K::glint_grid_params g;
            g.log_density = w[9], g.density_sigma = (i & 2u) ? 0.3f : 0.0f, g.lod_scale = 1.5f, g.slope_cell = 0.02f, g.smooth_tolerance = 0.0f;
            g.variant = variant, g.pow_method = static_cast<int>(glint::published_pow_method(static_cast<glint::binomial_variant>(variant)));
            g.seed = i * 747796405u;
            K::glint_grid_light l;
            l.kind = static_cast<int>(i & 1u), l.p = w[10], l.slope = -glm::vec2(w[6], w[7]) / w[8], l.ndf = 0;
            l.alpha = glm::vec2(0.2f, 0.1f), l.total_area = K::glint_total_area(0, l.alpha);
            K::glint_grid_estimate e;
            if (stochastic) {
                auto px = K::glint_grid_pixel_setup_stochastic(glm::vec2(w[0], w[1]), glm::vec2(w[2], w[3]), glm::vec2(w[4], w[5]), g,
                                                               K::glint_unit_from_bits(K::glint_hash_u32(i * 2654435761u)));
                e = K::glint_grid_sample_pixel(px, g, l);
            } else {
                e = K::glint_grid_sample(glm::vec2(w[0], w[1]), glm::vec2(w[2], w[3]), glm::vec2(w[4], w[5]), g, l);
            }
            const float gv = gpu[2 * i], ge = gpu[2 * i + 1];
            non_finite += !std::isfinite(gv) || !std::isfinite(ge);
            worst_expected = std::max(worst_expected, std::fabs(static_cast<double>(ge - e.expected)) / std::max(1e-30, static_cast<double>(e.expected)));
            const double d = std::fabs(static_cast<double>(gv - e.value)) / std::max({static_cast<double>(e.value), static_cast<double>(e.expected), 1e-30});
            identical += gv == e.value;
            if (d > GRID_GLSL_AGREEMENT && differing < 3)
                MESSAGE("  differs: GLSL " << gv << ", C++ " << e.value << ", E[R] " << e.expected << ", draws " << e.draws << ", ln density "
                                           << w[9] << ", footprint " << std::hypot(w[2], w[3]) << ", light kind " << (i & 1u));
            if (d > GRID_GLSL_AGREEMENT) ++differing;
            else worst_agreeing = std::max(worst_agreeing, d);
        }
        const double rate = static_cast<double>(differing) / static_cast<double>(n);
        MESSAGE(std::string(glint::name(static_cast<glint::binomial_variant>(variant))) << std::string(stochastic ? ", one lattice point" : "")
                << ": " << n << " estimates, " << identical << " identical, " << differing << " differ by more than "
                << GRID_GLSL_AGREEMENT << " of max(R, E[R]) (rate " << rate << "), the others within " << worst_agreeing
                << "; E[R] within " << worst_expected);
        CHECK(non_finite == 0u);
        CHECK(worst_expected < MICROFACET_GLSL_MAX_RELATIVE);
        CHECK(rate <= GRID_GLSL_MAX_FLIP_RATE);
    }
}

TEST_CASE("grid estimates for several lights on one footprint: GLSL glint_grid_sample_lights against C++ grid_sample per light") {
    const std::size_t n = 5000;
    const float scale[4] = {1.0f, 0.5f, -0.7f, 1.3f};
    std::vector<std::uint32_t> in;
    for (std::uint32_t i = 0; i < n; ++i) {
        const float fp = std::exp2(-6.0f + 16.0f * rnd(i, 19));
        const glm::vec3 h = random_direction(i, 22, 0.7f);
        glint_test::append_words(in, {100.0f * rnd(i, 23), 100.0f * rnd(i, 24), fp, 0.3f * fp, -0.2f * fp, 0.8f * fp, h.x, h.y, h.z,
                                      -4.0f + 10.0f * rnd(i, 25), 0.4f * rnd(i, 26)});
    }
    const std::string body =
        "uint b = 11u * i; vec2 uv = in_vec2(b); vec2 dx = in_vec2(b+2u); vec2 dy = in_vec2(b+4u); vec3 h = in_vec3(b+6u);"
        " glint_grid_params g; g.log_density = in_float(b+9u); g.density_sigma = 0.0; g.lod_scale = 1.5; g.slope_cell = 0.02;"
        " g.smooth_tolerance = 0.0; g.variant = 4; g.pow_method = 2; g.seed = i * 747796405u;"
        " const float scale[4] = float[4](1.0, 0.5, -0.7, 1.3); glint_grid_light ls[8];"
        " for (int k = 0; k < 8; ++k) { ls[k].kind = k & 1; ls[k].p = in_float(b+10u); ls[k].slope = -h.xy / h.z * scale[k & 3]; ls[k].ndf = 0;"
        " ls[k].alpha = vec2(0.2, 0.1); ls[k].total_area = glint_total_area(0, ls[k].alpha); }"
        " glint_grid_estimates e = glint_grid_sample_lights(uv, dx, dy, g, ls, 4);"
        " for (int k = 0; k < 4; ++k) out0[4u*i+uint(k)] = floatBitsToUint(e.e[k].value);";
    const auto gpu = glint_test::from_words<float>(glint_test::map_words(grid_files, body, in, n, 4));
    using K = glint::detail::glsl::kernels<float>;
    std::size_t differing = 0, non_finite = 0, with_draws = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto w = glint_test::from_words<float>(std::vector<std::uint32_t>(in.begin() + 11 * i, in.begin() + 11 * i + 11));
        K::glint_grid_params g;
        g.log_density = w[9], g.density_sigma = 0, g.lod_scale = 1.5f, g.slope_cell = 0.02f, g.smooth_tolerance = 0;
        g.variant = 4, g.pow_method = 2, g.seed = i * 747796405u;
        for (int k = 0; k < 4; ++k) {
            K::glint_grid_light l;
            l.kind = k & 1, l.p = w[10], l.slope = -glm::vec2(w[6], w[7]) / w[8] * scale[k], l.ndf = 0;
            l.alpha = glm::vec2(0.2f, 0.1f), l.total_area = K::glint_total_area(0, l.alpha);
            const auto e = K::glint_grid_sample(glm::vec2(w[0], w[1]), glm::vec2(w[2], w[3]), glm::vec2(w[4], w[5]), g, l);
            const float gv = gpu[4 * i + static_cast<std::size_t>(k)];
            non_finite += !std::isfinite(gv);
            with_draws += e.draws > 0;
            const double d = std::fabs(static_cast<double>(gv - e.value)) / std::max({static_cast<double>(e.value), static_cast<double>(e.expected), 1e-30});
            differing += d > GRID_GLSL_AGREEMENT;
        }
    }
    const double rate = static_cast<double>(differing) / static_cast<double>(4 * n);
    MESSAGE((4 * n) << " estimates (" << with_draws << " with draws), " << differing << " differ by more than " << GRID_GLSL_AGREEMENT
                  << " of max(R, E[R]) (rate " << rate << ")");
    CHECK(non_finite == 0u);
    CHECK(with_draws > n / 2);  // of 4 n: the comparison covers the draws
    CHECK(rate <= GRID_GLSL_MAX_FLIP_RATE);
}
