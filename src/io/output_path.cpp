#include "io/output_path.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <system_error>

#include "base/error.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

// Where the frame number goes in a file name, and how wide it is.
struct NumberSlot {
  std::size_t begin = 0, length = 0;   // the characters to replace
  int pad = 0;
};

constexpr const char* kForms =
    "use out.mp4, out.mkv or out.mov for a video, or a PNG sequence: a folder ending in '/', "
    "'out/frame_####.png' or 'out/frame_%04d.png'";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// The last run of '#' (Blender), or else the last %d / %0Nd (ffmpeg, printf).
std::optional<NumberSlot> findSlot(const std::string& name) {
  std::size_t last = name.rfind('#');
  if (last != std::string::npos) {
    std::size_t first = name.find_last_not_of('#', last);
    first = first == std::string::npos ? 0 : first + 1;
    int pad = static_cast<int>(last - first + 1);
    return NumberSlot{first, last - first + 1, pad};
  }
  for (std::size_t p = name.rfind('%'); p != std::string::npos;
       p = p == 0 ? std::string::npos : name.rfind('%', p - 1)) {
    std::size_t q = p + 1;
    while (q < name.size() && std::isdigit(static_cast<unsigned char>(name[q]))) ++q;
    if (q < name.size() && name[q] == 'd') {
      int pad = q == p + 1 ? 1 : std::stoi(name.substr(p + 1, q - p - 1));
      return NumberSlot{p, q - p + 1, std::max(pad, 1)};
    }
  }
  return std::nullopt;
}

// "frame_####.png" and "frame_%04d.png" for the slot (other '%' escaped for printf).
void spellPattern(const std::string& name, const NumberSlot& slot, std::string& hashes,
                  std::string& printf_form) {
  std::string head = name.substr(0, slot.begin), tail = name.substr(slot.begin + slot.length);
  hashes = head + std::string(slot.pad, '#') + tail;
  auto escape = [](std::string s) {
    for (std::size_t i = s.find('%'); i != std::string::npos; i = s.find('%', i + 2)) {
      s.insert(i, 1, '%');
    }
    return s;
  };
  printf_form = escape(head) + "%0" + std::to_string(slot.pad) + "d" + escape(tail);
}

OutputTarget sequence(const fs::path& folder, const std::string& name, const NumberSlot& slot) {
  std::string hashes, printf_form;
  spellPattern(name, slot, hashes, printf_form);
  return {OutputTarget::Kind::PngSequence, folder / hashes, (folder / printf_form).string(),
          slot.pad};
}

bool isVideoExtension(const std::string& ext) {
  return ext == ".mp4" || ext == ".mkv" || ext == ".mov";
}

[[noreturn]] void usage(const std::string& message) { throw Error(ExitCode::Usage, message); }

}  // namespace

OutputTarget parseOutput(const std::string& arg, int frame_count) {
  if (arg.empty()) usage(std::string("-o needs a path: ") + kForms);
  std::error_code ec;
  if (arg.back() == '/' || fs::is_directory(arg, ec)) {
    return sequence(fs::path(arg), "frame_####.png", NumberSlot{6, 4, 4});
  }
  fs::path path(arg);
  std::string name = path.filename().string();
  std::string ext = lower(path.extension().string());
  if (isVideoExtension(ext)) return {OutputTarget::Kind::Video, path, arg, 0};
  if (ext != ".png") {
    usage("cannot write '" + arg + "': " +
          (ext.empty() ? std::string("no extension") : "'" + ext + "' is not supported") + "; " +
          kForms);
  }
  if (std::optional<NumberSlot> slot = findSlot(name)) {
    return sequence(path.parent_path(), name, *slot);
  }
  if (frame_count > 1) {
    std::string stem = (path.parent_path() / path.stem()).string();
    usage("'" + arg + "' names one file but " + std::to_string(frame_count) +
          " frames are rendered; number them with '" + stem + "_####.png' (or '" + stem +
          "_%04d.png'), or give a folder ending in '/'");
  }
  return {OutputTarget::Kind::PngSequence, path, arg, 0};
}

fs::path framePath(const OutputTarget& target, int frame_number) {
  if (target.kind == OutputTarget::Kind::Video || target.pad == 0) return target.path;
  std::string name = target.path.filename().string();
  std::size_t last = name.rfind('#');
  std::size_t first = last + 1 - static_cast<std::size_t>(target.pad);
  char digits[32];
  std::snprintf(digits, sizeof digits, "%0*d", target.pad, frame_number);
  name.replace(first, static_cast<std::size_t>(target.pad), digits);
  return target.path.parent_path() / name;
}

std::vector<fs::path> existingOutputs(const OutputTarget& target, const std::vector<int>& frames) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (target.kind == OutputTarget::Kind::Video || target.pad == 0) {
    if (fs::exists(target.path, ec)) found.push_back(target.path);
    return found;
  }
  for (int frame : frames) {
    fs::path p = framePath(target, frame);
    if (fs::exists(p, ec)) found.push_back(p);
  }
  return found;
}

}  // namespace tumble
