#include "render/gl_program.h"

#include "base/error.h"

namespace tumble::render {

namespace {

// Splits "#version ...\n<rest>" so libraries can go between the two. #line directives keep the
// compiler's line numbers true to each file: string number 0 is the main file, 1.. the libraries.
std::vector<std::string> assembleStage(const ShaderSource& source, const ShaderStageFiles& files,
                                       const std::string& defines) {
  std::string main = source.read(files.main);
  const auto eol = main.find('\n');
  if (main.rfind("#version", 0) != 0 || eol == std::string::npos) {
    throw Error(ExitCode::BadInput,
                source.describe(files.main) + ": the first line must be a #version directive");
  }
  std::vector<std::string> parts{main.substr(0, eol + 1), defines};
  for (std::size_t i = 0; i < files.libraries.size(); ++i) {
    parts.push_back("#line 1 " + std::to_string(i + 1) + "\n");
    parts.push_back(source.read(files.libraries[i]) + "\n");
  }
  parts.push_back("#line 2 0\n");
  parts.push_back(main.substr(eol + 1));
  return parts;
}

std::string describeSources(const ShaderSource& source, const ShaderStageFiles& files) {
  std::string text = source.describe(files.main);
  for (std::size_t i = 0; i < files.libraries.size(); ++i) {
    text += ", " + std::to_string(i + 1) + ": " + source.describe(files.libraries[i]);
  }
  return text;
}

GLuint compileStage(GLenum type, const ShaderSource& source, const ShaderStageFiles& files,
                    const std::string& defines) {
  const std::vector<std::string> parts = assembleStage(source, files, defines);
  std::vector<const char*> pointers;
  for (const auto& p : parts) pointers.push_back(p.c_str());

  GLuint shader = glCreateShader(type);
  glShaderSource(shader, static_cast<GLsizei>(pointers.size()), pointers.data(), nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;

  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  glDeleteShader(shader);
  throw Error(ExitCode::BadInput, "GLSL compile error in " + source.describe(files.main) +
                                      " (source numbers in the log: 0: " +
                                      describeSources(source, files) + "):\n" + log.c_str());
}

}  // namespace

GlProgram::GlProgram(const ShaderSource& source, const ShaderStageFiles& vertex,
                     const ShaderStageFiles& fragment, const std::string& defines) {
  GLuint vs = compileStage(GL_VERTEX_SHADER, source, vertex, defines);
  GLuint fs = 0;
  try {
    fs = compileStage(GL_FRAGMENT_SHADER, source, fragment, defines);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  // The program keeps the compiled code; the shader objects can go now.
  glDeleteShader(vs);
  glDeleteShader(fs);

  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok) return;
  GLint length = 0;
  glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
  glDeleteProgram(id_);
  id_ = 0;
  throw Error(ExitCode::BadInput, "GLSL link error for " + source.describe(vertex.main) + " + " +
                                      source.describe(fragment.main) + ":\n" + log.c_str());
}

GlProgram::~GlProgram() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace tumble::render
