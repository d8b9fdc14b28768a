#version 300 es
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_colour;

uniform mat4 u_mvp;

out vec3 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = u_mvp * vec4(a_position, 1.0);
}
