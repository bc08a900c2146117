// Frames as numbered PNG files (or one PNG), each written atomically as it arrives.
#pragma once

#include <optional>
#include <string>

#include "io/frame_sink.h"
#include "io/output_path.h"
#include "io/provenance.h"

namespace tumble {

class PngSequenceSink : public FrameSink {
 public:
  // Creates the folder. `overwrite`: replace existing frames (otherwise an existing frame is an
  // Error(CantCreate), never silently replaced). `skip_existing`: leave existing frames as they are
  // and count them as done, for resuming an interrupted render. With `provenance`, every frame
  // carries it as text chunks (frameText).
  PngSequenceSink(const OutputTarget& target, bool overwrite, bool skip_existing,
                  std::optional<Provenance> provenance = std::nullopt);

  void write(const RgbImage& image, int frame_number) override;
  void finish() override {}   // every frame is complete once write() returns
  std::string describe() const override;
  void setRenderer(const std::string& renderer) override {
    if (provenance_) provenance_->renderer = renderer;
  }

  int framesWritten() const { return written_; }
  int framesSkipped() const { return skipped_; }

 private:
  OutputTarget target_;
  bool overwrite_, skip_existing_;
  std::optional<Provenance> provenance_;
  int written_ = 0, skipped_ = 0;
};

}  // namespace tumble
