#version 330 core
// Meshes as a file holds them: like lit.vert, but the normal is interpolated across each triangle
// (a file's smooth normals stay smooth; flat ones are equal at a triangle's corners and stay flat)
// and texture coordinates come along.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 a_model;   // locations 2..5
layout(location = 6) in vec3 a_colour;
layout(location = 7) in vec2 a_uv;

uniform mat4 u_view_proj;

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
flat out vec3 v_albedo;

void main() {
  vec4 world = a_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  // Poses are rigid (plus at most uniform scale), so the linear part itself maps normals.
  v_normal = mat3(a_model) * a_normal;
  v_uv = a_uv;
  v_albedo = a_colour;
  gl_Position = u_view_proj * world;
}
