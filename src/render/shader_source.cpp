#include "render/shader_source.h"

#include <fstream>
#include <sstream>

#include "base/error.h"
#include "render/embedded_shaders.h"

namespace tumble::render {

std::string ShaderSource::read(const std::string& name) const {
  if (dir_.empty()) {
    for (const EmbeddedShader& shader : embeddedShaders())
      if (shader.name == name) return std::string(shader.text);
    throw Error(ExitCode::MissingInput, "no built-in shader " + name);
  }
  const std::filesystem::path path = dir_ / name;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw Error(ExitCode::MissingInput,
                "cannot read shader " + path.string() +
                    " (the folder comes from --shaders or TUMBLE_SHADER_DIR; without either, "
                    "tumble uses its built-in shaders)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string ShaderSource::describe(const std::string& name) const {
  return dir_.empty() ? name + " (built in)" : (dir_ / name).string();
}

}  // namespace tumble::render
