// A GLSL program built from shader files (built in, or from a folder: see shader_source.h).
// Shared code (lighting, sRGB) lives in library files spliced into a stage right after its
// #version line, preceded by the program's #defines (its variant).
#pragma once

#include <string>
#include <vector>

#include "render/gl_api.h"
#include "render/shader_source.h"

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
  GlProgram(const ShaderSource& source, const ShaderStageFiles& vertex,
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
