#include "io/png_sequence_sink.h"

#include <system_error>

#include "io/atomic_file.h"
#include "io/png_file.h"

namespace tumble {

namespace fs = std::filesystem;

PngSequenceSink::PngSequenceSink(const OutputTarget& target, bool overwrite, bool skip_existing,
                                 std::optional<Provenance> provenance)
    : target_(target), overwrite_(overwrite), skip_existing_(skip_existing), provenance_(std::move(provenance)) {
  fs::path folder = target_.path.parent_path();
  std::error_code ec;
  if (!folder.empty()) fs::create_directories(folder, ec);
  if (ec) throwCantWrite(folder, ec.message());
}

void PngSequenceSink::write(const RgbImage& image, int frame_number) {
  fs::path path = framePath(target_, frame_number);
  std::error_code ec;
  if (skip_existing_ && !overwrite_ && fs::exists(path, ec)) {
    ++skipped_;
    return;
  }
  writePng(path, image, overwrite_, provenance_ ? frameText(*provenance_, frame_number) : std::vector<PngText>{});
  ++written_;
}

std::string PngSequenceSink::describe() const { return target_.path.string(); }

}  // namespace tumble
