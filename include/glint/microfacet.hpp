// Microfacet basics (kernels/microfacet.glsl; GLSL users include core.glsl first): GGX and
// Beckmann NDFs with anisotropic roughness, Smith Lambda / G1 / height-correlated G2, Schlick
// and conductor Fresnel, the visible NDF and GGX's visible-normal sampling, the total microfacet
// area D_H, and the NDF integrated over a light D_Omega (KK25 Eq. 9) for cones of directions
// (spherical lights, the sun) and rectangles.
//
// All directions are unit vectors in the tangent frame (normal +z). Roughness alpha is clamped
// to [1e-4, 4] per axis. No function allocates, throws, or returns NaN or Inf for finite input.
//
// Derivation of D_H and D_Omega. Write a microfacet normal m by its standardized slope
// u = (m.x / (m.z ax), m.y / (m.z ay)), T = |u|^2. The projected microfacet area has the density
// rho(T) = 1 / (pi (1 + T)^2) (GGX) or exp(-T) / pi (Beckmann) per unit u; the unprojected area,
// which D_H and the glint count measure (KK25 Sec. 3.2), has rho sqrt(1 + |s|^2), with the
// absolute slope |s|^2 = ax^2 ux^2 + ay^2 uy^2 = a2 T, a2 fixed along a ray from u = 0. Along a ray,
// with t = r^2 and W = sqrt(1 + a2 T):
//   GGX:      integral_0^T sqrt(1 + a2 t) / (1 + t)^2 dt / (2 pi)
//             = [1 - W / (1 + T) + a2 (T / d) g(k (T/d)^2)] / (2 pi),  d = W + 1 + T, k = 1 - a2,
//             by parts and w = sqrt(1 + a2 t), with g(z) = atanh(sqrt z) / sqrt z (atan for z < 0);
//             the tail from T to infinity is [W / (1 + T) + a2 g(k / W^2) / W] / (2 pi).
//   Beckmann: integral_0^T sqrt(1 + a2 t) exp(-t) dt / (2 pi)
//             = [1 - W e^-T + (a sqrt(pi) / 2)(erfcx(1 / a) - e^-T erfcx(W / a))] / (2 pi);
//             the tail is e^-T [W + (a sqrt(pi) / 2) erfcx(W / a)] / (2 pi).
// D_H is the tail at T = 0 averaged over the ray direction (times 2 pi): closed form if
// isotropic, e.g. GGX 1 + a^2 atanh(sqrt(1 - a^2)) / sqrt(1 - a^2); a 32-node midpoint rule over
// the direction otherwise.
// D_Omega is the unprojected area of the half vectors that reflect wo into the light, a region
// of u-space bounded by the image of the light's outline. In polar coordinates around u = 0 the
// area of a region is the closed line integral over its boundary of mass(T(phi)) d phi, i.e.
// of (mass(T) / T) (u x du) (Green's theorem); no root finding, any winding, any sharpness of the
// lobe relative to the light, and anisotropy enters only through a2. When the boundary does not
// wind around u = 0 and stays away from it, minus the integral of (tail(T) / T) (u x du) gives
// the same area without subtracting nearly equal masses (a small, far light keeps its relative
// precision). The boundary is mapped exactly (wi -> v = wi + wo -> u, with du from the chain
// rule), split into pieces and integrated by 4-point Gauss-Legendre; the only errors are that
// quadrature and the float rounding. Lights are clipped to the upper hemisphere first. Measured
// against double-precision 2D quadrature: docs/microfacet.md.
#pragma once

#include "glint/core.hpp"
#include "glint/detail/kernels.hpp"

