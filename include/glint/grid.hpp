// The discrete glint NDF on anisotropic grids (kernels/grid.glsl; GLSL users include core.glsl,
// binomial.glsl and microfacet.glsl first): DB23's grid with KK24's area lights and KK25's fixes.
//
//   glint::grid_params<float> g;                 // density, variant, tolerances (below)
//   auto light = glint::grid_extended_light(p, h);    // p = D_Omega / D_H, h towards the light
//   auto e = glint::grid_sample(uv, duvdx, duvdy, g, light);
//   radiance = smooth_radiance * glint::modulation(e);   // mean: smooth_radiance, exactly
//
// How it works (KK25 Eq. 7 and 10). A footprint holding N = density x area microfacets (uv
// units) sees c ~ b(N, p) of them reflect the light, p the probability that one microfacet
// does. The footprint's ellipse picks four lattice points (LOD, aspect-ratio level, rotation)
// with weights w_L summing to 1 (glint_footprint_lattice: a conforming triangulation of ratio x
// angle, times LOD, split into tetrahedra); each lattice point owns a rotated, stretched
// triangle grid in uv whose three vertices around the shading point carry barycentric weights
// l_t; each vertex draws, for each of the four corners of the half-vector slope cell (bilinear
// weights m_j), c ~ b(N w_L, p_j) from its own hashed random numbers. The estimate
// R = sum l_t m_j c / N (the count of N w_L trials carries w_L) has E[R] = sum m_j p_j exactly, because every draw is mean-preserving
// (binomial_unbiased; the published variants are not, which is what the tests show). Glints
// are stable: fixed random numbers per vertex, continuous weights, so a glint persists while
// the footprint or the half vector moves within a cell, and fades in and out. (Or, cheaper, one of
// the four lattice points per pixel, drawn with probability w_L: grid_pixel_setup with a
// lattice_u; the same mean and per-pixel variance, the fades replaced by a per-pixel choice.)
//
// Point lights (kind 0) have no solid angle, so p_j comes from the slope cell itself:
// p_j = slope_cell^2 x (unprojected slope density at the corner) / D_H. Extended lights (kind 1)
// use one p = D_Omega / D_H (KK25 Eq. 8, 9) for every corner; the corners then only decorrelate
// the random numbers as the light moves (KK25 Sec. 3.3). Either way the glint BRDF is the smooth
// BRDF times R / E[R], unbiased against the exact smooth BRDF.
//
// Real-valued vertex counts below 1 and 2 go through the sampler's real-N handling (KK25
// Eq. 23). Where the bound on R's relative standard deviation,
// sqrt(sum m_j^2 p_j (1 - p_j) / N + exp(sigma^2) - 1) / E[R], is below smooth_tolerance, R = E[R]
// is returned without any draw (the admitted error: a missing fluctuation of at most that
// relative size; the mean is unchanged). If E[R] = 0 nothing is drawn either.
//
// Domains: uv and its derivatives finite; |uv| / cell below 2^30 (precision: below 2^20 in float
// for sub-cell accuracy). Aspect ratios above 16 are clamped (the footprint's minor axis is
// widened); LODs are clamped to [-24, 24]. Zero-area footprints hold no microfacets: R = 0 (the
// smooth-result gate may return E[R] first, which is the limit of a huge density).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "glint/binomial.hpp"
#include "glint/microfacet.hpp"
#include "glint/detail/kernels.hpp"

