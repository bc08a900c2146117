// H.264 video through libavformat/libavcodec (libx264): yuv420p, BT.709 tags, constant frame rate
// with exact timestamps, faststart for MP4. The container follows the file extension.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "base/image.h"

namespace tumble {

struct VideoSettings {
  int width = 1280, height = 720;   // pixels; must be even for yuv420p
  int fps = 30;                     // frames per second
  int crf = 23;                     // x264 constant rate factor: 0 lossless .. 51 worst
  std::string preset = "veryfast";  // x264 preset
  // Encoder threads; 0 lets x264 choose from the core count. Output bytes are identical run to
  // run for a given count, but differ between counts: fix it (e.g. 4) for byte-identical videos
  // across machines.
  int threads = 0;
  // Container metadata (key, value): MP4/MOV keep keys of their own as well (use_metadata_tags).
  std::vector<std::pair<std::string, std::string>> metadata;
};

// libav and x264 print statistics and notes on stderr, which would break up the progress bar.
// Unless this is called, the first VideoWriter limits them to warnings and errors; `--verbose`
// can call setVideoLogVerbose(true) to see everything.
void setVideoLogVerbose(bool verbose);

class VideoWriter {
 public:
  // Opens `path` for writing. Throws tumble::Error: Unavailable when libx264 is missing,
  // CantCreate when the file cannot be created, BadInput for odd sizes.
  VideoWriter(const std::filesystem::path& path, const VideoSettings& settings);
  ~VideoWriter();   // closes without finishing if finish() was not called
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void write(const RgbImage& image);   // frames in order; size must match the settings
  void finish();                       // flushes the encoder and writes the trailer
  int framesWritten() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tumble
