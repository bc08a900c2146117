#include "io/image_compare.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace tumble {

namespace {

// Largest per-channel difference of the pixel starting at byte i.
int pixelDiff(const std::uint8_t* a, const std::uint8_t* b, std::size_t i) {
  int d0 = std::abs(a[i] - b[i]), d1 = std::abs(a[i + 1] - b[i + 1]), d2 = std::abs(a[i + 2] - b[i + 2]);
  return std::max({d0, d1, d2});
}

}  // namespace

double psnrFromSquares(double sum_sq, long long channels) {
  if (sum_sq == 0 || channels == 0) return std::numeric_limits<double>::infinity();
  double mse = sum_sq / static_cast<double>(channels);
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

std::string describeSize(const RgbImage& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

CompareResult compareImages(const RgbImage& a, const RgbImage& b, const CompareSettings& settings) {
  CompareResult r;
  if (a.width != b.width || a.height != b.height) {
    r.same_size = false;
    return r;
  }
  r.pixels = static_cast<long long>(a.width) * a.height;
  const std::uint8_t* pa = a.pixels.data();
  const std::uint8_t* pb = b.pixels.data();
  // Integer sums: exact, and a 8192x8192 frame's squares (< 2^43) cannot overflow 64 bits.
  unsigned long long sum_sq = 0;
  for (std::size_t i = 0, n = a.pixels.size(); i < n; i += 3) {
    int d = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      int dc = std::abs(pa[i + c] - pb[i + c]);
      sum_sq += static_cast<unsigned>(dc * dc);
      d = std::max(d, dc);
    }
    r.max_diff = std::max(r.max_diff, d);
    r.failing += d > settings.threshold;
  }
  r.sum_sq = static_cast<double>(sum_sq);
  r.psnr_db = psnrFromSquares(r.sum_sq, 3 * r.pixels);
  r.pass = r.failShare() <= settings.max_fail;
  return r;
}

RgbImage diffImage(const RgbImage& a, const RgbImage& b, int threshold) {
  assert(a.width == b.width && a.height == b.height);
  RgbImage out = a;
  for (std::size_t i = 0, n = a.pixels.size(); i < n; i += 3) {
    std::uint8_t* p = &out.pixels[i];
    if (pixelDiff(a.pixels.data(), b.pixels.data(), i) > threshold) {
      p[0] = 255, p[1] = 0, p[2] = 255;
      continue;
    }
    // Faded grey: the luma pulled towards white keeps the scene recognisable but quiet, so the
    // magenta stands out.
    int luma = (54 * p[0] + 183 * p[1] + 19 * p[2]) >> 8;
    auto faded = static_cast<std::uint8_t>(160 + luma * 95 / 255);
    p[0] = p[1] = p[2] = faded;
  }
  return out;
}

}  // namespace tumble
