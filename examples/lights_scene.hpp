// The scene of examples/lights.cpp (and of the frame-cost benchmark): a glinty silver sphere on
// a dark glinty plane, under a point light, the sun, or a rectangular area light, ray cast on the
// CPU. Each pixel's footprint comes from ray differentials; the glint BRDF is the smooth
// microfacet BRDF times glint::modulation of the grid estimate (glint/grid.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glint/grid.hpp>
#include <glint/microfacet.hpp>

#include "support/render.hpp"

namespace glint_examples {

using vec2 = glm::vec2;
using vec3 = glm::vec3;

enum class light_type { point, sun, area };

inline const char* name(light_type t) { return t == light_type::point ? "point" : t == light_type::sun ? "sun" : "area"; }

struct scene_options {
    light_type light = light_type::sun;
    bool smooth = false;
    std::uint32_t seed = 1;
    float log_density = 5.0f;  // ln(microfacets per unit uv area); uv = 100 x surface length
    float roughness = 0.12f;   // GGX alpha of both surfaces
    glint::binomial_variant variant = glint::binomial_variant::unbiased;
    float smooth_tolerance = 0.01f;  // glint::grid_params::smooth_tolerance
    bool stochastic_lattice = false;  // one lattice point per pixel (glint::grid_pixel_setup with lattice_uniform's u)
    int width = 800, height = 500;
};

// The uniform that picks pixel (x, y)'s lattice point where stochastic_lattice is on: a hash of the
// pixel and the scene's grid seed, white noise over pixels, the same for every renderer of the
// frame (glint_gl's shaders: glint_gl_lattice_u), new with every seed.
inline float lattice_uniform(int x, int y, std::uint32_t seed) {
    const glm::uvec3 key(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed ^ 0x5bd1e995u);  // MurmurHash2's constant: any salt
    return glint::unit_from_bits<float>(glint::pcg3d(key).x);
}

// The lattice_u a renderer of these scenes passes: lattice_uniform where one lattice point is on,
// else -1 (every lattice point).
inline float pixel_lattice_u(bool one_lattice_point, int x, int y, std::uint32_t seed) {
    return one_lattice_point ? lattice_uniform(x, y, seed) : -1.0f;
}

struct hit {
    bool found = false;
    bool sphere = false;
    vec3 p{}, n{}, t{}, b{};  // position and tangent frame (t, b, n)
    vec2 uv{};
    float distance = 0;
};

constexpr float uv_per_unit = 100.0f;  // microfacet-grid uv per unit of surface length
const vec3 sphere_centre(0.0f, 0.75f, 0.0f);
constexpr float sphere_radius = 0.75f;

// The sphere's tangent frame at a hit whose normal h.n is set: t along increasing phi, b = n x t.
inline void sphere_frame(hit& h) {
    const float s = std::max(std::sqrt(h.n.x * h.n.x + h.n.z * h.n.z), 1e-6f);
    h.t = vec3(-h.n.z / s, 0.0f, h.n.x / s);
    h.b = glm::cross(h.n, h.t);
}

inline hit intersect(const vec3& o, const vec3& d) {
    hit h;
    // Sphere.
    const vec3 oc = o - sphere_centre;
    const float bq = glm::dot(oc, d), cq = glm::dot(oc, oc) - sphere_radius * sphere_radius, disc = bq * bq - cq;
    if (disc > 0) {
        const float t = -bq - std::sqrt(disc);
        if (t > 1e-4f) {
            h.found = true, h.sphere = true, h.distance = t;
            h.p = o + t * d;
            h.n = glm::normalize(h.p - sphere_centre);
            const float phi = std::atan2(h.n.z, h.n.x), theta = std::acos(glm::clamp(h.n.y, -1.0f, 1.0f));
            h.uv = vec2(phi, theta) * (sphere_radius * uv_per_unit);
            sphere_frame(h);
        }
    }
    // Plane y = 0.
    if (d.y < 0) {
        const float t = -o.y / d.y;
        if (t > 1e-4f && (!h.found || t < h.distance)) {
            h.found = true, h.sphere = false, h.distance = t;
            h.p = o + t * d;
            h.n = vec3(0, 1, 0), h.t = vec3(1, 0, 0), h.b = vec3(0, 0, -1);
            h.uv = vec2(h.p.x, -h.p.z) * uv_per_unit;
        }
    }
    return h;
}

// uv derivative of a world displacement in the tangent plane at h.
inline vec2 uv_of_displacement(const hit& h, const vec3& disp) {
    if (!h.sphere) return vec2(disp.x, -disp.z) * uv_per_unit;
    const float s = std::max(std::sqrt(h.n.x * h.n.x + h.n.z * h.n.z), 1e-3f);
    // u = phi r, v = theta r: du = (disp . e_phi) / sin(theta), dv = disp . e_theta (e_theta = b).
    return vec2(glm::dot(disp, h.t) / s, glm::dot(disp, h.b)) * uv_per_unit;
}

struct camera {
    vec3 eye, target;
    float fov_y = 0.62f;  // radians
    int width, height;
    vec3 forward, right, up;
    camera(int w, int h, vec3 eye_at = vec3(0.0f, 1.25f, 4.2f), vec3 looking_at = vec3(0.0f, 0.55f, 0.0f))
        : eye(eye_at), target(looking_at), width(w), height(h) {
        forward = glm::normalize(target - eye);
        right = glm::normalize(glm::cross(forward, vec3(0, 1, 0)));
        up = glm::cross(right, forward);
    }
    vec3 ray(float x, float y) const {
        const float s = 2 * std::tan(0.5f * fov_y) / static_cast<float>(height);
        return glm::normalize(forward + right * ((x - 0.5f * static_cast<float>(width)) * s) - up * ((y - 0.5f * static_cast<float>(height)) * s));
    }
};

// Spectral data (per RGB channel): silver for the sphere; aluminium flakes on the plane.
const vec3 silver_eta(0.155f, 0.117f, 0.138f), silver_k(4.83f, 3.12f, 2.15f);
const vec3 flake_eta(1.2f, 0.96f, 0.67f), flake_k(7.2f, 6.4f, 5.3f);
const vec3 plane_diffuse(0.010f, 0.012f, 0.022f);
constexpr float flake_coverage = 0.5f;

struct light_setup {
    light_type type;
    vec3 position{2.6f, 3.2f, 1.2f};  // point light
    float intensity = 28.0f;          // point light, radiant intensity per channel
    vec3 sun_dir = glm::normalize(vec3(-0.35f, 0.22f, -1.0f));
    float sun_radius = 0.00454f;  // 0.26 degrees
    float sun_irradiance = 0.8f;
    vec3 rect_corner{-1.9f, 0.9f, -2.6f}, rect_e1{1.8f, 0.0f, 0.0f}, rect_e2{0.0f, 1.1f, 0.5f};
    float rect_radiance = 5.0f;
};

// A dusk sky behind the scene, also mirrored (smoothly, without glints) by the sphere.
inline vec3 background(const vec3& d) {
    if (d.y < 0) return vec3(0.004f, 0.004f, 0.005f);  // the plane, seen in the sphere
    const float t = glm::clamp(d.y * 2.5f, 0.0f, 1.0f);
    return glm::mix(vec3(0.060f, 0.045f, 0.050f), vec3(0.010f, 0.016f, 0.040f), t);
}

// The grid parameters of both surfaces; shade() adds 1 (sphere) or 2 (plane) to the seed, which
// is seed x 0x9E3779B9 (the golden ratio in 32 bits, so that neighbouring seeds decorrelate).
inline glint::grid_params<float> lights_grid(const scene_options& opt) {
    glint::grid_params<float> g;
    g.log_density = opt.log_density;
    g.variant = opt.variant;
    g.smooth_tolerance = opt.smooth_tolerance;
    g.seed = opt.seed * 0x9E3779B9u;
    return g;
}

// D_H of GGX at alpha = roughness (glint::total_area), which only the glints need. It depends on
// the roughness alone, a material constant in these scenes, so it is computed once per roughness
// and thread, as glint::total_area advises ("once per material") and bench/report_ibl.cpp's frames
// always did; a renderer with a roughness texture would pay it per pixel (until 2026-12-05 these
// scenes did: about 8% of the point-light glint frame, perf).
inline float ggx_total_area(float roughness) {
    thread_local float cached_roughness = -1.0f, cached = 1.0f;
    if (roughness != cached_roughness) cached = glint::total_area(glint::ndf::ggx, vec2(roughness)), cached_roughness = roughness;
    return cached;
}

struct shading_counters {
    std::uint64_t draws = 0;
};

inline vec3 to_local(const hit& h, const vec3& w) { return {glm::dot(w, h.t), glm::dot(w, h.b), glm::dot(w, h.n)}; }

// A hit's shading in two halves, so that a renderer can batch the glint estimates of many pixels
// (render_row): shade_begin computes everything but the glint factor, shade_finish adds the
// specular (times the factor, if any) with its Fresnel terms.
struct shading_partial {
    vec3 result{0};          // the radiance without the light's specular
    float specular = 0;      // the smooth specular without Fresnel (not positive: none)
    float cos_h = 0;         // dot(wi, h), for the Fresnel terms
    bool sphere = false;
    bool glint = false;      // whether specular waits for the factor glint::modulation(e) of the estimate
    glint::grid_light<float> light{};  // e = grid_sample(px, surface_grid(opt, sphere), light)
};

// The grid of a hit's surface: lights_grid's seed plus 1 (sphere) or 2 (plane).
inline glint::grid_params<float> surface_grid(const scene_options& opt, bool sphere) {
    glint::grid_params<float> g = lights_grid(opt);
    g.seed += sphere ? 1u : 2u;
    return g;
}

// wo_world: unit vector towards the eye.
inline shading_partial shade_begin(const scene_options& opt, const light_setup& ls, const hit& h, const vec3& wo_world) {
    shading_partial out;
    out.sphere = h.sphere;
    const vec2 alpha(opt.roughness);
    const vec3 wo = to_local(h, wo_world);
    if (!(wo.z > 0)) return out;
    // The sky mirrored by the sphere (a smooth ambient term, the same with or without glints).
    vec3 ambient(0);
    if (h.sphere) {
        const vec3 r = glm::reflect(-wo_world, h.n);
        for (int k = 0; k < 3; ++k) ambient[k] = glint::fresnel_conductor(silver_eta[k], silver_k[k], wo.z) * background(r)[k];
    }
    vec3 wi_c;           // direction to the light (its centre), local
    float d_omega = 0;   // extended lights
    vec3 irradiance(0);  // for the diffuse term, per channel (grey light)
    float radiance = 0;  // extended lights
    float point_scale = 0;
    switch (ls.type) {
        case light_type::point: {
            const vec3 d = ls.position - h.p;
            const float d2 = glm::dot(d, d);
            wi_c = to_local(h, d / std::sqrt(d2));
            point_scale = ls.intensity / d2;
            irradiance = vec3(point_scale * std::max(wi_c.z, 0.0f));
            break;
        }
        case light_type::sun: {
            wi_c = to_local(h, ls.sun_dir);
            radiance = ls.sun_irradiance / (2 * 3.14159265f * (1 - std::cos(ls.sun_radius)));
            irradiance = vec3(ls.sun_irradiance * std::max(wi_c.z, 0.0f));
            d_omega = glint::integrated_ndf_cone(glint::ndf::ggx, wo, alpha, wi_c, ls.sun_radius);
            break;
        }
        case light_type::area: {
            const vec3 p0 = to_local(h, ls.rect_corner - h.p), e1 = to_local(h, ls.rect_e1), e2 = to_local(h, ls.rect_e2);
            const vec3 c = p0 + 0.5f * (e1 + e2);
            const float len = glm::length(c);
            wi_c = c / len;
            radiance = ls.rect_radiance;
            const float solid = glm::length(glm::cross(e1, e2)) * std::max(0.0f, -glm::dot(glm::normalize(glm::cross(e1, e2)), wi_c)) / (len * len);
            irradiance = vec3(radiance * solid * std::max(wi_c.z, 0.0f));
            d_omega = glint::integrated_ndf_rect(glint::ndf::ggx, wo, alpha, p0, e1, e2);
            break;
        }
    }
    out.result = h.sphere ? ambient : plane_diffuse / 3.14159265f * irradiance;
    if (!(wi_c.z > 0) && ls.type == light_type::point) return out;
    const vec3 hv = glm::normalize(wi_c + wo);
    const float g2 = glint::smith_g2(glint::ndf::ggx, wi_c, wo, hv, alpha);
    if (!(g2 > 0)) return out;
    if (ls.type == light_type::point)
        out.specular = g2 * glint::ndf_value(glint::ndf::ggx, hv, alpha) * point_scale / (4 * wo.z);
    else
        out.specular = g2 * radiance * glm::dot(hv, wi_c) * d_omega / wo.z;
    if (!(out.specular > 0)) return out;
    out.cos_h = glm::dot(wi_c, hv);
    if (!opt.smooth) {
        const float dh = ggx_total_area(opt.roughness);
        out.glint = true;
        out.light = ls.type == light_type::point ? glint::grid_point_light(glint::ndf::ggx, alpha, dh, hv)
                                                 : glint::grid_extended_light(std::min(1.0f, d_omega / dh), hv);
    }
    return out;
}

inline vec3 shade_finish(const shading_partial& s) {
    vec3 result = s.result;
    if (!s.glint && !(s.specular > 0)) return result;  // a glint's specular is added even where its factor made it 0
    for (int k = 0; k < 3; ++k) {
        const float f = s.sphere ? glint::fresnel_conductor(silver_eta[k], silver_k[k], s.cos_h)
                                 : flake_coverage * glint::fresnel_conductor(flake_eta[k], flake_k[k], s.cos_h);
        result[k] += f * s.specular;
    }
    return result;
}

// Radiance towards the eye from hit h (wo: unit vector towards the eye, world), one pixel at a time.
inline vec3 shade(const scene_options& opt, const light_setup& ls, const hit& h, const vec3& wo_world, const vec2& duvdx, const vec2& duvdy,
                  shading_counters& counters, float lattice_u = -1.0f) {
    shading_partial s = shade_begin(opt, ls, h, wo_world);
    if (s.glint) {
        const glint::grid_params<float> g = surface_grid(opt, h.sphere);
        auto px = glint::grid_pixel_setup(h.uv, duvdx, duvdy, g, lattice_u);  // lattice_u < 0: every lattice point
        const auto e = glint::grid_sample(px, g, s.light);
        counters.draws += static_cast<std::uint64_t>(e.draws);
        s.specular *= glint::modulation(e);
    }
    return shade_finish(s);
}

// The radiance of pixel (x, y).
// The pixel footprint's uv derivatives at hit h of the ray through (fx, fy), by ray
// differentials: the neighbouring pixels' rays meet the tangent plane at h.
inline void footprint_derivatives(const camera& cam, const hit& h, float fx, float fy, vec2& duvdx, vec2& duvdy) {
    auto on_plane = [&](const vec3& dn) {
        const float t = glm::dot(h.p - cam.eye, h.n) / std::min(glm::dot(dn, h.n), -1e-6f);
        return cam.eye + t * dn - h.p;
    };
    duvdx = uv_of_displacement(h, on_plane(cam.ray(fx + 1, fy)));
    duvdy = uv_of_displacement(h, on_plane(cam.ray(fx, fy + 1)));
}

// Every pixel of cam on every core, with progress (render_rows): the ray through its centre and
// its first hit; shade(x, y, d, hit, duvdx, duvdy) gives a hit's radiance (duvdx, duvdy the
// footprint's uv derivatives), miss(d) a missed ray's. Fills rgb (w x h, row-major RGB).
template <class Shade, class Miss>
render_timing render_scene(const camera& cam, const std::string& label, std::vector<float>& rgb, Shade shade, Miss miss) {
    const int w = cam.width, h = cam.height;
    rgb.assign(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
    return render_rows(h, label, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const float fx = static_cast<float>(x) + 0.5f, fy = static_cast<float>(y) + 0.5f;
            const vec3 d = cam.ray(fx, fy);
            const hit ht = intersect(cam.eye, d);
            vec3 L;
            if (!ht.found) {
                L = miss(d);
            } else {
                vec2 duvdx, duvdy;
                footprint_derivatives(cam, ht, fx, fy, duvdx, duvdy);
                L = shade(x, y, d, ht, duvdx, duvdy);
            }
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
            rgb[i] = L.x, rgb[i + 1] = L.y, rgb[i + 2] = L.z;
        }
    });
}

