#version 330 core
// The ground: a rectangle of the plane z = height (the whole ground, or the part of it that
// shadows can reach).

layout(location = 0) in vec2 a_corner;   // in [0, 1]^2

uniform mat4 u_view_proj;
uniform vec4 u_ground_rect;     // world xy: min x, min y, max x, max y
uniform float u_ground_height;

out vec3 v_world;

void main() {
  v_world = vec3(mix(u_ground_rect.xy, u_ground_rect.zw, a_corner), u_ground_height);
  gl_Position = u_view_proj * vec4(v_world, 1.0);
}
