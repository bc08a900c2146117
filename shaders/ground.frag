#version 330 core
// The ground: a checkerboard in world xy, box-filtered over each pixel's footprint so it greys
// out smoothly in the distance instead of aliasing into moire, lit and shadowed like the bodies.

in vec3 v_world;

uniform vec3 u_colour_a;    // linear
uniform vec3 u_colour_b;    // linear
uniform float u_checker_m;  // square edge, m

out vec4 frag_colour;

// Integral of the square wave s(x) = +1 on [0,1), -1 on [1,2) (period 2): a triangle wave
// rising 0 -> 1 on [0,1] and falling back to 0 on [1,2].
vec2 squareWaveIntegral(vec2 x) {
  return 1.0 - abs(2.0 * fract(0.5 * x) - 1.0);
}

// Mean of s(x) * s(y) over a w-wide box around p: the box is separable, so the mean of the
// product is the product of the 1D means (I(x + w/2) - I(x - w/2)) / w. Returns the weight of
// colour b in [0, 1].
float filteredChecker(vec2 p) {
  // 1.2 pixel footprint: slightly wider than a pixel, trading a touch of sharpness for no
  // crawling in animations.
  vec2 w = max(1.2 * fwidth(p), vec2(1e-4));
  vec2 mean = (squareWaveIntegral(p + 0.5 * w) - squareWaveIntegral(p - 0.5 * w)) / w;
  return 0.5 - 0.5 * mean.x * mean.y;
}

void main() {
  float t = filteredChecker(v_world.xy / u_checker_m);
  vec3 albedo = mix(u_colour_a, u_colour_b, t);
  vec3 colour = shade(albedo, v_world, vec3(0.0, 0.0, 1.0));
  frag_colour = vec4(encodeSrgb(fadeWithDistance(toneMap(colour), v_world)), 1.0);
}
