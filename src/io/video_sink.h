// Frames as one H.264 video. The video is encoded under a hidden temporary name in the target's
// folder and renamed to the final name by finish(), so the final name only ever holds a complete
// video. If the sink is destroyed before finish() (an error or Ctrl-C unwinding the render), the
// frames so far are still flushed into a playable file named "<stem>.partial<ext>"
// ("out/drop.partial.mp4"); nothing is left if no frame was written.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "io/frame_sink.h"
#include "io/output_path.h"
#include "io/video_writer.h"

namespace tumble {

class VideoSink : public FrameSink {
 public:
  // Creates the folder and opens the encoder. Without `overwrite` an existing video is an
  // Error(CantCreate), checked here (before any work) and again at the final rename.
  VideoSink(const OutputTarget& target, const VideoSettings& settings, bool overwrite);
  ~VideoSink() override;

  // Frames must arrive in order without gaps: a video has no place for a missing frame.
  void write(const RgbImage& image, int frame_number) override;
  void finish() override;
  std::string describe() const override;

  // Flushes what was written into "<stem>.partial<ext>" and returns that path (empty if there was
  // nothing to keep). The destructor calls this when finish() was not called.
  std::filesystem::path finishPartial();

  static std::filesystem::path partialPath(const std::filesystem::path& final_path);

 private:
  std::filesystem::path final_, temp_;
  bool overwrite_;
  bool done_ = false;
  std::unique_ptr<VideoWriter> writer_;
};

}  // namespace tumble
