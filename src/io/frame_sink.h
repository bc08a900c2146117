// Where rendered frames go: a PNG sequence, a video, or nowhere. One interface, one file per backend.
#pragma once

#include <memory>
#include <string>

#include "base/image.h"

namespace tumble {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // `frame_number` is the user-facing number (frames count from 1), used for PNG names.
  virtual void write(const RgbImage& image, int frame_number) = 0;
  // Completes the output (flushes the encoder, writes the trailer, renames from the temporary
  // name to the final one). Outputs are never left half-written under their final name.
  virtual void finish() = 0;
  // What the user should be told was written, e.g. "out/drop.mp4" or "out/drop/frame_####.png".
  virtual std::string describe() const = 0;
  // The OpenGL renderer's name (GL_RENDERER), known once the renderer exists, for the frames'
  // provenance; outputs that do not record it ignore it.
  virtual void setRenderer(const std::string& /*renderer*/) {}
};

}  // namespace tumble