namespace glint {

template <class real>
using grid_estimate = typename detail::glsl::kernels<real>::glint_grid_estimate;
template <class real>
using grid_light = typename detail::glsl::kernels<real>::glint_grid_light;
template <class real>
using footprint_lattice = typename detail::glsl::kernels<real>::glint_lattice;

// The material's glint parameters (defaults: the showcase's).
template <class real>
struct grid_params {
    real log_density = real(0);         // ln(expected microfacets per unit uv area)
    real density_sigma = real(0);       // per-vertex log-normal randomisation of the density
    real lod_scale = real(1.5);         // cell size relative to the footprint's minor axis
    real slope_cell = real(0.02);       // half-vector slope grid spacing (absolute slope)
    real smooth_tolerance = real(0.01); // relative sd below which the smooth result is returned
    binomial_variant variant = binomial_variant::unbiased;
    std::uint32_t seed = 0;
};

namespace detail {
// The kernels' struct of the parameters.
template <class real>
typename glsl::kernels<real>::glint_grid_params to_kernel(const grid_params<real>& g) {
    typename glsl::kernels<real>::glint_grid_params k;
    k.log_density = g.log_density;
    k.density_sigma = g.density_sigma;
    k.lod_scale = g.lod_scale;
    k.slope_cell = g.slope_cell;
    k.smooth_tolerance = g.smooth_tolerance;
    k.variant = static_cast<int>(g.variant);
    k.pow_method = static_cast<int>(published_pow_method(g.variant));
    k.seed = g.seed;
    return k;
}

template <class real>
vec2_t<real> slope_of(const vec3_t<real>& h) {
    const real z = h.z > real(1e-30) ? h.z : real(1e-30);
    return vec2_t<real>(-h.x / z, -h.y / z);
}
}  // namespace detail

// A point light seen through half vector h (tangent frame).
template <class real>
grid_light<real> grid_point_light(ndf d, const vec2_t<real>& alpha, real total_area_dh, const vec3_t<real>& h) {
    grid_light<real> l;
    l.kind = 0;
    l.p = real(0);
    l.slope = detail::slope_of(h);
    l.ndf = static_cast<int>(d);
    l.alpha = alpha;
    l.total_area = total_area_dh;
    return l;
}

// An extended light with reflection probability p = D_Omega / D_H, h the half vector towards
// its centre.
template <class real>
grid_light<real> grid_extended_light(real p, const vec3_t<real>& h) {
    grid_light<real> l;
    l.kind = 1;
    l.p = p;
    l.slope = detail::slope_of(h);
    l.ndf = 0;
    l.alpha = vec2_t<real>(real(1));
    l.total_area = real(1);
    return l;
}

template <class real>
grid_estimate<real> grid_sample(const vec2_t<real>& uv, const vec2_t<real>& duvdx, const vec2_t<real>& duvdy,
                                const grid_params<real>& g, const grid_light<real>& light) {
    return detail::glsl::kernels<real>::glint_grid_sample(uv, duvdx, duvdy, detail::to_kernel(g), light);
}

// One pixel's footprint on the grid, for several lights (and glint::ibl_sample's environment):
// the footprint, its microfacet count and its lattice vertices, computed once (the vertices when
// a light first needs draws). grid_sample(px, g, light) gives exactly grid_sample(uv, duvdx,
// duvdy, g, light); px is the pixel's own (not thread-safe to share while sampling).
//
//   auto px = glint::grid_pixel_setup(uv, duvdx, duvdy, g);
//   for (const auto& light : lights) radiance += smooth(light) * glint::modulation(glint::grid_sample(px, g, light));
template <class real>
using grid_pixel = typename detail::glsl::kernels<real>::glint_grid_pixel;

template <class real>
grid_pixel<real> grid_pixel_setup(const vec2_t<real>& uv, const vec2_t<real>& duvdx, const vec2_t<real>& duvdy, const grid_params<real>& g) {
    return detail::glsl::kernels<real>::glint_grid_pixel_setup(uv, duvdx, duvdy, detail::to_kernel(g));
}

// The same footprint on one of its four lattice points, drawn with probability w_L from the
// caller's uniform lattice_u in [0, 1) (above: just below 1; negative: all four points, as
// above), whose triangle vertices draw with the
// whole N: the same mean and, for binomial draws, the same variance per pixel as the four points
// together, at 3 vertices instead of up to 12 (stochastic texture filtering of KK25's lattice
// interpolation; kernels/grid.glsl, glint_grid_pixel_setup_stochastic, says what changes across
// pixels; docs/grid.md measures the cost). Use it with grid_sample(px, ...) and ibl_sample(px, ...).
template <class real>
grid_pixel<real> grid_pixel_setup(const vec2_t<real>& uv, const vec2_t<real>& duvdx, const vec2_t<real>& duvdy, const grid_params<real>& g,
                                  real lattice_u) {
    return detail::glsl::kernels<real>::glint_grid_pixel_setup_stochastic(uv, duvdx, duvdy, detail::to_kernel(g), lattice_u);
}

template <class real>
grid_estimate<real> grid_sample(grid_pixel<real>& px, const grid_params<real>& g, const grid_light<real>& light) {
    return detail::glsl::kernels<real>::glint_grid_sample_pixel(px, detail::to_kernel(g), light);
}

// Every light of a list on one pixel's footprint (grid_pixel_setup, one lattice point's too):
// out[i] = grid_sample(px, g, lights[i]), bit for bit; count may be 0, nothing allocated. The
// way to shade several lights: where the CPU has AVX2 (float), eight lights at a time share their
// per-light setup and skip test in vector lanes, so that an extra light costs a fraction of a
// grid_sample call (kernels/grid.glsl, glint_grid_sample_pixel_lights; docs/grid.md measures it).
template <class real>
void grid_sample_lights(grid_pixel<real>& px, const grid_params<real>& g, const grid_light<real>* lights, std::size_t count,
                        grid_estimate<real>* out) {
    const auto k = detail::to_kernel(g);
    for (std::size_t first = 0; first < count; first += 1u << 20)  // the kernel counts in int
        detail::glsl::kernels<real>::glint_grid_sample_pixel_lights(px, k, lights + first, static_cast<int>(std::min<std::size_t>(count - first, 1u << 20)),
                                                                    out + first);
}

// The same from the footprint: out[i] = grid_sample(uv, duvdx, duvdy, g, lights[i]), the
// footprint's setup done once. (GLSL: glint_grid_sample_lights, up to GLINT_GRID_MAX_LIGHTS = 8
// lights, one after another.)
template <class real>
void grid_sample_lights(const vec2_t<real>& uv, const vec2_t<real>& duvdx, const vec2_t<real>& duvdy, const grid_params<real>& g,
                        const grid_light<real>* lights, std::size_t count, grid_estimate<real>* out) {
    auto px = grid_pixel_setup(uv, duvdx, duvdy, g);
    grid_sample_lights(px, g, lights, count, out);
}

// The footprints of several pixels at once: out[i] = grid_pixel_setup(uv[i], duvdx[i], duvdy[i], g,
// lattice_u[i]) bit for bit (lattice_u null: every lattice point, as grid_pixel_setup without
// one), eight footprints at a time in AVX2 lanes where the CPU has them (float). For the batches
// of grid_sample_pixels and ibl_sample_pixels; nothing allocated.
template <class real>
void grid_pixels_setup(std::size_t count, const vec2_t<real>* uv, const vec2_t<real>* duvdx, const vec2_t<real>* duvdy, const grid_params<real>& g,
                       const real* lattice_u, grid_pixel<real>* out) {
    const auto k = detail::to_kernel(g);
    for (std::size_t first = 0; first < count; first += 1u << 20)  // the kernel counts in int
        detail::glsl::kernels<real>::glint_grid_pixels_setup(static_cast<int>(std::min<std::size_t>(count - first, 1u << 20)), uv + first, duvdx + first,
                                                             duvdy + first, k, lattice_u ? lattice_u + first : nullptr, out + first);
}

// Several pixels, each under its own light (a row of pixels under one point light, whose half
// vector differs from pixel to pixel): out[i] = grid_sample(px[i], g, lights[i]), bit for bit;
// count may be 0, nothing allocated. Where the CPU has AVX2 (float) and density_sigma is 0, eight
// pixels at a time share vector lanes, a pixel a lane: the lights' set-up, the footprints'
// lattices and vertices and the skip test, so that a pixel costs a fraction of a grid_sample call
// (kernels/grid.glsl, glint_grid_sample_pixels; docs/grid.md measures it). The lanes leave the
// pixels' vertex arrays unfilled, the one-at-a-time paths fill them; either way a later
// grid_sample(px[i], g, light) gives what it would have.
template <class real>
void grid_sample_pixels(grid_pixel<real>* px, const grid_params<real>& g, const grid_light<real>* lights, std::size_t count, grid_estimate<real>* out) {
    const auto k = detail::to_kernel(g);
    for (std::size_t first = 0; first < count; first += 1u << 20)  // the kernel counts in int
        detail::glsl::kernels<real>::glint_grid_sample_pixels(px + first, k, lights + first, static_cast<int>(std::min<std::size_t>(count - first, 1u << 20)),
                                                              out + first);
}

// R / E[R], the factor on the smooth result (the kernels' glint_modulation; 0 if E[R] = 0), for
// the estimates of glint::grid_sample and glint::ibl_sample (one type, glint_grid_estimate, whose
// real cannot be deduced through the nested name: a template on the estimate).
template <class estimate>
auto modulation(const estimate& e) -> decltype(e.value) {
    using real = decltype(e.value);
    return e.expected > real(0) ? e.value / e.expected : real(0);
}

// The lattice points and weights of a footprint (for tests and visualisation).
template <class real>
footprint_lattice<real> lattice_of(const vec2_t<real>& duvdx, const vec2_t<real>& duvdy, real lod_scale) {
    using k = detail::glsl::kernels<real>;
    return k::glint_footprint_lattice(k::glint_footprint_from_derivatives(duvdx, duvdy), lod_scale);
}

}  // namespace glint
