// Picks the FrameSink for an output target: the one place that knows every backend.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "io/frame_sink.h"
#include "io/output_path.h"
#include "io/provenance.h"

namespace tumble {

struct SinkOptions {
  int width = 1280, height = 720;   // pixels (even, for video)
  int fps = 30;                     // frames per second (video only)
  int crf = 23;                     // x264 constant rate factor (video only)
  bool overwrite = false;           // replace existing outputs (-y)
  bool skip_existing = false;       // keep existing PNG frames (--skip-existing); ignored for video
  std::optional<Provenance> provenance;   // written into every PNG, and a video's metadata
};

std::unique_ptr<FrameSink> makeFrameSink(const OutputTarget& target, const SinkOptions& options);

// Ends a render's output and says where it went: finished as asked, or, when the render was
// interrupted, a video finalised (playable) under its ".partial" name, never the final one.
std::string finishFrameSink(std::unique_ptr<FrameSink>& sink, const OutputTarget& target, bool interrupted);

// A sink that discards frames, for timing the renderer or simulating without output.
std::unique_ptr<FrameSink> makeNullSink();

}  // namespace tumble
