#include "render/lighting.h"

#include <string>

#include "base/error.h"

namespace tumble::render {

namespace {

// The ground fades into the background from 40 % to 95 % of its half size: its edge is never
// seen (for cameras near the middle), and the far field, where even the filtered checker is
// just grey, turns into a soft horizon haze.
constexpr float kFadeStartFraction = 0.4f;
constexpr float kFadeEndFraction = 0.95f;

void checkLights(const std::vector<DirectionalLight>& lights) {
  if (lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw Error(ExitCode::BadInput, "at most " + std::to_string(kMaxLights) +
                                        " lights can be drawn, got " +
                                        std::to_string(lights.size()));
  }
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (!lights[i].direction.allFinite() || lights[i].direction.squaredNorm() == 0) {
      throw Error(ExitCode::BadInput, "light " + std::to_string(i) + " has no direction");
    }
  }
}

}  // namespace

FrameLighting frameLighting(const DrawFrame& frame, const std::optional<BoundingSphere>& bound,
                            int shadow_map_size) {
  checkLights(frame.lights);
  FrameLighting lit;
  // Shadows need something to cast them; the first light that asks gets them.
  int shadow_light = -1;
  for (std::size_t i = 0; i < frame.lights.size() && bound; ++i) {
    if (frame.lights[i].casts_shadows) {
      shadow_light = static_cast<int>(i);
      break;
    }
  }
  auto add = [&lit](const DirectionalLight& light) {
    lit.to_light.push_back(-light.direction.normalized());
    lit.rgb.push_back(light.colour * light.intensity);
  };
  if (shadow_light >= 0) {
    const DirectionalLight& light = frame.lights[static_cast<std::size_t>(shadow_light)];
    add(light);
    lit.shadows = true;
    lit.shadow = fitShadow(light.direction, *bound, shadow_map_size);
  }
  for (std::size_t i = 0; i < frame.lights.size(); ++i) {
    if (static_cast<int>(i) != shadow_light) add(frame.lights[i]);
  }
  if (frame.ground.present) {
    lit.fade_start_m = kFadeStartFraction * frame.ground.extent_m;
    lit.fade_end_m = kFadeEndFraction * frame.ground.extent_m;
  }
  return lit;
}

void applyLighting(const GlProgram& program, const DrawFrame& frame, const FrameLighting& lit) {
  const auto count = static_cast<GLsizei>(lit.to_light.size());
  if (count > 0) {
    glUniform3fv(program.uniform("u_light_to"), count, lit.to_light[0].data());
    glUniform3fv(program.uniform("u_light_rgb"), count, lit.rgb[0].data());
  }
  glUniform3fv(program.uniform("u_ambient"), 1, frame.ambient.data());
  glUniform3fv(program.uniform("u_eye"), 1, frame.camera.eye.data());
  glUniform3fv(program.uniform("u_background"), 1, frame.background.data());
  glUniform1f(program.uniform("u_fade_start_m"), lit.fade_start_m);
  glUniform1f(program.uniform("u_fade_end_m"), lit.fade_end_m);
  if (lit.shadows) {
    glUniform1i(program.uniform("u_shadow_map"), 0);
    glUniformMatrix4fv(program.uniform("u_light_view_proj"), 1, GL_FALSE,
                       lit.shadow.view_projection.data());
    glUniform1f(program.uniform("u_shadow_texel_m"), lit.shadow.texel_m);
  }
}

}  // namespace tumble::render
