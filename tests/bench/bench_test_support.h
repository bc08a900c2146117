// What the bench tests share: a made-up result row (no simulation runs) and a file's bytes.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/run_point.h"

namespace tumble::bench::testing {

// A point of the sweep as an engine would report it: the engine is the setting's name up to its
// first '-' ("tumble-rk4" -> "tumble", "bullet" -> "bullet"), 3 runs over 2 simulated s.
inline RunResult madeUpRow(const std::string& scene, const std::string& setting, double dt, double wall,
                           std::vector<Metric> metrics) {
  RunResult r;
  r.scene = scene;
  r.setting = setting;
  r.engine = setting.substr(0, setting.find('-'));
  r.dt = dt;
  r.wall_per_sim = wall;
  r.reps = 3;
  r.simulated_s = 2;
  r.metrics = std::move(metrics);
  return r;
}

inline std::string fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace tumble::bench::testing
