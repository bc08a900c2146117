// What one invocation of tumble-bench runs: scenes, settings, dts, limits. --quick shrinks it to
// a smoke test (two dt values, short durations, one run per point) for the test suite.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_scene.h"
#include "bench/run_point.h"

namespace tumble::bench {

struct BenchOptions {
  bool quick = false;
  std::vector<std::string> scenes;                 // ids; empty = all (quick: all but the big piles)
  std::vector<std::string> settings;               // names; empty = every available default
  std::vector<double> hz{60, 120, 240, 480, 1000}; // steps per second to sweep
  double pile_duration_s = 5;                      // s: docs/bench/scenes.md's 5 s unless shortened
  std::filesystem::path out_dir = "out/bench";
  RunOptions run;
};

// The scenes to run, with the durations --quick or --pile-duration ask for.
std::vector<BenchScene> plannedScenes(const BenchOptions& o);
// Applies --quick's defaults to everything the user did not set explicitly.
void applyQuick(BenchOptions& o);

}  // namespace tumble::bench
