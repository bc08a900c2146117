// The GLSL of shaders/, compiled into the binary (cmake/embed_shaders.cmake writes the table at
// build time, again whenever a shader changes), so that tumble renders without the source tree.
#pragma once

#include <span>
#include <string_view>

namespace tumble::render {

struct EmbeddedShader {
  std::string_view name;   // file name in shaders/, e.g. "lit.frag"
  std::string_view text;   // the file's contents
};

std::span<const EmbeddedShader> embeddedShaders();

}  // namespace tumble::render
