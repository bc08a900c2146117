#version 330 core
// Bodies: Blinn-Phong with the shared lighting in lighting.glsl, output in sRGB.

in vec3 v_world;
flat in vec3 v_normal;
flat in vec3 v_albedo;

out vec4 frag_colour;

void main() {
  vec3 colour = shade(v_albedo, v_world, v_normal);
  frag_colour = vec4(encodeSrgb(fadeWithDistance(toneMap(colour), v_world)), 1.0);
}
