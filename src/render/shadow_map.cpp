#include "render/shadow_map.h"

#include <string>

#include "base/error.h"
#include "render/gl_check.h"

namespace tumble::render {

namespace {

// Slope-scaled bias for the depth written by casters: the slope term grows where a surface is
// grazing to the light (where acne appears); the constant term covers depth quantisation. Small
// enough that shadows stay attached at contacts (no peter-panning); the receiver also moves its
// lookup one texel along its normal in the shader.
constexpr float kOffsetSlope = 2.0f;
constexpr float kOffsetUnits = 4.0f;
constexpr int kMinSize = 64;

}  // namespace

ShadowMap::ShadowMap(int size) : size_(size) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (size < kMinSize || size > max_size) {
    throw Error(ExitCode::BadInput, "shadow map size " + std::to_string(size) +
                                        " is outside [" + std::to_string(kMinSize) + ", " +
                                        std::to_string(max_size) + "]");
  }
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_INT, nullptr);
  // NEAREST: each lookup is one depth comparison. The shaders take several of them spread over
  // the pixel instead of one LINEAR (2x2 bilinear) lookup: on llvmpipe a LINEAR comparison costs
  // about eight NEAREST ones, and the spread is what smooths the edge (see lighting.glsl).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  // Outside the fitted box there are no casters: the border depth 1 compares as lit.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[] = {1, 1, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);

  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  throwIfFramebufferIncomplete("the shadow map");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  throwIfGlError("creating the shadow map");
}

ShadowMap::~ShadowMap() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (texture_) glDeleteTextures(1, &texture_);
}

void ShadowMap::beginPass() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, size_, size_);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(kOffsetSlope, kOffsetUnits);
}

void ShadowMap::endPass() const { glDisable(GL_POLYGON_OFFSET_FILL); }

void ShadowMap::bindTexture(GLenum unit) const {
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, texture_);
}

}  // namespace tumble::render
