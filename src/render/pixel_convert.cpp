#include "render/pixel_convert.h"

#include <algorithm>
#include <cmath>

namespace tumble::render {

void rgbaBottomUpToRgbTopDown(const std::vector<std::uint8_t>& rgba, int width, int height,
                              RgbImage& out) {
  const auto w = static_cast<std::size_t>(width);
  const auto h = static_cast<std::size_t>(height);
  out.width = width;
  out.height = height;
  out.pixels.resize(w * h * 3);
  for (std::size_t row = 0; row < h; ++row) {
    const std::uint8_t* src = rgba.data() + (h - 1 - row) * w * 4;
    std::uint8_t* dst = out.pixels.data() + row * w * 3;
    for (std::size_t x = 0; x < w; ++x) {
      dst[3 * x + 0] = src[4 * x + 0];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
}

float encodeSrgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c < 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace tumble::render
