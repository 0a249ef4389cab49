// Double-precision references for the microfacet tests: D_Omega (KK25 Eq. 9) by nested adaptive
// Gauss-Kronrod quadrature over the light itself, independent of glint's boundary method. The
// integration domain is split at the mirror direction's position on the light, so that a lobe
// much narrower than the light sits at a corner of the sub-domains where the adaptive rule
// finds it, and limited exactly to the part above the horizon.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <glint/microfacet.hpp>

namespace glint_test {

using dvec3 = glm::dvec3;
using dvec2 = glm::dvec2;

// 1D adaptive Gauss-Kronrod over [a, b] with interior break points.
template <class F>
double integrate_1d(F f, double a, double b, std::vector<double> breaks, double tol = 1e-10) {
    if (!(b > a)) return 0.0;
    breaks.push_back(a), breaks.push_back(b);
    std::sort(breaks.begin(), breaks.end());
    double s = 0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
        if (hi > lo) s += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, lo, hi, 12, tol);
    }
    return s;
}

// D(h) / (4 <h, wi>) for light direction wi (0 below the horizon).
inline double lobe(glint::ndf d, const dvec3& wo, const dvec2& alpha, const dvec3& wi) {
    if (wi.z <= 0) return 0.0;
    const dvec3 h = glm::normalize(wi + wo);
    return glint::ndf_value(d, h, alpha) / (4 * glm::dot(h, wi));
}

inline dvec3 mirror(const dvec3& wo) { return {-wo.x, -wo.y, wo.z}; }

// Cone: polar coordinates (theta, psi) around the axis; theta limited to the horizon exactly.
inline double reference_cone(glint::ndf d, const dvec3& wo, const dvec2& alpha, const dvec3& c, double radius) {
    const dvec3 t1 = std::hypot(c.x, c.y) > 1e-9 ? glm::normalize(dvec3(-c.y, c.x, 0)) : dvec3(1, 0, 0);
    const dvec3 t2 = glm::cross(c, t1);
    const dvec3 r = mirror(wo);
    const double theta_r = std::acos(std::clamp(glm::dot(r, c), -1.0, 1.0));
    const double psi_r = std::atan2(glm::dot(r, t2), glm::dot(r, t1));
    std::vector<double> psi_breaks{psi_r < 0 ? psi_r + 2 * M_PI : psi_r};
    std::vector<double> theta_breaks{theta_r};
    auto outer = [&](double psi) {
        const dvec3 dir = std::cos(psi) * t1 + std::sin(psi) * t2;
        // wi.z = cos(theta) c.z + sin(theta) dir.z >= 0 on theta in [0, radius] <= pi/2: an interval.
        const double A = c.z, B = dir.z;
        double lo = 0, hi = radius;
        if (A >= 0 && B < 0) hi = std::min(hi, std::atan2(A, -B));
        if (A < 0) {
            if (B <= 0) return 0.0;
            lo = std::atan2(-A, B);
        }
        auto inner = [&](double theta) { return lobe(d, wo, alpha, std::cos(theta) * c + std::sin(theta) * dir) * std::sin(theta); };
        return integrate_1d(inner, lo, hi, theta_breaks);
    };
    return integrate_1d(outer, 0.0, 2 * M_PI, psi_breaks, 1e-9);
}

// Rectangle p0 + x e1 + y e2, (x, y) in [0, 1]^2: dw = |cross(e1, e2) . P| / |P|^3 dx dy; y limited
// to P.z >= 0 exactly; split at the point where the mirror direction meets the rectangle.
inline double reference_rect(glint::ndf d, const dvec3& wo, const dvec2& alpha, const dvec3& p0, const dvec3& e1, const dvec3& e2) {
    const dvec3 n = glm::cross(e1, e2);
    if (!(glm::dot(n, p0) < 0)) return 0.0;
    const dvec3 r = mirror(wo);
    std::vector<double> xb, yb;
    const double rn = glm::dot(r, n);
    if (rn != 0) {
        const double lambda = glm::dot(p0, n) / rn;
        if (lambda > 0) {
            const dvec3 q = lambda * r - p0;
            // solve q = x e1 + y e2 by least squares on the plane
            const double a11 = glm::dot(e1, e1), a12 = glm::dot(e1, e2), a22 = glm::dot(e2, e2);
            const double b1 = glm::dot(q, e1), b2 = glm::dot(q, e2), det = a11 * a22 - a12 * a12;
            xb.push_back((b1 * a22 - b2 * a12) / det), yb.push_back((a11 * b2 - a12 * b1) / det);
        }
    }
    auto outer = [&](double x) {
        // P.z = p0.z + x e1.z + y e2.z >= 0
        double lo = 0, hi = 1;
        const double z0 = p0.z + x * e1.z;
        if (e2.z > 0) lo = std::max(lo, -z0 / e2.z);
        else if (e2.z < 0) hi = std::min(hi, -z0 / e2.z);
        else if (z0 < 0) return 0.0;
        auto inner = [&](double y) {
            const dvec3 P = p0 + x * e1 + y * e2;
            const double len = glm::length(P);
            return lobe(d, wo, alpha, P / len) * std::fabs(glm::dot(n, P)) / (len * len * len);
        };
        return integrate_1d(inner, lo, hi, yb);
    };
    return integrate_1d(outer, 0.0, 1.0, xb, 1e-9);
}

