// Test pictures that look a little like renders: a vertical sky gradient, a checkered floor with
// fine texture, and a shaded square that moves with the frame number. Deterministic.
#pragma once

#include <cstdint>

#include "base/image.h"

namespace tumble::test {

inline RgbImage syntheticImage(int width, int height, int frame) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<std::size_t>(width) * height * 3);
  const int horizon = height / 2;
  const int size = height / 4, left = (frame * 5) % (width - size), top = height / 5;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(y) * width + x) * 3];
      if (x >= left && x < left + size && y >= top && y < top + size) {
        int shade = 120 + 100 * (x - left) / size;   // lit from the right
        p[0] = static_cast<std::uint8_t>(shade);
        p[1] = static_cast<std::uint8_t>(shade / 3);
        p[2] = 40;
      } else if (y < horizon) {
        p[0] = static_cast<std::uint8_t>(90 + 60 * y / horizon);
        p[1] = static_cast<std::uint8_t>(140 + 50 * y / horizon);
        p[2] = 230;
      } else {
        bool dark = ((x / 32) + (y / 16)) % 2;
        int grain = ((x * 7919 + y * 104729 + frame * 31) >> 3) % 9;   // fine texture
        int v = (dark ? 70 : 180) + grain;
        p[0] = p[1] = p[2] = static_cast<std::uint8_t>(v);
      }
    }
  }
  return image;
}

inline double meanChannel(const RgbImage& image, int channel) {
  double sum = 0;
  for (std::size_t i = static_cast<std::size_t>(channel); i < image.pixels.size(); i += 3) {
    sum += image.pixels[i];
  }
  return sum / (static_cast<double>(image.pixels.size()) / 3);
}

}  // namespace tumble::test
