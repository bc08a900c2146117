#include "app/frame_check.h"

#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "io/output_path.h"
#include "io/png_file.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

std::string formatPsnr(double psnr_db) {
  if (std::isinf(psnr_db)) return "inf (identical)";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f dB", psnr_db);
  return buffer;
}

// "max diff 37, 152 pixels over 8 (0.264 %), PSNR 41.20 dB"
std::string describe(int max_diff, long long failing, long long pixels, double psnr_db, int threshold) {
  char buffer[160];
  double share = pixels > 0 ? 100.0 * static_cast<double>(failing) / static_cast<double>(pixels) : 0.0;
  std::snprintf(buffer, sizeof buffer, "max diff %d, %lld of %lld pixels over %d (%.3f %%), PSNR %s", max_diff,
                failing, pixels, threshold, share, formatPsnr(psnr_db).c_str());
  return buffer;
}

}  // namespace

void addCheckOptions(CLI::App& command, CheckOptions& options) {
  // Default threshold 1, max-fail 0: any visible change fails, but an off-by-one from a different
  // sRGB rounding (another tool re-saving the PNG) does not. Renders of this build are
  // bit-identical, so the default never hides a real change; golden tests across Mesa builds
  // pass a looser tolerance explicitly (README, "Visual regression").
  command.add_option("--threshold", options.settings.threshold,
                     "Per-channel difference (0..255) a pixel may have and still match; default 1")
      ->check(CLI::Range(0, 255));
  command.add_option("--max-fail", options.settings.max_fail,
                     "Share of pixels (0..1) allowed over the threshold per frame; default 0")
      ->check(CLI::Range(0.0, 1.0));
  command.add_option("--diff-out", options.diff_out,
                     "Folder for the diff images of failing frames (default: next to the frames, NAME.diff.png)");
}

fs::path diffPathFor(const fs::path& frame, const std::string& folder) {
  fs::path name = frame.stem();
  name += ".diff.png";
  return folder.empty() ? frame.parent_path() / name : fs::path(folder) / name;
}

bool CheckReport::compare(const std::string& label, const RgbImage& a, const RgbImage& b, const fs::path& diff_path) {
  CompareResult r = compareImages(a, b, settings_);
  if (!r.same_size) {
    badInput(label + ": sizes differ: " + describeSize(a) + " vs " + describeSize(b));
    return false;
  }
  ++compared_;
  max_diff_ = std::max(max_diff_, r.max_diff);
  failing_pixels_ += r.failing;
  pixels_ += r.pixels;
  sum_sq_ += r.sum_sq;
  std::string line = label + ": " + describe(r.max_diff, r.failing, r.pixels, r.psnr_db, settings_.threshold);
  if (r.pass) {
    if (print_passing_) std::printf("%s: pass\n", line.c_str());
    return true;
  }
  ++failed_;
  try {
    writePng(diff_path, diffImage(a, b, settings_.threshold));
    std::printf("%s: FAIL (diff image %s)\n", line.c_str(), diff_path.string().c_str());
  } catch (const Error& e) {
    std::printf("%s: FAIL (no diff image: %s)\n", line.c_str(), e.what());
  }
  return false;
}

void CheckReport::badInput(const std::string& message) {
  ++bad_;
  std::fflush(stdout);   // keep the order of the frame lines and this one in a shared log
  std::fprintf(stderr, "tumble: %s\n", message.c_str());
}

void CheckReport::printSummary(const std::string& who) const {
  std::string verdict = exitCode() == 0 ? "pass" : exitCode() == 1 ? "FAIL" : "BAD INPUT";
  std::printf("%s: %s: %d frames compared, %d failed, %d not comparable; overall %s (threshold %d, max-fail %g %%)\n",
              who.c_str(), verdict.c_str(), compared_, failed_, bad_,
              describe(max_diff_, failing_pixels_, pixels_, psnrFromSquares(sum_sq_, 3 * pixels_), settings_.threshold)
                  .c_str(),
              settings_.threshold, 100.0 * settings_.max_fail);
}

void checkAgainstGolden(CheckReport& report, const std::string& golden_dir, const RgbImage& image, int frame,
                        const fs::path& frame_file, const std::string& diff_out) {
  fs::path golden = framePath(parseOutput(golden_dir + "/", 2), frame);
  try {
    report.compare("frame " + std::to_string(frame), readPng(golden), image, diffPathFor(frame_file, diff_out));
  } catch (const Error& e) {
    report.badInput(e.what());
  }
}

int CheckReport::exitCode() const {
  if (bad_ > 0 || compared_ == 0) return static_cast<int>(CheckExit::BadInput);
  return static_cast<int>(failed_ > 0 ? CheckExit::Fail : CheckExit::Pass);
}

}  // namespace tumble
