// Shared by lit.frag and ground.frag (spliced after their #version line by GlProgram, after the
// variant's #defines: TUMBLE_LIGHT_COUNT, TUMBLE_LIGHT_ARRAY_SIZE, TUMBLE_SHADOWS).
// Everything here works in linear RGB. Every fragment ends the same way:
//   shade (scene-linear) -> toneMap -> fadeWithDistance -> encodeSrgb,
// the fade after the tone map because the background it fades into is display-linear: the
// framebuffer is cleared to encodeSrgb(background) with no tone map.
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

// Percentage-closer filtering (W. Reeves, D. Salesin, R. Cook, "Rendering antialiased shadows
// with depth maps", SIGGRAPH 1987) over the pixel's own footprint: eight single comparisons at
// the sample positions of the usual 8x MSAA pattern (in 1/16 pixel), carried from screen to
// shadow-map space by the derivatives of the lookup (depth included: the receiver-plane bias,
// exact on flat faces). Shading runs once per pixel, so with one lookup MSAA never smoothed the
// shadow's edge: it ran across pixels as a hard staircase. Eight samples give nine grey levels
// there, as 8x MSAA would on a body's outline.
//   kShadowFilterPixels widens the pattern a little past the pixel (as the ground's checker
//   filter does) so the grey levels blend instead of stepping; kShadowFilterMinTexels keeps it at
//   least a couple of texels wide close up, where a texel spans several pixels.
// Fixed offsets, no noise: frames stay bit-identical. Cost on llvmpipe at 1280x720: a NEAREST
// comparison about 1 ms, a LINEAR one about 8 ms, so these eight cost what the one LINEAR lookup
// they replace did, plus the derivatives.
const float kShadowFilterPixels = 1.5;
const float kShadowFilterMinTexels = 2.0;
const vec2 kShadowSamples[8] = vec2[8](vec2(1, -3), vec2(-1, 3), vec2(5, 1), vec2(-3, -5),
                                       vec2(-5, 5), vec2(-7, -1), vec2(3, 7), vec2(7, -7));

// A derivative of the lookup (per pixel), stretched to span at least kShadowFilterMinTexels.
vec3 filterAxis(vec3 d, float texels_per_uv) {
  float texels = length(d.xy) * texels_per_uv;
  return d * (kShadowFilterPixels / 16.0 * max(1.0, kShadowFilterMinTexels / max(texels, 1e-6)));
}

float softShadowLookup(vec3 uvz) {
  float texels_per_uv = float(textureSize(u_shadow_map, 0).x);
  vec3 ex = filterAxis(dFdx(uvz), texels_per_uv);
  vec3 ey = filterAxis(dFdy(uvz), texels_per_uv);
  float lit = 0.0;
  for (int i = 0; i < 8; ++i) {
    vec3 q = uvz + ex * kShadowSamples[i].x + ey * kShadowSamples[i].y;
    lit += texture(u_shadow_map, vec3(q.xy, min(q.z, 1.0)));
  }
  return lit / 8.0;
}

// Fraction of light 0 that reaches p (1 = fully lit).
float shadowVisibility(vec3 p, vec3 n) {
  // Normal offset: move the lookup off the surface by about a texel, more at grazing angles
  // where one texel spans a long stretch of surface; this removes acne without the large depth
  // bias that would detach shadows from contacts.
  float grazing = 1.0 - clamp(dot(n, u_light_to[0]), 0.0, 1.0);
  vec3 q = p + n * u_shadow_texel_m * (1.0 + 2.0 * grazing);
  vec3 uvz = (u_light_view_proj * vec4(q, 1.0)).xyz * 0.5 + 0.5;  // orthographic: w = 1
  // Receivers beyond the fitted depth range (the ground) are behind every caster, so
  // softShadowLookup clamps each sample's depth to 1; outside the box's sides the border
  // (depth 1) reads as lit.
  return softShadowLookup(uvz);
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

// Scene-referred linear light -> display-referred linear in [0, 1): exposure, then the fit of the
// ACES filmic reference curve by K. Narkowicz ("ACES Filmic Tone Mapping Curve", 2015),
//   f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14).
// Clamping alone (what a plain sRGB encode does) clips every bright face to the same flat white
// and shifts its hue where one channel clips first; the curve rolls highlights off instead and
// deepens the darkest shadows slightly (its toe). kExposure 0.8 keeps mid-tones where clamping
// put them (f(0.8 x) is within 15% of x for x in 0.2..0.6), so scenes lit for the old
// pipeline keep their look.
const float kExposure = 0.8;

vec3 toneMap(vec3 linear) {
  vec3 x = kExposure * max(linear, vec3(0.0));
  return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
}

// Linear -> sRGB transfer (IEC 61966-2-1), per channel, after clamping to the displayable range.
vec3 encodeSrgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  vec3 low = 12.92 * c;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(low, high, step(vec3(0.0031308), c));
}
