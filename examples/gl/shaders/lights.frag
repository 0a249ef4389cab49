// glint_gl: the lights scene's surfaces, shaded as examples/lights_scene.hpp shade() does on the
// CPU, with the footprint from the uv derivatives of the 2x2 pixel quad (dFdxFine, dFdyFine; the
// y derivative negated, since the CPU renderer's rows run downwards). The sphere's position,
// normal and uv are the mesh's, interpolated; the plane's are reconstructed from the pixel's ray
// (as a deferred renderer reconstructs them from depth): interpolated across a quad of +-1e5
// units, float positions would be 6e-3 units off near the camera. Forward (GLINT_GL_SHADE): this
// fragment shader shades; deferred (--deferred), it writes the G-buffer only and deferred.comp,
// which includes this file with GLINT_GL_COMPUTE, calls glint_gl_shade_surface on it.
uniform int u_sphere;      // 1: the sphere, 0: the plane
uniform int u_light;       // 0: point, 1: sun, 2: area
uniform int u_ggx;         // glint::ndf::ggx
uniform vec3 u_light_position;
uniform float u_intensity;
uniform vec3 u_sun_dir;
uniform float u_sun_radius, u_sun_irradiance;
uniform vec3 u_rect_corner, u_rect_e1, u_rect_e2;
uniform float u_rect_radiance;
uniform vec3 u_flake_eta, u_flake_k, u_plane_diffuse;
uniform float u_flake_coverage;
uniform float u_uv_per_unit;

vec3 to_local(vec3 t, vec3 b, vec3 n, vec3 w) { return vec3(dot(w, t), dot(w, b), dot(w, n)); }

vec3 shade(bool sphere, vec3 p, vec3 n, vec3 t, vec3 b, vec2 uv, vec3 wo_world, vec2 duvdx, vec2 duvdy) {
    vec2 alpha = vec2(u_roughness);
    vec3 wo = to_local(t, b, n, wo_world);
    if (!(wo.z > 0.0)) return vec3(0.0);
    vec3 ambient = vec3(0.0);
    if (sphere) {
        vec3 sky = glint_gl_sky(reflect(-wo_world, n));
        for (int k = 0; k < 3; ++k) ambient[k] = glint_fresnel_conductor(u_silver_eta[k], u_silver_k[k], wo.z) * sky[k];
    }
    vec3 wi_c;
    float d_omega = 0.0, radiance = 0.0, point_scale = 0.0;
    vec3 irradiance = vec3(0.0);
    if (u_light == 0) {
        vec3 d = u_light_position - p;
        float d2 = dot(d, d);
        wi_c = to_local(t, b, n, d / sqrt(d2));
        point_scale = u_intensity / d2;
        irradiance = vec3(point_scale * max(wi_c.z, 0.0));
    } else if (u_light == 1) {
        wi_c = to_local(t, b, n, u_sun_dir);
        radiance = u_sun_irradiance / (2.0 * 3.14159265 * (1.0 - cos(u_sun_radius)));
        irradiance = vec3(u_sun_irradiance * max(wi_c.z, 0.0));
        d_omega = glint_integrated_ndf_cone(u_ggx, wo, alpha, wi_c, cos(u_sun_radius), sin(u_sun_radius), 8);
    } else {
        vec3 p0 = to_local(t, b, n, u_rect_corner - p), e1 = to_local(t, b, n, u_rect_e1), e2 = to_local(t, b, n, u_rect_e2);
        vec3 c = p0 + 0.5 * (e1 + e2);
        float len = length(c);
        wi_c = c / len;
        radiance = u_rect_radiance;
        float solid = length(cross(e1, e2)) * max(0.0, -dot(normalize(cross(e1, e2)), wi_c)) / (len * len);
        irradiance = vec3(radiance * solid * max(wi_c.z, 0.0));
        d_omega = glint_integrated_ndf_rect(u_ggx, wo, alpha, p0, e1, e2, 8);
    }
    vec3 result = sphere ? ambient : u_plane_diffuse / 3.14159265 * irradiance;
    if (!(wi_c.z > 0.0) && u_light == 0) return result;
    vec3 hv = normalize(wi_c + wo);
    float g2 = glint_smith_g2(u_ggx, wi_c, wo, hv, alpha);
    if (!(g2 > 0.0)) return result;
    float specular = u_light == 0 ? g2 * glint_ndf(u_ggx, hv, alpha) * point_scale / (4.0 * wo.z)
                                  : g2 * radiance * dot(hv, wi_c) * d_omega / wo.z;
    if (!(specular > 0.0)) return result;
    if (GLINT_GL_GLINTS != 0) {
        float dh = u_total_area;  // only the glints need D_H (lights_scene.hpp ggx_total_area)
        glint_grid_params g = u_grid;
        g.seed = u_grid.seed + (sphere ? 1u : 2u);
        glint_grid_light light;
        light.slope = -vec2(hv.x, hv.y) / max(hv.z, 1e-30);
        if (u_light == 0) {
            light.kind = 0, light.p = 0.0, light.ndf = u_ggx, light.alpha = alpha, light.total_area = dh;
        } else {
            light.kind = 1, light.p = min(1.0, d_omega / dh), light.ndf = 0, light.alpha = vec2(1.0), light.total_area = 1.0;
        }
        glint_grid_pixel px = glint_grid_pixel_setup_stochastic(uv, duvdx, duvdy, g, glint_gl_lattice_u(u_grid.seed));
        specular *= glint_modulation(glint_grid_sample_pixel(px, g, light));
    }
    float c = dot(wi_c, hv);
    for (int k = 0; k < 3; ++k) {
        float f = sphere ? glint_fresnel_conductor(u_silver_eta[k], u_silver_k[k], c)
                         : u_flake_coverage * glint_fresnel_conductor(u_flake_eta[k], u_flake_k[k], c);
        result[k] += f * specular;
    }
    return result;
}

