#include "render/gl_check.h"

#include <sstream>

#include "base/error.h"

namespace tumble::render {

namespace {

const char* glErrorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}

}  // namespace

void throwIfGlError(const std::string& what) {
  GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  // GL may queue several flags; drain them so the next check starts clean.
  while (glGetError() != GL_NO_ERROR) {
  }
  std::ostringstream msg;
  msg << "OpenGL error while " << what << ": " << glErrorName(first) << " (0x" << std::hex << first
      << ")";
  throw Error(ExitCode::Unavailable, msg.str());
}

void throwIfFramebufferIncomplete(const std::string& what) {
  GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  std::ostringstream msg;
  msg << "the off-screen framebuffer for " << what << " is incomplete (status 0x" << std::hex
      << status << "); this OpenGL (OSMesa) does not support it";
  throw Error(ExitCode::Unavailable, msg.str());
}

}  // namespace tumble::render
