// The scene of examples/ibl.cpp (and of glint_gl's IBL frames): a glinty silver sphere under an
// environment map, seen from its own camera; the shading of one pixel given its hit and
// footprint (KK25 Sec. 4-5 through glint::ibl_sample).
#pragma once

#include <cstdint>

#include <glint/ibl.hpp>

#include "lights_scene.hpp"

namespace glint_examples {

struct ibl_settings {
    bool smooth = false;
    std::uint32_t seed = 1;
    float log_density = 5.0f;  // ln(microfacets per unit uv area)
    float roughness = 0.12f;   // GGX alpha of the sphere
    bool stochastic_lattice = false;  // one lattice point per pixel (render_ibl_pixel: lights_scene.hpp's lattice_uniform)
};

inline camera ibl_camera(int width, int height) { return camera(width, height, vec3(0.0f, 0.75f, 3.2f), sphere_centre); }

// The grid parameters of the sphere (the kernels' seed: seed x 0x9E3779B9, the golden ratio in
// 32 bits, so that neighbouring seeds decorrelate).
inline glint::grid_params<float> ibl_grid(const ibl_settings& s) {
    glint::grid_params<float> g;
    g.log_density = s.log_density;
    g.seed = s.seed * 0x9E3779B9u;
    return g;
}

// Radiance towards the eye from the sphere at ht, seen along the unit ray direction d.
inline vec3 shade_ibl(const glint::environment& env, const ibl_settings& s, const hit& ht, const vec3& d, const vec2& duvdx,
                      const vec2& duvdy, float lattice_u = -1.0f) {
    const float sa = std::sqrt(s.roughness);
    const float cos_o = std::max(glm::dot(-d, ht.n), 1e-4f);
    const vec3 r = glm::reflect(d, ht.n);
    vec3 radiance;
    float m = 1.0f;
    if (s.smooth) {
        radiance = env.lookup_radiance(r, sa);  // the K indicators are for the glints only
    } else {
        const auto look = env.lookup(r, sa);
        radiance = look.radiance;
        const auto g = ibl_grid(s);
        auto px = glint::grid_pixel_setup(ht.uv, duvdx, duvdy, g, lattice_u);  // lattice_u < 0: every lattice point
        const auto e = glint::ibl_sample(px, g, env.levels(), look.indicators, env.visible_area(cos_o, sa), ggx_total_area(s.roughness));
        m = glint::modulation(e);
    }
    const float albedo = env.albedo(cos_o, sa);
    vec3 L;
    for (int c = 0; c < 3; ++c) L[c] = glint::fresnel_conductor(silver_eta[c], silver_k[c], cos_o) * albedo * radiance[c] * m;
    return L;
}

// The radiance of pixel (x, y): the sphere, or the environment itself (no ground plane here).
inline vec3 render_ibl_pixel(const glint::environment& env, const ibl_settings& s, const camera& cam, int x, int y) {
    const float fx = static_cast<float>(x) + 0.5f, fy = static_cast<float>(y) + 0.5f;
    const vec3 d = cam.ray(fx, fy);
    const hit ht = intersect(cam.eye, d);
    if (!ht.found || !ht.sphere) return env.lookup_radiance(d, 0.0f);
    vec2 duvdx, duvdy;
    footprint_derivatives(cam, ht, fx, fy, duvdx, duvdy);
    return shade_ibl(env, s, ht, d, duvdx, duvdy, pixel_lattice_u(s.stochastic_lattice, x, y, ibl_grid(s).seed));
}

}  // namespace glint_examples
