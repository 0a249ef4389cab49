// The IBL kernels through Mesa llvmpipe: the texture lookup that glint's C++ side computes with
// glint_bilinear against OpenGL's own GL_LINEAR / GL_REPEAT / GL_CLAMP_TO_EDGE filtering, the
// equirectangular mapping, the fuzzy indicator weights, and the multi-level glint estimate
// against the C++ float path.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glint/ibl.hpp>

#include "parity.hpp"
#include "tolerances.hpp"

namespace {

using K = glint::detail::glsl::kernels<float>;

float rnd(std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, salt, 0x1bu)).x); }

}  // namespace

TEST_CASE("ibl: glint_bilinear reproduces OpenGL's GL_LINEAR filtering with GL_REPEAT in u and GL_CLAMP_TO_EDGE in v") {
    const int w = 37, h = 19;
    std::vector<float> rgba(4 * w * h);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = rnd(static_cast<std::uint32_t>(i), 1) * 10.0f;
    const std::size_t n = 50000;
    std::vector<float> uvs;
    for (std::uint32_t i = 0; i < n; ++i) uvs.push_back(-1.5f + 4.0f * rnd(i, 2)), uvs.push_back(-0.2f + 1.4f * rnd(i, 3));
    auto& gl = glint_test::gl();
    const unsigned tex = gl.texture_rgba32f(w, h, rgba);
    const std::string src = glint_test::shader_header({}) +
                            "layout(std430, binding = 0) readonly buffer In { float in0[]; };\n"
                            "layout(std430, binding = 1) writeonly buffer Out { float out0[]; };\n"
                            "layout(binding = 0) uniform sampler2D env;\n"
                            "void main() { uint i = gl_GlobalInvocationID.x; if (i >= " + std::to_string(n) + "u) return;\n"
                            "  vec4 v = textureLod(env, vec2(in0[2u*i], in0[2u*i+1u]), 0.0); out0[i] = v.x; }\n";
    const auto out = glint_test::from_words<float>(gl.run(gl.program(src), {glint_test::to_words(uvs)}, n, n));
    gl.delete_texture(tex);
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
        // GL's row y is the data's row y (t = (y + 1/2) / h): glint_bilinear's v is the same coordinate.
        const auto taps = K::glint_bilinear(glm::vec2(uvs[2 * i], uvs[2 * i + 1]), w, h);
        double v = 0;
        for (int k = 0; k < 4; ++k)
            v += static_cast<double>(taps.weight[k] * rgba[4 * (static_cast<std::size_t>(taps.texel[k].y) * w + static_cast<std::size_t>(taps.texel[k].x))]);
        worst = std::max(worst, std::fabs(v - static_cast<double>(out[i])));
    }
    MESSAGE(n << " lookups: max |C++ - OpenGL| = " << worst << " (texel values up to 10)");
    CHECK(worst < IBL_FILTER_GLSL_MAX_ABSOLUTE * 10);
}

