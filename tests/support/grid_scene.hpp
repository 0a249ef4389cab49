// A shading configuration for the grid tests and benches: a view, a light of each kind, a
// roughness, a density and a footprint; modulation(seed) is one realisation of R / E[R] (the
// glint BRDF divided by the smooth one), whose mean must be 1.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include <glint/grid.hpp>

namespace glint_test {

enum class light_kind { point, sun, sphere, rect };

inline const char* name(light_kind k) {
    switch (k) {
        case light_kind::point: return "point";
        case light_kind::sun: return "sun";
        case light_kind::sphere: return "sphere";
        case light_kind::rect: break;
    }
    return "rect";
}

struct grid_scene {
    light_kind kind = light_kind::sun;
    float alpha = 0.25f;       // isotropic roughness
    float log_density = 0.0f;  // ln(microfacets per unit uv area)
    float footprint = 1.0f;    // major axis length in uv
    float ratio = 1.0f;        // major / minor
    glint::binomial_variant variant = glint::binomial_variant::unbiased;
    float light_size = 0.0f;   // cone radius (rad) or rectangle side; 0: the kind's default
    float slope_cell = glint::grid_params<float>{}.slope_cell;

    glm::vec3 wo = glm::normalize(glm::vec3(0.55f, 0.2f, 0.8f));
    glm::vec3 wi{}, h{};
    glint::grid_light<float> light{};
    float p = 0;  // probability one microfacet reflects (extended lights)

    // Places the light so that its centre's half vector sits at standardized slope (0.5, -0.3).
    void prepare() {
        const glm::vec3 m = glm::normalize(glm::vec3(-0.5f * alpha, 0.3f * alpha, 1.0f));
        wi = 2 * glm::dot(wo, m) * m - wo;
        h = m;
        const glm::vec2 a(alpha);
        const float dh = glint::total_area(glint::ndf::ggx, a);
        float d_omega = 0;
        switch (kind) {
            case light_kind::point: light = glint::grid_point_light(glint::ndf::ggx, a, dh, h); return;
            case light_kind::sun: d_omega = glint::integrated_ndf_cone(glint::ndf::ggx, wo, a, wi, light_size > 0 ? light_size : 0.00454f); break;
            case light_kind::sphere: d_omega = glint::integrated_ndf_cone(glint::ndf::ggx, wo, a, wi, light_size > 0 ? light_size : 0.1f); break;
            case light_kind::rect: {
                const float s = light_size > 0 ? light_size : 1.0f;
                glm::vec3 e1 = glm::normalize(glm::cross(wi, glm::vec3(0, 1, 0))) * s;
                glm::vec3 e2 = glm::normalize(glm::cross(e1, wi)) * (0.6f * s);
                if (glm::dot(glm::cross(e1, e2), wi) > 0) std::swap(e1, e2);
                d_omega = glint::integrated_ndf_rect(glint::ndf::ggx, wo, a, 2.0f * wi - 0.5f * e1 - 0.5f * e2, e1, e2);
                break;
            }
        }
        p = std::min(1.0f, d_omega / dh);
        light = glint::grid_extended_light(p, h);
    }

    glint::grid_params<float> params(std::uint32_t seed) const {
        glint::grid_params<float> g;
        g.log_density = log_density;
        g.variant = variant;
        g.smooth_tolerance = 0;  // always sample: the tests look at the glints themselves
        g.slope_cell = slope_cell;
        g.seed = seed;
        return g;
    }

    // The footprint: major axis along 30 degrees, derivatives spanning the ellipse.
    void derivatives(glm::vec2& dx, glm::vec2& dy) const {
        const float c = std::cos(0.5236f), s = std::sin(0.5236f);
        dx = glm::vec2(c, s) * footprint;
        dy = glm::vec2(-s, c) * (footprint / ratio);
    }

    glint::grid_estimate<float> estimate(std::uint32_t seed, glm::vec2 uv) const {
        glm::vec2 dx, dy;
        derivatives(dx, dy);
        return glint::grid_sample(uv, dx, dy, params(seed), light);
    }

    // Expected microfacets per footprint that reflect: N E[R].
    double expected_glints() const {
        glm::vec2 dx, dy;
        derivatives(dx, dy);
        const double area = std::fabs(static_cast<double>(dx.x * dy.y - dx.y * dy.x));
        return std::exp(static_cast<double>(log_density)) * area * static_cast<double>(estimate(1u, glm::vec2(0.3f)).expected);
    }

    std::string describe() const {
        return std::string(name(kind)) + ", alpha " + std::to_string(alpha) + ", ln density " + std::to_string(log_density) +
               ", footprint " + std::to_string(footprint) + " ratio " + std::to_string(ratio);
    }
};

}  // namespace glint_test
