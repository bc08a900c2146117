#include "bench/canvas.h"

#include <algorithm>
#include <cstdlib>

namespace tumble::bench {

Canvas::Canvas(int width, int height, Rgb background) {
  image_.width = width;
  image_.height = height;
  image_.pixels.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < image_.pixels.size(); i += 3)
    std::copy(background.begin(), background.end(), image_.pixels.begin() + static_cast<long>(i));
}

void Canvas::pixel(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
  const std::size_t at = (static_cast<std::size_t>(y) * image_.width + x) * 3;
  std::copy(c.begin(), c.end(), image_.pixels.begin() + static_cast<long>(at));
}

void Canvas::fillRect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y)
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) pixel(x, y, c);
}

void Canvas::line(int x0, int y0, int x1, int y1, Rgb c, int thickness) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  const int lo = -(thickness - 1) / 2, hi = thickness / 2;
  for (int err = dx + dy;;) {
    fillRect(x0 + lo, y0 + lo, x0 + hi, y0 + hi, c);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) { err += dy; x0 += sx; }
    if (e2 <= dx) { err += dx; y0 += sy; }
  }
}

void Canvas::dashedHLine(int x0, int x1, int y, Rgb c) {
  for (int x = x0; x <= x1; ++x)
    if ((x / 3) % 2 == 0) pixel(x, y, c);
}

int Canvas::text(int x, int y, const std::string& s, Rgb c, int scale) {
  int pen = x;
  for (char ch : s) {
    const auto& rows = glyph(ch);
    for (int r = 0; r < 7; ++r)
      for (int col = 0; col < 5; ++col)
        if (rows[r] & (0x10 >> col)) fillRect(pen + col * scale, y + r * scale, pen + col * scale + scale - 1,
                                               y + r * scale + scale - 1, c);
    pen += 6 * scale;
  }
  return pen - x;
}

}  // namespace tumble::bench
