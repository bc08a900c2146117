// A GLSL program built from files in the shader folder, loaded at run time so looks can be tuned
// without rebuilding. Shared code (lighting, sRGB) lives in library files spliced into a stage
// right after its #version line, preceded by the program's #defines (its variant).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/gl_api.h"

namespace tumble::render {

struct ShaderStageFiles {
  std::string main;                    // e.g. "lit.frag": holds #version and main()
  std::vector<std::string> libraries;  // e.g. {"lighting.glsl"}: spliced after #version
};

class GlProgram {
 public:
  // Throws Error(MissingInput) naming a file that cannot be read, Error(BadInput) with the GLSL
  // info log when a stage does not compile or the program does not link.
  // `defines` (e.g. "#define TUMBLE_LIGHT_COUNT 2\n") goes right after #version in both stages.
  GlProgram(const std::filesystem::path& dir, const ShaderStageFiles& vertex,
            const ShaderStageFiles& fragment, const std::string& defines = {});
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { glUseProgram(id_); }
  // -1 when the uniform does not exist or was optimised away; glUniform* ignores -1.
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace tumble::render
