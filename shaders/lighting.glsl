// Shared by lit.frag and ground.frag (spliced after their #version line by GlProgram, after the
// variant's #defines: TUMBLE_LIGHT_COUNT, TUMBLE_LIGHT_ARRAY_SIZE, TUMBLE_SHADOWS).
// Everything here works in linear RGB; encodeSrgb is the last step of every fragment.
//
// Written for llvmpipe, which shades pixels in SIMD lanes: a branch costs both of its sides and
// a loop costs its largest trip count, so the light loop has a compile-time bound and shadow code
// exists only in the variant that uses it.

const float kSpecularStrength = 0.18;   // "modest": highlights never wash out the albedo

uniform vec3 u_light_to[TUMBLE_LIGHT_ARRAY_SIZE];   // unit vector from the surface to light i
uniform vec3 u_light_rgb[TUMBLE_LIGHT_ARRAY_SIZE];  // colour * intensity, linear
uniform vec3 u_ambient;                 // linear
uniform vec3 u_eye;                     // camera position, world

#if TUMBLE_SHADOWS
uniform sampler2DShadow u_shadow_map;   // for light 0
uniform mat4 u_light_view_proj;
uniform float u_shadow_texel_m;         // one shadow texel in metres

// Fraction of light 0 that reaches p (1 = fully lit).
float shadowVisibility(vec3 p, vec3 n) {
  // Normal offset: move the lookup off the surface by about a texel, more at grazing angles
  // where one texel spans a long stretch of surface; this removes acne without the large depth
  // bias that would detach shadows from contacts.
  float grazing = 1.0 - clamp(dot(n, u_light_to[0]), 0.0, 1.0);
  vec3 q = p + n * u_shadow_texel_m * (1.0 + 2.0 * grazing);
  vec3 uvz = (u_light_view_proj * vec4(q, 1.0)).xyz * 0.5 + 0.5;  // orthographic: w = 1
  // Receivers beyond the fitted depth range (the ground) are behind every caster; outside the
  // box's sides the border (depth 1) reads as lit.
  uvz.z = min(uvz.z, 1.0);
  // One lookup: with the comparison sampler and LINEAR filtering it is a 2x2 bilinear PCF, a
  // penumbra about one texel wide (a few mm on a tight 2048 map: close to what the sun's 0.5 deg
  // gives for bodies of about a metre). Every further tap cost ~4 ms per 720p frame.
  return texture(u_shadow_map, uvz);
}
#endif

// Diffuse + specular from one directional light, before shadowing.
vec3 directLight(vec3 albedo, vec3 n, vec3 v, vec3 l, vec3 rgb) {
  float n_dot_l = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  // Blinn-Phong exponent 32 by five squarings: pow() is exp2(log2()) in software and cost
  // about a fifth of the whole ground pass.
  float s = max(dot(n, h), 0.0);
  s *= s; s *= s; s *= s; s *= s; s *= s;
  // The smoothstep fades the highlight in at the terminator instead of switching it on.
  float specular = kSpecularStrength * s * smoothstep(0.0, 0.15, n_dot_l);
  return rgb * (albedo * n_dot_l + vec3(specular));
}

// Blinn-Phong: ambient + for each directional light diffuse and a modest specular.
vec3 shade(vec3 albedo, vec3 p, vec3 n) {
  // A hint of hemisphere lighting (sky above, less from below) so faces in shadow still read as
  // different faces instead of one flat ambient colour: 1.0 facing up, 0.8 sideways, 0.6 down.
  vec3 colour = albedo * u_ambient * (0.8 + 0.2 * n.z);
  vec3 v = normalize(u_eye - p);
  for (int i = 0; i < TUMBLE_LIGHT_COUNT; ++i) {
    vec3 direct = directLight(albedo, n, v, u_light_to[i], u_light_rgb[i]);
#if TUMBLE_SHADOWS
    if (i == 0) direct *= shadowVisibility(p, n);  // constant after unrolling: no real branch
#endif
    colour += direct;
  }
  return colour;
}

uniform vec3 u_background;              // linear: distant surfaces fade into it
uniform float u_fade_start_m;
uniform float u_fade_end_m;

// Far surfaces dissolve into the background, hiding the ground's edge and its far-field aliasing.
vec3 fadeWithDistance(vec3 colour, vec3 p) {
  float t = smoothstep(u_fade_start_m, u_fade_end_m, length(p - u_eye));
  return mix(colour, u_background, t);
}

// Linear -> sRGB transfer (IEC 61966-2-1), per channel, after clamping to the displayable range.
vec3 encodeSrgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  vec3 low = 12.92 * c;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(low, high, step(vec3(0.0031308), c));
}