// Half the estimates (i & 4) on one lattice point per pixel (glint_grid_pixel_setup_stochastic).
TEST_CASE("ibl: equirectangular mapping, fuzzy weights and the glint estimate: GLSL against C++") {
    const std::size_t n = 20000;
    std::vector<float> in;
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t k = 0; k < 12; ++k) in.push_back(rnd(i, 10 + k));
    const std::string body =
        "uint b = 12u * i; float r[12]; for (uint k = 0u; k < 12u; ++k) r[k] = in_float(b + k);"
        " vec3 d = glint_equirect_direction(vec2(r[0], r[1])); vec2 uv = glint_equirect_uv(d);"
        " glint_ibl_levels lv; lv.count = ((i & 1u) != 0u) ? 8 : 4;"
        " for (int k = 0; k < 8; ++k) lv.radiance[k] = glint_ibl_level(k, lv.count, 0.01, 3.0e4);"
        " vec2 jt = glint_ibl_fuzzy_weight(3.0e4 * r[2] * r[2] * r[2] * r[2], lv, (i & 2u) != 0u);"
        " glint_ibl_indicators ind; float s = 0.0; for (int k = 0; k < 8; ++k) { ind.w[k] = (k < lv.count) ? r[3 + k] : 0.0; s += ind.w[k]; }"
        " for (int k = 0; k < 8; ++k) ind.w[k] /= s;"
        " glint_grid_params g; g.log_density = -2.0 + 10.0 * r[11]; g.density_sigma = 0.0; g.lod_scale = 1.5; g.slope_cell = 0.02;"
        " g.smooth_tolerance = 0.0; g.variant = 4; g.pow_method = 2; g.seed = i * 747796405u;"
        " float lattice_u = ((i & 4u) != 0u) ? glint_unit_from_bits(glint_hash_u32(i * 2654435761u)) : -1.0;"
        " glint_grid_pixel px = glint_grid_pixel_setup_stochastic(vec2(r[0], r[1]) * 100.0, vec2(1.0, 0.1), vec2(-0.2, 0.8), g, lattice_u);"
        " glint_grid_estimate e = glint_ibl_sample_pixel(px, g, lv, ind, 0.9, 1.1);"
        " out0[6u*i] = floatBitsToUint(d.x); out0[6u*i+1u] = floatBitsToUint(uv.x); out0[6u*i+2u] = floatBitsToUint(uv.y);"
        " out0[6u*i+3u] = floatBitsToUint(jt.x + jt.y); out0[6u*i+4u] = floatBitsToUint(e.value); out0[6u*i+5u] = floatBitsToUint(e.expected);";
    const auto gpu = glint_test::from_words<float>(glint_test::map_words(
        {"core.glsl", "binomial.glsl", "multinomial.glsl", "microfacet.glsl", "grid.glsl", "ibl.glsl"}, body, glint_test::to_words(in), n, 6));
    double worst_map = 0, worst_weight = 0, worst_expected = 0;
    std::size_t differing = 0, differing_one_point = 0, one_points = 0, non_finite = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const float* r = &in[12 * i];
        const glm::vec3 d = K::glint_equirect_direction(glm::vec2(r[0], r[1]));
        const glm::vec2 uv = K::glint_equirect_uv(d);
        K::glint_ibl_levels lv;
        lv.count = (i & 1u) ? 8 : 4;
        for (int k = 0; k < 8; ++k) lv.radiance[k] = K::glint_ibl_level(k, lv.count, 0.01f, 3.0e4f);
        const glm::vec2 jt = K::glint_ibl_fuzzy_weight(3.0e4f * r[2] * r[2] * r[2] * r[2], lv, (i & 2u) != 0u);
        K::glint_ibl_indicators ind;
        float s = 0;
        for (int k = 0; k < 8; ++k) ind.w[k] = k < lv.count ? r[3 + k] : 0.0f, s += ind.w[k];
        for (int k = 0; k < 8; ++k) ind.w[k] /= s;
        K::glint_grid_params g;
        g.log_density = -2.0f + 10.0f * r[11], g.density_sigma = 0, g.lod_scale = 1.5f, g.slope_cell = 0.02f, g.smooth_tolerance = 0;
        g.variant = 4, g.pow_method = 2, g.seed = i * 747796405u;
        const bool one_point = (i & 4u) != 0;
        const float lattice_u = one_point ? K::glint_unit_from_bits(K::glint_hash_u32(i * 2654435761u)) : -1.0f;
        auto px = K::glint_grid_pixel_setup_stochastic(glm::vec2(r[0], r[1]) * 100.0f, glm::vec2(1.0f, 0.1f), glm::vec2(-0.2f, 0.8f), g, lattice_u);
        const auto e = K::glint_ibl_sample_pixel(px, g, lv, ind, 0.9f, 1.1f);
        const float* o = &gpu[6 * i];
        for (int k = 0; k < 6; ++k) non_finite += !std::isfinite(o[k]);
        worst_map = std::max({worst_map, static_cast<double>(std::fabs(o[0] - d.x)), static_cast<double>(std::fabs(o[1] - uv.x)),
                              static_cast<double>(std::fabs(o[2] - uv.y))});
        worst_weight = std::max(worst_weight, static_cast<double>(std::fabs(o[3] - (jt.x + jt.y))));
        worst_expected = std::max(worst_expected, static_cast<double>(std::fabs(o[5] - e.expected) / e.expected));
        const bool differs = std::fabs(static_cast<double>(o[4] - e.value)) > GRID_GLSL_AGREEMENT * std::max(static_cast<double>(e.value), static_cast<double>(e.expected));
        differing += differs;
        differing_one_point += differs && one_point;
        one_points += one_point;
    }
    const double rate = static_cast<double>(differing) / static_cast<double>(n);
    MESSAGE("equirect max difference " << worst_map << ", fuzzy weight (j + t) " << worst_weight << ", E[estimate] relative " << worst_expected
                                       << "; estimates differing by more than " << GRID_GLSL_AGREEMENT << ": " << differing << " of " << n << " ("
                                       << differing_one_point << " of the " << one_points << " on one lattice point)");
    CHECK(one_points > n / 3);
    CHECK(non_finite == 0u);
    CHECK(worst_map < IBL_EQUIRECT_GLSL_MAX_ABSOLUTE);
    CHECK(worst_weight < 1e-4);
    CHECK(worst_expected < MICROFACET_GLSL_MAX_RELATIVE);
    CHECK(rate <= GRID_GLSL_MAX_FLIP_RATE);
}
