// Comparing frames with approved ones, shared by `tumble diff` and `tumble render --check-against`:
// the threshold flags, one report line per frame, the overall summary and the exit code
// (0 pass, 1 fail, 2 bad input), which the callers return themselves rather than through
// tumble::Error, whose codes mean other things.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "io/image_compare.h"

namespace tumble {

// The exit codes of comparisons, as diff(1), cmp(1) and idiff use them.
enum class CheckExit : int { Pass = 0, Fail = 1, BadInput = 2 };

struct CheckOptions {
  CompareSettings settings{1, 0.0};   // see addCheckOptions for why
  std::string diff_out;               // folder for the diff images; empty: next to the frames
};

// Adds --threshold, --max-fail and --diff-out to a subcommand.
void addCheckOptions(CLI::App& command, CheckOptions& options);

// Collects the results of one run and prints them.
class CheckReport {
 public:
  CheckReport(CompareSettings settings, bool print_passing) : settings_(settings), print_passing_(print_passing) {}

  // Compares `a` with `b` under `label`; on failure writes the diff image to `diff_path`.
  // Returns whether the frame passed. A size mismatch counts as bad input.
  bool compare(const std::string& label, const RgbImage& a, const RgbImage& b,
               const std::filesystem::path& diff_path);
  // A frame that could not be compared (missing file, unreadable PNG), said plainly.
  void badInput(const std::string& message);

  // "tumble diff: 3 frames: ...": the overall figures.
  void printSummary(const std::string& who) const;
  int exitCode() const;
  int compared() const { return compared_; }

 private:
  CompareSettings settings_;
  bool print_passing_;
  int compared_ = 0, failed_ = 0, bad_ = 0, max_diff_ = 0;
  long long failing_pixels_ = 0, pixels_ = 0;
  double sum_sq_ = 0;
};

// The diff image's name for a frame file: "frame_0001.png" -> "frame_0001.diff.png", in
// `folder` when it is not empty, else next to the frame.
std::filesystem::path diffPathFor(const std::filesystem::path& frame, const std::string& folder);

// render --check-against: compares a rendered frame with GOLDEN_DIR/frame_####.png of the same
// number. The diff image goes to `diff_out`, else next to `frame_file` (the frame's PNG, or where
// it would be for a video output).
void checkAgainstGolden(CheckReport& report, const std::string& golden_dir, const RgbImage& image, int frame,
                        const std::filesystem::path& frame_file, const std::string& diff_out);

}  // namespace tumble
