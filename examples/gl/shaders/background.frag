// glint_gl: the background pass, where no surface covers the pixel.
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(glint_gl_background(glint_gl_ray(glint_gl_pixel())), 1.0); }
