// glint_gl: the sphere and plane meshes, world-space attributes passed through.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_uv = a_uv;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
