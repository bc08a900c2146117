// Decodes a whole video with libavformat/libavcodec, for tests that check what was written
// (the io round trip here, the app's end-to-end test). Not part of tumble itself.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "base/image.h"

namespace tumble::test {

struct DecodedVideo {
  int width = 0, height = 0;
  double fps = 0;              // the stream's average frame rate
  double duration = 0;         // seconds: the stream's duration, else the container's
  std::string codec;           // "h264"
  std::string pix_fmt;         // "yuv420p"
  std::string color_primaries; // "bt709"
  std::string color_space;     // the matrix, "bt709"
  std::string color_range;     // "tv" (limited) or "pc" (full)
  std::vector<RgbImage> frames;                   // decoded to RGB with the tagged matrix and range
  std::vector<std::vector<std::uint8_t>> luma;    // each frame's Y plane as coded, width*height
};

// Throws std::runtime_error with the libav reason when the file cannot be decoded.
DecodedVideo decodeVideo(const std::filesystem::path& path);

// The top-level box types of an MP4/MOV file in order ("ftyp", "moov", "mdat", ...).
std::vector<std::string> topLevelBoxes(const std::filesystem::path& path);

}  // namespace tumble::test
