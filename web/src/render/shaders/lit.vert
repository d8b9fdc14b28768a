#version 300 es
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model_view;
uniform mat4 u_projection;

out vec3 v_normal;
out vec3 v_view_pos;

void main() {
  vec4 p = u_model_view * vec4(a_position, 1.0);
  v_view_pos = p.xyz;
  v_normal = transpose(inverse(mat3(u_model_view))) * a_normal;
  gl_Position = u_projection * p;
}
