// Comparing two frames the way visual regression tools do (OpenImageIO's idiff, Blender's render
// tests): a per-channel threshold says which pixels differ, and the share of such pixels that is
// allowed decides pass or fail. The numbers reported are the largest per-channel difference, the
// count and share of pixels over the threshold, and PSNR.
#pragma once

#include <string>

#include "base/image.h"

namespace tumble {

struct CompareSettings {
  int threshold = 0;       // a pixel fails when any channel differs by more than this (0..255)
  double max_fail = 0.0;   // the share of failing pixels allowed, 0..1
};

struct CompareResult {
  bool same_size = true;
  int max_diff = 0;          // largest per-channel difference, 0..255
  long long failing = 0;     // pixels whose any-channel difference exceeds the threshold
  long long pixels = 0;      // pixels compared
  double psnr_db = 0;        // +infinity when identical
  double sum_sq = 0;         // sum of squared channel differences (for an overall PSNR)
  bool pass = false;

  double failShare() const { return pixels > 0 ? static_cast<double>(failing) / pixels : 0.0; }
};

// Images of different sizes are not compared: same_size is false and pass is false.
CompareResult compareImages(const RgbImage& a, const RgbImage& b, const CompareSettings& settings);

// PSNR in dB for 8-bit channels from a sum of squared differences over `channels` values;
// +infinity for a zero sum.
double psnrFromSquares(double sum_sq, long long channels);

// "W x H" for messages about sizes.
std::string describeSize(const RgbImage& image);

// A picture of what changed: a faded grey copy of `a`, with every pixel whose difference exceeds
// `threshold` in saturated magenta (a colour renders of scenes rarely contain). Same size as `a`;
// `b` must have the same size.
RgbImage diffImage(const RgbImage& a, const RgbImage& b, int threshold);

}  // namespace tumble
