#include "bench/results_csv.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string>

namespace tumble::bench {
namespace {

// The columns writeCsv writes, in its order.
enum Column { kScene, kSetting, kEngine, kDt, kHz, kWallPerSim, kReps, kSimulated, kCut, kPeakRss, kFailed,
              kMetric, kValue, kHeadline, kNote, kColumns };

// One CSV line: fields with a ',' or '"' are quoted, a '"' inside doubled (RFC 4180).
std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += line[++i];
    else if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.emplace_back();
    else out.back() += c;
  }
  return out;
}

double number(const std::string& field) {
  std::size_t used = 0;
  const double v = std::stod(field, &used);
  if (used != field.size()) throw std::invalid_argument(field);
  return v;
}

RunResult resultOf(const std::vector<std::string>& f) {
  RunResult r;
  r.scene = f[kScene];
  r.setting = f[kSetting];
  r.engine = f[kEngine];
  r.dt = number(f[kDt]);
  r.wall_per_sim = number(f[kWallPerSim]);
  r.reps = static_cast<int>(number(f[kReps]));
  r.simulated_s = number(f[kSimulated]);
  r.cut = f[kCut] == "1";
  r.peak_rss_mb = number(f[kPeakRss]);
  r.failed = f[kFailed] == "1";
  r.note = f[kNote];
  return r;
}

}  // namespace

std::vector<SceneResults> readResultsCsv(std::istream& in, const std::string& name) {
  std::string line;
  if (!std::getline(in, line) || splitCsvLine(line).size() != kColumns || splitCsvLine(line)[0] != "scene")
    throw std::runtime_error(name + ": not a tumble-bench results CSV (no header line)");
  std::vector<SceneResults> out;
  for (int at = 2; std::getline(in, line); ++at) {
    if (line.empty()) continue;
    const std::vector<std::string> f = splitCsvLine(line);
    const std::string where = name + ":" + std::to_string(at) + ": ";
    if (f.size() != kColumns)
      throw std::runtime_error(where + std::to_string(f.size()) + " fields, expected " + std::to_string(kColumns));
    try {
      auto scene = std::find_if(out.begin(), out.end(), [&](const SceneResults& s) { return s.scene.id == f[kScene]; });
      if (scene == out.end()) scene = out.insert(out.end(), SceneResults{makeScene(f[kScene], {}), {}, {}});
      RunResult r = resultOf(f);
      // One row per metric: consecutive rows of the same point add to one result.
      std::vector<RunResult>& rows = scene->rows;
      if (rows.empty() || rows.back().setting != r.setting || rows.back().dt != r.dt) {
        rows.push_back(r);
        if (std::find(scene->scene.dts.begin(), scene->scene.dts.end(), r.dt) == scene->scene.dts.end())
          scene->scene.dts.push_back(r.dt);
      }
      if (!f[kMetric].empty()) rows.back().metrics.push_back({f[kMetric], number(f[kValue])});
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where + e.what());
    } catch (const std::out_of_range& e) {
      throw std::runtime_error(where + "number out of range");
    }
  }
  return out;
}

std::vector<SceneResults> readResultsCsv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  return readResultsCsv(in, file.string());
}

}  // namespace tumble::bench
