// Frames as numbered PNG files (or one PNG), each written atomically as it arrives.
#pragma once

#include <string>

#include "io/frame_sink.h"
#include "io/output_path.h"

namespace tumble {

class PngSequenceSink : public FrameSink {
 public:
  // Creates the folder. `overwrite`: replace existing frames (otherwise an existing frame is an
  // Error(CantCreate), never silently replaced). `skip_existing`: leave existing frames as they are
  // and count them as done, for resuming an interrupted render.
  PngSequenceSink(const OutputTarget& target, bool overwrite, bool skip_existing);

  void write(const RgbImage& image, int frame_number) override;
  void finish() override {}   // every frame is complete once write() returns
  std::string describe() const override;

  int framesWritten() const { return written_; }
  int framesSkipped() const { return skipped_; }

 private:
  OutputTarget target_;
  bool overwrite_, skip_existing_;
  int written_ = 0, skipped_ = 0;
};

}  // namespace tumble
