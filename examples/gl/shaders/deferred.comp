// glint_gl --deferred: the shading pass of a deferred renderer, one invocation per pixel over the
// G-buffer that the raster pass wrote (lights.frag / ibl.frag without GLINT_GL_SHADE), with the same
// shading functions as the forward fragment shaders. Included after common.glsl and the scene's
// .frag file (GLINT_GL_COMPUTE leaves out their fragment stage).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform readonly image2D u_uv_dx;    // uv, du/dx
layout(binding = 1, rgba32f) uniform readonly image2D u_dy_kind;  // du/dy, 0 background / 1 sphere / 2 plane
layout(binding = 2, rgba32f) uniform readonly image2D u_position;
layout(binding = 3, rgba32f) uniform readonly image2D u_normal;
layout(binding = 4, rgba32f) uniform writeonly image2D u_color;

void main() {
    // Rows of the G-buffer run upwards (GL's window coordinates), as gl_FragCoord's.
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (q.x >= int(u_size.x) || q.y >= int(u_size.y)) return;
    vec4 uv_dx = imageLoad(u_uv_dx, q), dy_kind = imageLoad(u_dy_kind, q);
    vec3 color;
    if (dy_kind.z == 0.0) {
        color = glint_gl_background(glint_gl_ray(glint_gl_pixel()));
    } else {
        vec3 p = imageLoad(u_position, q).xyz, n = imageLoad(u_normal, q).xyz;
#if GLINT_GL_IBL
        color = glint_gl_shade_ibl(p, n, uv_dx.xy, uv_dx.zw, dy_kind.xy);
#else
        color = glint_gl_shade_surface(dy_kind.z == 1.0, p, n, uv_dx.xy, uv_dx.zw, dy_kind.xy);
#endif
    }
    imageStore(u_color, q, vec4(color, 1.0));
}
