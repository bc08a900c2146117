#version 330 core
// Shadow pass: bodies' depth as seen from the shadow light. Same vertex layout as lit.vert.

layout(location = 0) in vec3 a_position;
layout(location = 2) in mat4 a_model;   // locations 2..5

uniform mat4 u_light_view_proj;

void main() {
  gl_Position = u_light_view_proj * (a_model * vec4(a_position, 1.0));
}
