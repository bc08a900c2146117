#version 330 core
// Bodies: one instanced draw per mesh; the model matrix and albedo come per instance.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 a_model;   // locations 2..5
layout(location = 6) in vec3 a_colour;

uniform mat4 u_view_proj;

out vec3 v_world;
flat out vec3 v_normal;   // flat: one normal per triangle, never interpolated
flat out vec3 v_albedo;

void main() {
  vec4 world = a_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  // Poses are rigid (plus at most uniform scale), so the linear part itself maps normals.
  v_normal = normalize(mat3(a_model) * a_normal);
  v_albedo = a_colour;
  gl_Position = u_view_proj * world;
}
