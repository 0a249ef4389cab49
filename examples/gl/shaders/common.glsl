// glint_gl: what every fragment shader shares, after the glint kernel files and the #defines
// (GLINT_GL_GLINTS: 0 for the smooth BRDF's programs, which leave the glint code out): the camera (the
// CPU renderer's camera::ray, examples/lights_scene.hpp), the scenes' constants, the lights
// scene's sky, and the IBL scene's environment (glint::environment's lookups, examples/ibl.cpp,
// with the same manual bilinear filtering over shader storage buffers).
uniform vec3 u_eye, u_forward, u_right, u_up;
uniform vec2 u_size;          // viewport width and height in pixels
uniform float u_ray_scale;    // 2 tan(fov_y / 2) / height
uniform float u_roughness;    // GGX alpha
uniform float u_total_area;   // D_H of GGX at u_roughness (glint::total_area), set with it: a material constant
uniform glint_grid_params u_grid;  // the seed here is the scene's; the lights scene adds 1 (sphere) or 2 (plane)
uniform vec3 u_silver_eta, u_silver_k;

// The image-space pixel centre of this fragment (rows from the top, as the CPU renderer's); in the
// deferred shading pass (deferred.comp), of the invocation's pixel.
#if GLINT_GL_COMPUTE
vec2 glint_gl_pixel() { return vec2(float(gl_GlobalInvocationID.x) + 0.5, u_size.y - (float(gl_GlobalInvocationID.y) + 0.5)); }
#else
vec2 glint_gl_pixel() { return vec2(gl_FragCoord.x, u_size.y - gl_FragCoord.y); }
#endif

// The uniform that picks this pixel's lattice point where GLINT_GL_ONE_LATTICE_POINT is 1
// (examples/lights_scene.hpp lattice_uniform(x, y, seed), a hash of the pixel and the grid's
// seed); else -1, every lattice point (glint_grid_pixel_setup_stochastic's u < 0).
float glint_gl_lattice_u(uint seed) {
    if (GLINT_GL_ONE_LATTICE_POINT == 0) return -1.0;
    uvec2 xy = uvec2(floor(glint_gl_pixel()));
    return glint_unit_from_bits(glint_pcg3d(uvec3(xy, seed ^ 0x5bd1e995u)).x);
}

vec3 glint_gl_ray(vec2 f) {
    return normalize(u_forward + u_right * ((f.x - 0.5 * u_size.x) * u_ray_scale) - u_up * ((f.y - 0.5 * u_size.y) * u_ray_scale));
}

// examples/lights_scene.hpp background(): a dusk sky, the plane's colour below the horizon.
vec3 glint_gl_sky(vec3 d) {
    if (d.y < 0.0) return vec3(0.004, 0.004, 0.005);
    float t = clamp(d.y * 2.5, 0.0, 1.0);
    return mix(vec3(0.060, 0.045, 0.050), vec3(0.010, 0.016, 0.040), t);
}

#if GLINT_GL_IBL
layout(std430, binding = 0) readonly buffer glint_gl_chain_buffer { float glint_gl_chain[]; };
layout(std430, binding = 1) readonly buffer glint_gl_table_buffer { float glint_gl_tables[]; };
uniform int u_chain_count;      // roughness levels M
uniform ivec3 u_chain[8];       // per level: first float, width, height
uniform int u_channels;         // 3 + K
uniform int u_table_size;       // E_rho at 0, E_D after it, u_table_size^2 each
uniform glint_ibl_levels u_levels;

void glint_gl_add_bilinear(int m, vec2 uv, float weight, inout float v[11]) {
    glint_bilinear_taps taps = glint_bilinear(uv, u_chain[m].y, u_chain[m].z);
    int channels = GLINT_GL_GLINTS != 0 ? u_channels : 3;  // the smooth BRDF reads the radiance only
    for (int i = 0; i < 4; ++i) {
        float w = weight * taps.weight[i];
        int first = u_chain[m].x + (taps.texel[i].y * u_chain[m].y + taps.texel[i].x) * u_channels;
        for (int c = 0; c < channels; ++c) v[c] += w * glint_gl_chain[first + c];
    }
}

// glint::environment::lookup: radiance (v[0..2]) and the K indicators, trilinear.
void glint_gl_lookup(vec3 d, float sqrt_alpha, out vec3 radiance, out glint_ibl_indicators ind) {
    vec2 uv = glint_equirect_uv(d);
    float f = clamp(sqrt_alpha, 0.0, 1.0) * float(u_chain_count - 1);
    int m0 = min(int(f), u_chain_count - 1), m1 = min(m0 + 1, u_chain_count - 1);
    float t = f - float(m0);
    float v[11];
    for (int c = 0; c < 11; ++c) v[c] = 0.0;
    glint_gl_add_bilinear(m0, uv, 1.0 - t, v);
    if (t > 0.0) glint_gl_add_bilinear(m1, uv, t, v);
    radiance = vec3(v[0], v[1], v[2]);
    for (int k = 0; k < 8; ++k) ind.w[k] = k < u_levels.count ? v[3 + k] : 0.0;
}

// glint::environment's tables (E_rho: which 0, E_D: which 1), bilinear with clamped edges.
float glint_gl_table(int which, float x, float y) {
    int n = u_table_size;
    float fx = clamp(x * float(n) - 0.5, 0.0, float(n - 1));
    float fy = clamp(y * float(n) - 0.5, 0.0, float(n - 1));
    int x0 = int(fx), y0 = int(fy), x1 = min(x0 + 1, n - 1), y1 = min(y0 + 1, n - 1);
    float ax = fx - float(x0), ay = fy - float(y0);
    int base = which * n * n;
    float a00 = glint_gl_tables[base + y0 * n + x0], a10 = glint_gl_tables[base + y0 * n + x1];
    float a01 = glint_gl_tables[base + y1 * n + x0], a11 = glint_gl_tables[base + y1 * n + x1];
    return (1.0 - ay) * ((1.0 - ax) * a00 + ax * a10) + ay * ((1.0 - ax) * a01 + ax * a11);
}
#endif

// The background where no surface covers the pixel (background.frag, deferred.comp): the
// environment's radiance, or the lights scene's sky.
vec3 glint_gl_background(vec3 d) {
#if GLINT_GL_IBL
    vec3 radiance;
    glint_ibl_indicators ind;
    glint_gl_lookup(d, 0.0, radiance, ind);
    return radiance;
#else
    return glint_gl_sky(d);
#endif
}
