#include "render/overlay_composite.h"

#include "base/error.h"

namespace tumble {

void compositeOver(RgbImage& frame, const RgbaImage& layer) {
  if (frame.width != layer.width || frame.height != layer.height)
    throw Error(ExitCode::Software, "overlay layer of " + std::to_string(layer.width) + "x" +
                                        std::to_string(layer.height) + " over a frame of " +
                                        std::to_string(frame.width) + "x" + std::to_string(frame.height));
  const std::size_t n = static_cast<std::size_t>(frame.width) * frame.height;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* src = &layer.pixels[4 * i];
    const unsigned keep = 255u - src[3];
    if (keep == 255u) continue;   // transparent: most of the frame
    std::uint8_t* dst = &frame.pixels[3 * i];
    for (int c = 0; c < 3; ++c) dst[c] = static_cast<std::uint8_t>(src[c] + (dst[c] * keep + 127u) / 255u);
  }
}

}  // namespace tumble
