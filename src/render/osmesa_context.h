// An OSMesa OpenGL 3.3+ core-profile context. It is made current on a tiny OSMesa buffer that is
// never drawn to: all rendering goes into the renderer's own framebuffer objects.
#pragma once

#include <cstdint>
#include <vector>

namespace tumble::render {

class OsmesaContext {
 public:
  // Throws Error(Unavailable) with an install hint when OSMesa cannot make a core context.
  OsmesaContext();
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  // GL contexts are current per thread; call before any GL work on this context. Cheap when it
  // is already current, so several renderers can take turns on one thread.
  void makeCurrent();

 private:
  void* context_ = nullptr;                // OSMesaContext, kept opaque so osmesa.h stays private
  std::vector<std::uint8_t> buffer_;       // the 1x1 RGBA buffer OSMesa insists on
};

}  // namespace tumble::render
