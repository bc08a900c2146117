#version 330 core
// The ground: a square of the plane z = height, centred on the origin.

layout(location = 0) in vec2 a_corner;   // in [-1, 1]^2

uniform mat4 u_view_proj;
uniform float u_ground_extent;  // half the square's edge, m
uniform float u_ground_height;

out vec3 v_world;

void main() {
  v_world = vec3(a_corner * u_ground_extent, u_ground_height);
  gl_Position = u_view_proj * vec4(v_world, 1.0);
}
