// The render tests' renderer settings: a small frame, shaders read from the source tree (so a test
// runs the GLSL as edited).
#pragma once

#include <filesystem>

#include "render/renderer.h"

namespace tumble::test {

inline RenderConfig testConfig(int width, int height, int shadow_map_size) {
  RenderConfig config;
  config.width = width;
  config.height = height;
  config.shadow_map_size = shadow_map_size;
  config.shader_dir = std::filesystem::path(TUMBLE_SOURCE_DIR) / "shaders";
  return config;
}

}  // namespace tumble::test
