// Where the renderer's GLSL comes from: the copy embedded at build time, which is the default so
// that an installed binary needs no source tree, or a folder read at run time (render --shaders,
// TUMBLE_SHADER_DIR), so that shader edits can be tried without rebuilding.
#pragma once

#include <filesystem>
#include <string>

namespace tumble::render {

class ShaderSource {
 public:
  // An empty folder means the embedded copy.
  explicit ShaderSource(std::filesystem::path dir = {}) : dir_(std::move(dir)) {}

  // The text of a shader file such as "lit.frag"; throws Error(MissingInput) naming it when the
  // file cannot be read.
  std::string read(const std::string& name) const;
  // How messages name that file: "DIR/lit.frag", or "lit.frag (built in)".
  std::string describe(const std::string& name) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace tumble::render
