// glint_gl: the background pass, where no surface covers the pixel.
layout(location = 0) out vec4 o_color;
void main() {
    vec3 d = glint_gl_ray(glint_gl_pixel());
#if GLINT_GL_IBL
    vec3 radiance;
    glint_ibl_indicators ind;
    glint_gl_lookup(d, 0.0, radiance, ind);
    o_color = vec4(radiance, 1.0);
#else
    o_color = vec4(glint_gl_sky(d), 1.0);
#endif
}