inline vec3 render_pixel(const scene_options& opt, const light_setup& ls, const camera& cam, int x, int y, shading_counters& counters) {
    const float fx = static_cast<float>(x) + 0.5f, fy = static_cast<float>(y) + 0.5f;
    const vec3 d = cam.ray(fx, fy);
    const hit h = intersect(cam.eye, d);
    if (!h.found) return background(d);
    vec2 duvdx, duvdy;
    footprint_derivatives(cam, h, fx, fy, duvdx, duvdy);
    return shade(opt, ls, h, -d, duvdx, duvdy, counters, pixel_lattice_u(opt.stochastic_lattice, x, y, lights_grid(opt).seed));
}


// Pixels x0 .. x1 - 1 of row y into out[0 .. x1 - x0): render_pixel's values bit for bit, with
// the glint estimates of up to 32 pixels at a time batched per surface through
// glint::grid_pixels_setup and glint::grid_sample_pixels (eight pixels a vector where the CPU has
// AVX2), as a renderer that shades a tile of pixels would; nothing allocated.
inline void render_row(const scene_options& opt, const light_setup& ls, const camera& cam, int y, int x0, int x1, vec3* out,
                       shading_counters& counters) {
    constexpr int chunk = 32;
    const glint::grid_params<float> g[2] = {surface_grid(opt, true), surface_grid(opt, false)};  // sphere, plane
    const std::uint32_t lattice_seed = lights_grid(opt).seed;
    shading_partial part[chunk];
    vec2 uv[2][chunk], duvdx[2][chunk], duvdy[2][chunk];
    float lattice_u[2][chunk];
    glint::grid_pixel<float> px[chunk];
    glint::grid_light<float> lights[2][chunk];
    glint::grid_estimate<float> e[chunk];
    int index[2][chunk];
    for (int a = x0; a < x1; a += chunk) {
        const int b = std::min(a + chunk, x1);
        int count[2] = {0, 0};
        for (int x = a; x < b; ++x) {
            shading_partial& s = part[x - a];
            const float fx = static_cast<float>(x) + 0.5f, fy = static_cast<float>(y) + 0.5f;
            const vec3 d = cam.ray(fx, fy);
            const hit h = intersect(cam.eye, d);
            if (!h.found) {
                s = shading_partial();
                s.result = background(d);
                continue;
            }
            s = shade_begin(opt, ls, h, -d);
            if (!s.glint) continue;
            const int surface = h.sphere ? 0 : 1, k = count[surface]++;
            footprint_derivatives(cam, h, fx, fy, duvdx[surface][k], duvdy[surface][k]);
            uv[surface][k] = h.uv;
            lattice_u[surface][k] = pixel_lattice_u(opt.stochastic_lattice, x, y, lattice_seed);
            lights[surface][k] = s.light;
            index[surface][k] = x - a;
        }
        for (int surface = 0; surface < 2; ++surface) {
            const auto n = static_cast<std::size_t>(count[surface]);
            glint::grid_pixels_setup(n, uv[surface], duvdx[surface], duvdy[surface], g[surface], lattice_u[surface], px);
            glint::grid_sample_pixels(px, g[surface], lights[surface], n, e);
            for (int k = 0; k < count[surface]; ++k) {
                part[index[surface][k]].specular *= glint::modulation(e[k]);
                counters.draws += static_cast<std::uint64_t>(e[k].draws);
            }
        }
        for (int x = a; x < b; ++x) out[x - x0] = shade_finish(part[x - a]);
    }
}

}  // namespace glint_examples
