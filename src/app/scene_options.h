// Options every subcommand shares: the scene, the overrides of its timing, verbosity.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "dynamics/fault_check.h"
#include "dynamics/simulator.h"
#include "scene/scene.h"

namespace tumble {

struct SceneOptions {
  std::string scene;
  std::vector<std::string> patches, sets;   // --patch FILE.json, --set PATH=VALUE: patches first, each in order
  std::optional<double> dt_s;
  std::string integrator;
  std::string contact_model;   // empty: the scene's
  bool no_sleep = false;        // --no-sleep: simulation.step.sleep.enabled = false
  int threads = 1;              // --threads N: simulation threads, 0 every hardware thread
  std::optional<int> fps;
  std::optional<double> duration_s;
  std::optional<double> time_scale;   // --time-scale S: slow motion, S simulated seconds per clip second
  bool quiet = false, verbose = false;
  bool keep_going = false;   // numerical faults are counted and reported, not fatal (render, simulate)
};

// Adds the shared flags to a subcommand.
void addSceneOptions(CLI::App& command, SceneOptions& options);
// Adds --keep-going to a subcommand that simulates.
void addKeepGoingOption(CLI::App& command, SceneOptions& options);
// After a run with --keep-going: prints how many steps had numerical faults, and the first.
void reportFaults(const FaultCheck& faults);
// After a run of a scene with an accuracy target: what was measured against it, a line per part
// ("tumble: target: ..."), unless quiet; a part missed is a warning, printed even when quiet.
void reportTarget(const Simulator& simulator, bool quiet);
// Loads the scene and applies the overrides, through the same checks as the file.
Scene loadSceneWithOverrides(const SceneOptions& options);

}  // namespace tumble
