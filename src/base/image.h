// An 8-bit RGB picture, the currency between renderer, image files and video.
#pragma once

#include <cstdint>
#include <vector>

namespace tumble {

// Tightly packed 8-bit sRGB, top row first (row 0 is the top of the picture).
struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;   // width * height * 3
};

// 8-bit RGBA, top row first: a texture as decoded from its file (colour sRGB-encoded, alpha linear).
struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;   // width * height * 4
};

}  // namespace tumble
