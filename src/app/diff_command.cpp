// tumble diff A B: compares two PNG files, two folders of PNGs (matched by name), or two numbered
// sequences ('out/frame_####.png', 'out/frame_%04d.png', matched by number).
// Exit codes 0 pass, 1 fail, 2 bad input, returned here rather than thrown: main's codes for
// tumble::Error (65, 66, ...) mean other things, and diff tools answer 0/1/2.
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/frame_check.h"
#include "base/error.h"
#include "io/output_path.h"
#include "io/png_file.h"
#include "io/provenance.h"

namespace tumble {
namespace {

namespace fs = std::filesystem;

struct DiffOptions {
  std::string a, b;
  CheckOptions check;
  bool quiet = false;
};

struct FramePair {
  std::string label;
  fs::path a, b;   // either may be empty: the frame is missing on that side
};

bool isPattern(const std::string& s) {
  return s.find('#') != std::string::npos || s.find('%') != std::string::npos;
}

// The PNG files of a folder by name, leaving out the diff images earlier runs wrote.
std::map<std::string, fs::path> pngFiles(const fs::path& dir) {
  std::map<std::string, fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::string name = e.path().filename().string();
    bool png = name.size() > 4 && name.ends_with(".png") && !name.ends_with(".diff.png");
    if (png && e.is_regular_file()) files[name] = e.path();
  }
  return files;
}

// The frames on disk of a numbered sequence, by frame number.
std::map<int, fs::path> sequenceFiles(const std::string& pattern) {
  OutputTarget target = parseOutput(pattern, 2);
  std::string hashes = target.path.filename().string();
  std::size_t first = hashes.find('#');
  std::string head = hashes.substr(0, first), tail = hashes.substr(first + target.pad);
  fs::path dir = target.path.parent_path().empty() ? fs::path(".") : target.path.parent_path();
  std::map<int, fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::string name = e.path().filename().string();
    if (name.size() <= head.size() + tail.size() || !name.starts_with(head) || !name.ends_with(tail)) continue;
    std::string digits = name.substr(head.size(), name.size() - head.size() - tail.size());
    bool numeric = digits.size() >= static_cast<std::size_t>(target.pad) && digits.size() < 9 &&
                   std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (numeric) files[std::stoi(digits)] = e.path();
  }
  return files;
}

// Joins two keyed listings; a key on one side only becomes a pair with an empty path.
template <typename Key, typename Label>
std::vector<FramePair> join(const std::map<Key, fs::path>& a, const std::map<Key, fs::path>& b, Label label) {
  std::map<Key, FramePair> joined;
  for (const auto& [key, path] : a) joined[key] = FramePair{label(key), path, {}};
  for (const auto& [key, path] : b) {
    FramePair& p = joined[key];
    p.label = label(key);
    p.b = path;
  }
  std::vector<FramePair> pairs;
  for (auto& [key, pair] : joined) pairs.push_back(std::move(pair));
  return pairs;
}

// What A and B name, as pairs of files. Throws Error(BadInput) for arguments that do not match.
std::vector<FramePair> listPairs(const std::string& a, const std::string& b) {
  if (isPattern(a) != isPattern(b))
    throw Error(ExitCode::BadInput, "compare a pattern with a pattern ('####' or '%04d'), not with " +
                                        (isPattern(a) ? b : a));
  if (isPattern(a)) {
    return join(sequenceFiles(a), sequenceFiles(b), [](int n) { return "frame " + std::to_string(n); });
  }
  if (fs::is_directory(a) != fs::is_directory(b)) {
    const std::string& dir = fs::is_directory(a) ? a : b;
    const std::string& other = fs::is_directory(a) ? b : a;
    throw Error(ExitCode::BadInput, dir + " is a folder but " + other + " is not; compare a folder with a folder");
  }
  if (fs::is_directory(a)) return join(pngFiles(a), pngFiles(b), [](const std::string& n) { return n; });
  return {FramePair{fs::path(b).filename().string(), a, b}};
}

void comparePair(const FramePair& pair, const DiffOptions& o, CheckReport& report) {
  if (pair.a.empty() || pair.b.empty()) {
    report.badInput(pair.label + ": missing in " + (pair.a.empty() ? o.a : o.b));
    return;
  }
  try {
    RgbImage a = readPng(pair.a), b = readPng(pair.b);
    report.compare(pair.label, a, b, diffPathFor(pair.b, o.check.diff_out));
    // Where the two frames came from, when that differs: another build, scene or renderer
    // often explains a difference in the pixels.
    std::vector<std::string> lines = provenanceDifferences(readPngText(pair.a), readPngText(pair.b));
    if (!lines.empty() && !o.quiet) {
      std::printf("%s: provenance differs (A | B):\n", pair.label.c_str());
      for (const std::string& line : lines) std::printf("%s\n", line.c_str());
    }
  } catch (const Error& e) {
    report.badInput(e.what());
  }
}

int run(const DiffOptions& o) {
  CheckReport report(o.check.settings, !o.quiet);
  try {
    if (!o.check.diff_out.empty()) fs::create_directories(o.check.diff_out);
    std::vector<FramePair> pairs = listPairs(o.a, o.b);
    if (pairs.empty()) report.badInput("no PNG frames found in " + o.a + " or " + o.b);
    for (const FramePair& pair : pairs) comparePair(pair, o, report);
  } catch (const std::exception& e) {   // tumble::Error, or a folder that cannot be listed/created
    report.badInput(e.what());
  }
  if (!o.quiet || report.exitCode() != 0) report.printSummary("tumble diff");
  return report.exitCode();
}

}  // namespace

std::function<int()> addDiffCommand(CLI::App& app) {
  auto o = std::make_shared<DiffOptions>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare frames with approved ones: two PNG files, two folders, or two sequences ('####' / '%04d')");
  cmd->add_option("A", o->a, "The approved (golden) frame, folder or sequence")->required();
  cmd->add_option("B", o->b, "The frame, folder or sequence to check")->required();
  addCheckOptions(*cmd, o->check);
  cmd->add_flag("-q,--quiet", o->quiet, "Print only failing frames and errors");
  cmd->footer(R"(Exit codes of diff:
  0   every frame passes (at most --max-fail of its pixels differ by more than --threshold)
  1   some frame fails; its diff image (changes in magenta over a faded A) is written
  2   bad input: a missing or unreadable file, a frame on one side only, sizes that differ
  64  bad command line (unknown flag, malformed value)
)");
  return [o] { return run(*o); };
}

}  // namespace tumble
