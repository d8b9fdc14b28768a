#version 300 es
// Lit meshes: positions and normals to view space; the light rides with the camera so every
// view of the machine is lit from the front (readable on a projector).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model_view;
uniform mat4 u_projection;
uniform mat3 u_normal_matrix;

out vec3 v_normal;
out vec3 v_view_pos;

void main() {
  vec4 p = u_model_view * vec4(a_position, 1.0);
  v_view_pos = p.xyz;
  v_normal = u_normal_matrix * a_normal;
  gl_Position = u_projection * p;
}