// The sphere's tangent frame from its (interpolated) normal: lights_scene.hpp sphere_frame().
void glint_gl_sphere_frame(vec3 n, out vec3 t, out vec3 b) {
    float s = max(sqrt(n.x * n.x + n.z * n.z), 1e-6);
    t = vec3(-n.z / s, 0.0, n.x / s);
    b = cross(n, t);
}

// A surface point's shading, as the G-buffer holds it (position, normal, uv and its derivatives).
vec3 glint_gl_shade_surface(bool sphere, vec3 p, vec3 n, vec2 uv, vec2 duvdx, vec2 duvdy) {
    vec3 t = vec3(1.0, 0.0, 0.0), b = vec3(0.0, 0.0, -1.0);
    if (sphere) glint_gl_sphere_frame(n, t, b);
    return shade(sphere, p, n, t, b, uv, normalize(u_eye - p), duvdx, duvdy);
}

#if !GLINT_GL_COMPUTE
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
#if GLINT_GL_SHADE
layout(location = 0) out vec4 o_color;
#endif
#if GLINT_GL_GBUFFER
layout(location = 1) out vec4 o_uv_dx;    // uv, du/dx
layout(location = 2) out vec4 o_dy_kind;  // du/dy, 1 sphere / 2 plane, 1
layout(location = 3) out vec4 o_position;
layout(location = 4) out vec4 o_normal;
#endif

void main() {
    bool sphere = u_sphere != 0;
    vec3 n = sphere ? normalize(v_normal) : vec3(0.0, 1.0, 0.0);
    vec3 p = v_position;
    vec2 uv = v_uv;
    if (!sphere) {  // lights_scene.hpp intersect(): the ray meets y = 0
        vec3 d = glint_gl_ray(glint_gl_pixel());
        p = u_eye + (-u_eye.y / d.y) * d;
        uv = vec2(p.x, -p.z) * u_uv_per_unit;
    }
    vec2 duvdx = dFdxFine(uv), duvdy = -dFdyFine(uv);
#if GLINT_GL_SHADE
    o_color = vec4(glint_gl_shade_surface(sphere, p, n, uv, duvdx, duvdy), 1.0);
#endif
#if GLINT_GL_GBUFFER
    o_uv_dx = vec4(uv, duvdx);
    o_dy_kind = vec4(duvdy, sphere ? 1.0 : 2.0, 1.0);
    o_position = vec4(p, 1.0);
    o_normal = vec4(n, 1.0);
#endif
}
#endif
