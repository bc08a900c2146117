#include "io/make_frame_sink.h"

#include "io/png_sequence_sink.h"
#include "io/video_sink.h"

namespace tumble {

namespace {

class NullSink : public FrameSink {
 public:
  void write(const RgbImage&, int) override {}
  void finish() override {}
  std::string describe() const override { return "nothing (frames discarded)"; }
};

}  // namespace

std::unique_ptr<FrameSink> makeFrameSink(const OutputTarget& target, const SinkOptions& options) {
  if (target.kind == OutputTarget::Kind::PngSequence) {
    return std::make_unique<PngSequenceSink>(target, options.overwrite, options.skip_existing, options.provenance);
  }
  VideoSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.fps = options.fps;
  settings.crf = options.crf;
  if (options.provenance) settings.metadata = videoMetadata(*options.provenance);
  return std::make_unique<VideoSink>(target, settings, options.overwrite);
}

std::string finishFrameSink(std::unique_ptr<FrameSink>& sink, const OutputTarget& target, bool interrupted) {
  std::string written = sink->describe();
  if (interrupted && target.kind == OutputTarget::Kind::Video) {
    sink.reset();
    return VideoSink::partialPath(target.path).string();
  }
  sink->finish();
  return written;
}

std::unique_ptr<FrameSink> makeNullSink() { return std::make_unique<NullSink>(); }

}  // namespace tumble
