// A tiny raster canvas for the benchmark plots: pixels, lines, rectangles and 5x7 bitmap text on
// an RgbImage, which src/io writes as PNG. Enough for a log-log chart without a plotting library.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "base/image.h"

namespace tumble::bench {

using Rgb = std::array<std::uint8_t, 3>;

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);

  void pixel(int x, int y, Rgb c);
  void fillRect(int x0, int y0, int x1, int y1, Rgb c);   // inclusive corners
  // A line `thickness` pixels wide (Bresenham, stamped with a square brush).
  void line(int x0, int y0, int x1, int y1, Rgb c, int thickness = 1);
  void dashedHLine(int x0, int x1, int y, Rgb c);
  // Text in the 5x7 font scaled by `scale`; lower case is drawn as upper case. Returns the width.
  int text(int x, int y, const std::string& s, Rgb c, int scale = 1);
  static int textWidth(const std::string& s, int scale = 1) { return static_cast<int>(s.size()) * 6 * scale; }

  const RgbImage& image() const { return image_; }

 private:
  RgbImage image_;
};

// Rows of a glyph, bit 4 = leftmost column; unknown characters draw as a box.
const std::array<std::uint8_t, 7>& glyph(char c);

}  // namespace tumble::bench
