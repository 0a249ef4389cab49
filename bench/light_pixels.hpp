// The several-lights workload of the report's grid section (bench/report_grid.cpp) and of
// glint_frame_loop's "lights" mode, so that callgrind counts what the report times.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glint/core.hpp>
#include <glint/grid.hpp>
#include <glint/microfacet.hpp>

namespace glint_bench {

// Several point lights on glinty pixels: 1024 pixels of the showcase's flake paint (GGX, alpha
// 0.25, ln density 5, footprints of 0.4 to 0.8 uv units, N about 20 to 80), 16 point lights each.
struct light_pixels {
    static constexpr int pixels = 1024, lights = 16;
    std::vector<glm::vec2> uv, duvdx, duvdy;
    std::vector<glm::vec3> wo, wi;  // wi: lights per pixel
    light_pixels() {
        for (int i = 0; i < pixels; ++i) {
            auto r = [&](std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), salt, 0x51u)).x); };
            uv.push_back(glm::vec2(100 * r(1), 100 * r(2)));
            const float s = 0.4f + 0.4f * r(3);
            duvdx.push_back(glm::vec2(s, 0.1f * s)), duvdy.push_back(glm::vec2(-0.05f * s, s));
            const float a = 0.6f * r(4), b = 6.2831853f * r(5);
            wo.push_back(glm::vec3(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a)));
            for (int l = 0; l < lights; ++l) {
                const float c = 0.9f * r(10 + static_cast<std::uint32_t>(l)), d = 6.2831853f * r(30 + static_cast<std::uint32_t>(l));
                wi.push_back(glm::vec3(std::sin(c) * std::cos(d), std::sin(c) * std::sin(d), std::cos(c)));
            }
        }
    }
};

// The smooth specular of one point light (GGX D, Smith G2, silver's conductor Fresnel per channel,
// unit intensity), as the showcase shades it, and its half vector.
inline glm::vec3 smooth_point(const glm::vec3& wi, const glm::vec3& wo, glm::vec3& hv) {
    const glm::vec2 alpha(0.25f);
    hv = glm::normalize(wi + wo);
    const float spec = glint::smith_g2(glint::ndf::ggx, wi, wo, hv, alpha) * glint::ndf_value(glint::ndf::ggx, hv, alpha) / (4 * wo.z);
    const float c = glm::dot(wi, hv);
    return spec * glm::vec3(glint::fresnel_conductor(0.155f, 4.83f, c), glint::fresnel_conductor(0.117f, 3.12f, c), glint::fresnel_conductor(0.138f, 2.15f, c));
}

// Pixel i's glint parameters (the flake paint's density, a seed per pixel) and, in mode 3, its
// uniform that picks one lattice point (-1 otherwise: all four).
inline glint::grid_params<float> light_pixel_params(int i) {
    glint::grid_params<float> g;
    g.log_density = 5, g.seed = static_cast<std::uint32_t>(i);
    return g;
}

inline float light_pixel_lattice_u(int i, int mode) {
    return mode == 3 ? glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 0x1a77u, 0x51u)).x) : -1.0f;
}

// Pixel i of lp shaded by its first k lights. mode 0: smooth; 1: glints on one footprint shared by
// every light (grid_pixel and the list of lights, grid_sample_lights); 2: glints through a
// footprint of each light's own (grid_sample each); 3: as 1 on one lattice point drawn per pixel
// (grid_pixel_setup with a lattice_u); 4: as 1, one light at a time (grid_sample(px, ...) each).
inline glm::vec3 shade_light_pixel(const light_pixels& lp, int i, int k, int mode) {
    const auto at = static_cast<std::size_t>(i);
    const glint::grid_params<float> g = light_pixel_params(i);
    const float dh = glint::total_area(glint::ndf::ggx, glm::vec2(0.25f));
    const glm::vec3* wi = lp.wi.data() + i * light_pixels::lights;
    glm::vec3 sum(0);
    auto px = glint::grid_pixel_setup(lp.uv[at], lp.duvdx[at], lp.duvdy[at], g, light_pixel_lattice_u(i, mode));
    if (mode == 0 || mode == 2 || mode == 4) {
        for (int l = 0; l < k; ++l) {
            glm::vec3 hv;
            const glm::vec3 c = smooth_point(wi[l], lp.wo[at], hv);
            if (mode == 0) {
                sum += c;
                continue;
            }
            const auto light = glint::grid_point_light(glint::ndf::ggx, glm::vec2(0.25f), dh, hv);
            const auto e = mode == 4 ? glint::grid_sample(px, g, light) : glint::grid_sample(lp.uv[at], lp.duvdx[at], lp.duvdy[at], g, light);
            sum += c * glint::modulation(e);
        }
        return sum;
    }
    glm::vec3 colour[light_pixels::lights];
    glint::grid_light<float> light[light_pixels::lights];
    glint::grid_estimate<float> e[light_pixels::lights];
    for (int l = 0; l < k; ++l) {
        glm::vec3 hv;
        colour[l] = smooth_point(wi[l], lp.wo[at], hv);
        light[l] = glint::grid_point_light(glint::ndf::ggx, glm::vec2(0.25f), dh, hv);
    }
    glint::grid_sample_lights(px, g, light, static_cast<std::size_t>(k), e);
    for (int l = 0; l < k; ++l) sum += colour[l] * glint::modulation(e[l]);
    return sum;
}

}  // namespace glint_bench
