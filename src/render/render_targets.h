// The off-screen colour+depth framebuffer the frame is drawn into, and (with MSAA) the
// single-sample framebuffer it is resolved into for reading back.
#pragma once

#include <cstdint>
#include <vector>

#include "render/gl_api.h"

namespace tumble::render {

class RenderTargets {
 public:
  // samples: 1 (no MSAA), 2 or 4. Throws Error(BadInput) for other counts or sizes, naming the
  // values that work; Error(Unavailable) if GL cannot make the framebuffers.
  RenderTargets(int width, int height, int samples);
  ~RenderTargets();
  RenderTargets(const RenderTargets&) = delete;
  RenderTargets& operator=(const RenderTargets&) = delete;

  void beginPass() const;  // binds the draw framebuffer and sets the viewport
  void resolve() const;    // MSAA -> single sample; nothing to do without MSAA
  // Reads the resolved RGBA8 pixels, bottom row first (GL's order).
  void readRgba(std::vector<std::uint8_t>& rgba) const;

 private:
  int width_, height_, samples_;
  GLuint draw_fbo_ = 0, colour_rb_ = 0, depth_rb_ = 0;  // multisampled when samples_ > 1
  GLuint resolve_fbo_ = 0, resolve_rb_ = 0;             // only when samples_ > 1
};

}  // namespace tumble::render
