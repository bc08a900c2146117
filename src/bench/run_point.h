// Runs one point of the sweep, (scene, engine setting, dt): median wall time per simulated second
// over fresh runs (only the engine's step call is timed), the scene's metrics, and for piles the
// Erez-Tassa-Todorov self-consistency error against a run of the same engine at dt / 4.
#pragma once

#include <string>
#include <vector>

#include "bench/bench_scene.h"
#include "bench/engine.h"
#include "bench/metrics.h"

namespace tumble::bench {

struct RunOptions {
  int reps = 3;                     // fresh runs per point; the median time is reported
  double single_run_above_s = 60;   // s: one run only when a run's stepping takes longer (scenes.md)
  double cap_s = 60;                // s: wall time of stepping after which a run stops early ("cut")
  double sc_horizon_s = 1.0;        // s: horizon of the self-consistency error (piles)
  int sc_ratio = 4;                 // the reference runs at dt / sc_ratio
  // s: when an earlier engine's pile run was cut, later ones also report their wall time per
  // simulated s over this head of the run (wall_per_sim_head), so the figures compare like with
  // like; 0 = the whole run.
  double head_s = 0;
};

struct RunResult {
  std::string scene, setting, engine;
  double dt = 0;                    // s
  double wall_per_sim = 0;          // wall s of stepping per simulated s (median)
  int reps = 0;
  double simulated_s = 0;           // s reached (less than the duration when cut)
  bool cut = false;
  double peak_rss_mb = -1;          // MB, peak resident memory of the run's process (-1: unknown)
  std::vector<Metric> metrics;
  std::string note;                 // engine remarks, what was cut, errors
  bool failed = false;
};

// An empty result naming its point, to be filled in.
RunResult resultFor(const BenchScene& scene, const EngineSetting& setting, double dt);

RunResult runPoint(const BenchScene& scene, const EngineSetting& setting, double dt,
                   const RunOptions& options);

// Peak resident set of this process so far (VmHWM), MB.
double peakRssMb();

}  // namespace tumble::bench
