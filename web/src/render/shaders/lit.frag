#version 300 es
precision highp float;

in vec3 v_normal;
in vec3 v_view_pos;

uniform vec4 u_colour;
uniform vec4 u_clip;
uniform vec4 u_inside;

out vec4 out_colour;

const vec3 KEY = normalize(vec3(-0.45, 0.65, 0.62));
const vec3 FILL = normalize(vec3(0.7, -0.2, 0.5));

void main() {
  if (dot(u_clip.xyz, v_view_pos) + u_clip.w > 0.0) discard;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(-v_view_pos);
  float key = max(dot(n, KEY), 0.0);
  float fill = max(dot(n, FILL), 0.0);
  float spec = pow(max(dot(n, normalize(KEY + v)), 0.0), 32.0);
  vec3 base = (!gl_FrontFacing && u_inside.a > 0.0) ? u_inside.rgb : u_colour.rgb;
  vec3 c = base * (0.34 + 0.58 * key + 0.20 * fill) + vec3(0.18 * spec);
  out_colour = vec4(min(c, vec3(1.0)), u_colour.a);
}
