// glint_gl: the IBL scene's sphere, shaded as examples/ibl_scene.hpp shade_ibl() does on the CPU,
// with the footprint from dFdxFine / dFdyFine of uv (y negated: the CPU's rows run downwards).
// Forward (GLINT_GL_SHADE): this fragment shader shades; deferred (--deferred), it writes the
// G-buffer only and deferred.comp, which includes this file with GLINT_GL_COMPUTE, calls
// glint_gl_shade_ibl on it.

// glint_gl --stage (profiling): the glint shading stopped after glint_ibl_needs_draws (stage 1)
// or after the grid vertices as well where it would draw (stage 2), what was computed folded into
// a factor within 2^-20 of 1, so that the compiler cannot leave it out. Left out of the full
// program, so that the program timed by default is the one before --stage.
#if GLINT_GL_STAGE != 0
float glint_gl_ibl_stage(inout glint_grid_pixel px, glint_ibl_indicators ind, float e_d, float d_h) {
    glint_multinomial_probabilities all;
    glint_grid_estimate o;
    bool draws = glint_ibl_needs_draws(u_grid, u_levels, ind, e_d, d_h, px.N, all, o);
    uint h = floatBitsToUint(o.value);
    if (GLINT_GL_STAGE >= 2 && draws) {
        glint_grid_pixel_vertices(px, u_grid);
        for (int i = 0; i < 12; ++i)
            h ^= px.v.hash_x[i] ^ px.v.hash_y[i] ^ px.v.hash_z[i] ^ floatBitsToUint(px.v.weight[i] * px.v.share[i] + px.skip_scale[i]);
    }
    return 1.0 + float(h & 1u) * exp2(-20.0);
}
#endif

vec3 glint_gl_shade_ibl(vec3 position, vec3 n, vec2 uv, vec2 duvdx, vec2 duvdy) {
    vec3 d = normalize(position - u_eye);
    float sa = sqrt(u_roughness);
    float cos_o = max(dot(-d, n), 1e-4);
    vec3 radiance;
    glint_ibl_indicators ind;
    glint_gl_lookup(reflect(d, n), sa, radiance, ind);
    float m = 1.0;
    if (GLINT_GL_GLINTS != 0) {
        float dh = u_total_area;
        glint_grid_pixel px = glint_grid_pixel_setup_stochastic(uv, duvdx, duvdy, u_grid, glint_gl_lattice_u(u_grid.seed));
        float e_d = glint_gl_table(1, sqrt(max(cos_o, 0.0)), sa);
#if GLINT_GL_STAGE == 0
        m = glint_modulation(glint_ibl_sample_pixel(px, u_grid, u_levels, ind, e_d, dh));
#else
        m = glint_gl_ibl_stage(px, ind, e_d, dh);
#endif
    }
    float albedo = glint_gl_table(0, sqrt(max(cos_o, 0.0)), sa);
    vec3 L;
    for (int c = 0; c < 3; ++c) L[c] = glint_fresnel_conductor(u_silver_eta[c], u_silver_k[c], cos_o) * albedo * radiance[c] * m;
    return L;
}

#if !GLINT_GL_COMPUTE
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
#if GLINT_GL_SHADE
layout(location = 0) out vec4 o_color;
#endif
#if GLINT_GL_GBUFFER
layout(location = 1) out vec4 o_uv_dx;
layout(location = 2) out vec4 o_dy_kind;
layout(location = 3) out vec4 o_position;
layout(location = 4) out vec4 o_normal;
#endif

void main() {
    vec3 n = normalize(v_normal);
    vec2 duvdx = dFdxFine(v_uv), duvdy = -dFdyFine(v_uv);
#if GLINT_GL_SHADE
    o_color = vec4(glint_gl_shade_ibl(v_position, n, v_uv, duvdx, duvdy), 1.0);
#endif
#if GLINT_GL_GBUFFER
    o_uv_dx = vec4(v_uv, duvdx);
    o_dy_kind = vec4(duvdy, 1.0, 1.0);
    o_position = vec4(v_position, 1.0);
    o_normal = vec4(n, 1.0);
#endif
}
#endif
