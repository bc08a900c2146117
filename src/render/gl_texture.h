// One uploaded albedo texture: sRGB storage, so the sampler returns linear colour for the
// shaders' linear-light maths (and filtering averages light, not encoded values), with a full
// mipmap chain and trilinear filtering so a texture seen from afar does not shimmer.
#pragma once

#include "render/draw_list.h"
#include "render/gl_api.h"

namespace tumble::render {

class GlTexture {
 public:
  // Throws Error(BadInput) for an empty image, a size that does not match its pixels, or a side
  // above the GL's maximum.
  explicit GlTexture(const DrawTexture& image);
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  void bind(GLenum unit) const;

 private:
  GLuint id_ = 0;
};

}  // namespace tumble::render
