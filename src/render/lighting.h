// The lighting uniforms shared by lit.frag and ground.frag (declared in shaders/lighting.glsl),
// computed once per frame from the draw list.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "render/draw_list.h"
#include "render/gl_program.h"
#include "render/shader_programs.h"
#include "render/shadow_fit.h"

namespace tumble::render {

constexpr int kMaxLights = 8;  // a sanity bound: each light adds work to every pixel

struct FrameLighting {
  // The shadow-casting light, if any, comes first: the shaders shadow light 0 only.
  std::vector<Eigen::Vector3f> to_light;  // unit, surface -> light
  std::vector<Eigen::Vector3f> rgb;       // colour * intensity, linear
  bool shadows = false;                   // light 0 casts shadows this frame
  ShadowFit shadow;                       // valid when shadows
  float fade_start_m = 1e30f, fade_end_m = 2e30f;  // no fade without a ground

  LightingVariant variant() const { return {static_cast<int>(to_light.size()), shadows}; }
};

// Throws Error(BadInput) for more than kMaxLights lights or a zero/non-finite light direction.
// The shadow light is the first with casts_shadows; there is none when there are no instances.
FrameLighting frameLighting(const DrawFrame& frame, const std::optional<BoundingSphere>& bound,
                            int shadow_map_size);

// Sets the lighting uniforms on the program in use; the shadow map is on texture unit 0.
void applyLighting(const GlProgram& program, const DrawFrame& frame, const FrameLighting& lit);

}  // namespace tumble::render
