#version 330 core
// Meshes as a file holds them: the albedo is the base-colour texture (sRGB storage, so the sample
// is linear already) times the material's colour, then the shared lighting of lighting.glsl.

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
flat in vec3 v_albedo;

uniform sampler2D u_albedo_map;   // a 1x1 white texture for meshes without one

out vec4 frag_colour;

void main() {
  vec3 albedo = v_albedo * texture(u_albedo_map, v_uv).rgb;
  // Interpolated unit normals shorten between corners: renormalise per pixel.
  vec3 colour = shade(albedo, v_world, normalize(v_normal));
  frag_colour = vec4(encodeSrgb(fadeWithDistance(toneMap(colour), v_world)), 1.0);
}