// One light of the D_Omega comparisons (unit test and report): a cone (axis, radius) or a
// rectangle (p0, e1, e2) seen from view wo at roughness alpha.
struct light_case {
    std::string what;
    glint::ndf d;
    dvec2 alpha;
    dvec3 wo;
    bool cone;
    dvec3 axis;
    double radius;
    dvec3 p0, e1, e2;
};

// Cones (the sun's 0.26 degrees, 3 and 23 degrees) and rectangles (small to wider than the
// lobe), at and near the mirror direction (and, with `far_cones`, cones 4 radii plus 0.3 rad
// away), from normal to grazing views, sharp to rough, isotropic and anisotropic, including lights
// cut by the horizon.
inline std::vector<light_case> light_cases(bool far_cones) {
    std::vector<light_case> cases;
    for (glint::ndf d : {glint::ndf::ggx, glint::ndf::beckmann})
        for (dvec2 a : {dvec2(2e-3, 2e-3), dvec2(0.02, 0.08), dvec2(0.2, 0.2), dvec2(0.5, 0.25)})
            for (double theta_o : {0.0, 0.8, 1.4}) {
                const dvec3 wo(std::sin(theta_o), 0, std::cos(theta_o));
                const dvec3 r = mirror(wo);
                const dvec3 side = glm::normalize(glm::cross(r, dvec3(0.3, 1, 0.2)));
                for (double radius : {0.00454, 0.05, 0.4})
                    for (double off : {0.0, 0.5, 1.5, 4.0}) {
                        if (off > 3 && !far_cones) continue;
                        const double ang = off * radius + (off > 3 ? 0.3 : 0);
                        const dvec3 c = std::cos(ang) * r + std::sin(ang) * side;
                        cases.push_back({"cone", d, a, wo, true, c, radius, {}, {}, {}});
                    }
                for (double size : {0.05, 0.5, 3.0})
                    for (double off : {0.0, 0.5, 1.5}) {
                        const double ang = off * size / 2;
                        const dvec3 c = std::cos(ang) * r + std::sin(ang) * side;
                        dvec3 e1 = glm::normalize(glm::cross(c, dvec3(0, 0.2, 1))) * size;
                        dvec3 e2 = glm::normalize(glm::cross(e1, c)) * size * 0.6;
                        if (glm::dot(glm::cross(e1, e2), c) > 0) std::swap(e1, e2);
                        cases.push_back({"rect", d, a, wo, false, {}, 0, c * 2.0 - 0.5 * e1 - 0.5 * e2, e1, e2});
                    }
            }
    return cases;
}

inline double reference(const light_case& c) {
    return c.cone ? reference_cone(c.d, c.wo, c.alpha, c.axis, c.radius) : reference_rect(c.d, c.wo, c.alpha, c.p0, c.e1, c.e2);
}

// glint's D_Omega for the light in float or double.
template <class real>
real d_omega(const light_case& c, int pieces) {
    using v2 = glm::vec<2, real, glm::defaultp>;
    using v3 = glm::vec<3, real, glm::defaultp>;
    return c.cone ? glint::integrated_ndf_cone<real>(c.d, v3(c.wo), v2(c.alpha), v3(c.axis), static_cast<real>(c.radius), pieces)
                  : glint::integrated_ndf_rect<real>(c.d, v3(c.wo), v2(c.alpha), v3(c.p0), v3(c.e1), v3(c.e2), pieces);
}

}  // namespace glint_test
