// The shadow map: a square depth texture with its own framebuffer, sampled with hardware depth
// comparison (sampler2DShadow, NEAREST): each lookup is one comparison, and the shaders average
// several per pixel (percentage-closer filtering, see shaders/lighting.glsl).
#pragma once

#include "render/gl_api.h"

namespace tumble::render {

class ShadowMap {
 public:
  // Throws Error(BadInput) for a size outside [64, GL_MAX_TEXTURE_SIZE], Error(Unavailable) if
  // the depth-only framebuffer is not supported.
  explicit ShadowMap(int size);
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  // Binds the framebuffer and viewport and clears depth; polygon offset on (see the .cpp).
  void beginPass() const;
  void endPass() const;
  void bindTexture(GLenum unit) const;
  int size() const { return size_; }

 private:
  int size_ = 0;
  GLuint texture_ = 0, framebuffer_ = 0;
};

}  // namespace tumble::render
