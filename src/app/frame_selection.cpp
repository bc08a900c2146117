#include "app/frame_selection.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include "base/error.h"

namespace tumble {
namespace {

[[noreturn]] void usage(const std::string& message) { throw Error(ExitCode::Usage, message); }

void checkInRange(int frame, int total, const std::string& flag) {
  if (frame < 1 || frame > total)
    usage(flag + ": frame " + std::to_string(frame) + " is outside the scene's frames 1.." +
          std::to_string(total));
}

std::vector<int> parseList(const std::string& list, int total) {
  static const std::regex item(R"(\s*(\d{1,9})\s*(?:\.\.\s*(\d{1,9})\s*)?)");
  std::vector<int> frames;
  std::stringstream in(list);
  std::string part;
  while (std::getline(in, part, ',')) {
    std::smatch m;
    if (!std::regex_match(part, m, item))
      usage("--frames: \"" + part + "\" is not a frame number or a range like 10..20");
    int first = std::stoi(m[1]);
    int last = m[2].matched ? std::stoi(m[2]) : first;
    if (last < first) usage("--frames: the range " + part + " runs backwards");
    checkInRange(first, total, "--frames");
    checkInRange(last, total, "--frames");
    for (int f = first; f <= last; ++f) frames.push_back(f);
  }
  if (frames.empty()) usage("--frames: the list is empty");
  return frames;
}

}  // namespace

std::vector<int> selectFrames(int total, std::optional<int> start, std::optional<int> end,
                              const std::string& list) {
  if (!list.empty() && (start || end)) usage("--frames cannot be combined with --start/--end");
  std::vector<int> frames;
  if (!list.empty()) {
    frames = parseList(list, total);
  } else {
    int first = start.value_or(1), last = end.value_or(total);
    checkInRange(first, total, "--start");
    checkInRange(last, total, "--end");
    if (last < first) usage("--end " + std::to_string(last) + " is before --start " + std::to_string(first));
    for (int f = first; f <= last; ++f) frames.push_back(f);
  }
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

}  // namespace tumble