namespace glint {

enum class ndf { ggx = 0, beckmann = 1 };

inline const char* name(ndf d) { return d == ndf::ggx ? "GGX" : "Beckmann"; }

template <class real>
using vec2_t = glm::vec<2, real, glm::defaultp>;
template <class real>
using vec3_t = glm::vec<3, real, glm::defaultp>;
template <class real>
using vec4_t = glm::vec<4, real, glm::defaultp>;

namespace detail {
template <class real>
using mk = glsl::kernels<real>;
}

// D(m) per unit solid angle; 0 for m.z <= 0.
template <class real>
real ndf_value(ndf d, const vec3_t<real>& m, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_ndf(static_cast<int>(d), m, alpha);
}

// Density of unprojected microfacet area per unit of absolute slope s = -(m.x, m.y) / m.z.
template <class real>
real slope_area_density(ndf d, const vec2_t<real>& s, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_slope_area_density(static_cast<int>(d), s, alpha);
}

template <class real>
real smith_lambda(ndf d, const vec3_t<real>& w, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_smith_lambda(static_cast<int>(d), w, alpha);
}

template <class real>
real smith_g1(ndf d, const vec3_t<real>& w, const vec3_t<real>& m, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_smith_g1(static_cast<int>(d), w, m, alpha);
}

// Height-correlated masking-shadowing.
template <class real>
real smith_g2(ndf d, const vec3_t<real>& wi, const vec3_t<real>& wo, const vec3_t<real>& m, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_smith_g2(static_cast<int>(d), wi, wo, m, alpha);
}

template <class real>
real fresnel_schlick(real f0, real cos_theta) {
    return detail::mk<real>::glint_fresnel_schlick(f0, cos_theta);
}

// Conductor with complex index of refraction eta + i k, one wavelength.
template <class real>
real fresnel_conductor(real eta, real k, real cos_theta) {
    return detail::mk<real>::glint_fresnel_conductor(eta, k, cos_theta);
}

// Visible NDF D_wo(m), a density over m.
template <class real>
real vndf(ndf d, const vec3_t<real>& wo, const vec3_t<real>& m, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_vndf(static_cast<int>(d), wo, m, alpha);
}

// A GGX microfacet normal distributed by the visible NDF, from u1, u2 in [0, 1).
template <class real>
vec3_t<real> sample_vndf_ggx(const vec3_t<real>& wo, const vec2_t<real>& alpha, real u1, real u2) {
    return detail::mk<real>::glint_sample_vndf_ggx(wo, alpha, u1, u2);
}

// D_H, the total microfacet area per unit macro-surface area (>= 1).
template <class real>
real total_area(ndf d, const vec2_t<real>& alpha) {
    return detail::mk<real>::glint_total_area(static_cast<int>(d), alpha);
}

// D_Omega for a cone of light directions: unit axis, angular radius radius_angle (radians, in
// [0, pi/2]). `pieces` (4 to 64) sets the quadrature (2 x pieces pieces on the circle); the
// default 8 has a worst relative error of 2e-4 over the lights in docs/grid.md (below 1e-6 away
// from sharp lobes at grazing views), 16 about 1e-5, 32 about 4e-8, at 2x and 4x the time.
template <class real>
real integrated_ndf_cone(ndf d, const vec3_t<real>& wo, const vec2_t<real>& alpha, const vec3_t<real>& axis, real radius_angle,
                         int pieces = 8) {
    using std::cos;
    using std::sin;
    return detail::mk<real>::glint_integrated_ndf_cone(static_cast<int>(d), wo, alpha, axis, cos(radius_angle), sin(radius_angle),
                                                       pieces);
}

// D_Omega for a one-sided rectangular light with corners p0, p0 + e1, p0 + e1 + e2, p0 + e2
// relative to the shading point (tangent frame), emitting toward cross(e1, e2). `pieces` per edge
// (4 to 64, as for cones).
template <class real>
real integrated_ndf_rect(ndf d, const vec3_t<real>& wo, const vec2_t<real>& alpha, const vec3_t<real>& p0, const vec3_t<real>& e1,
                         const vec3_t<real>& e2, int pieces = 8) {
    return detail::mk<real>::glint_integrated_ndf_rect(static_cast<int>(d), wo, alpha, p0, e1, e2, pieces);
}

}  // namespace glint
