#include "render/overlay_composite.h"

#include <algorithm>

namespace tumble {

void compositeOver(RgbImage& frame, const RgbaImage& layer, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(frame.width, x + layer.width);
  const int y0 = std::max(0, y), y1 = std::min(frame.height, y + layer.height);
  for (int row = y0; row < y1; ++row)
    for (int col = x0; col < x1; ++col) {
      const std::uint8_t* src =
          &layer.pixels[(static_cast<std::size_t>(row - y) * layer.width + static_cast<std::size_t>(col - x)) * 4];
      const unsigned keep = 255u - src[3];
      if (keep == 255u) continue;   // transparent
      std::uint8_t* dst = &frame.pixels[(static_cast<std::size_t>(row) * frame.width + static_cast<std::size_t>(col)) * 3];
      for (int c = 0; c < 3; ++c) dst[c] = static_cast<std::uint8_t>(src[c] + (dst[c] * keep + 127u) / 255u);
    }
}

}  // namespace tumble
