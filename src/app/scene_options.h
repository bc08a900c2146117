// Options every subcommand shares: the scene, the overrides of its timing, verbosity.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace tumble {

struct SceneOptions {
  std::string scene;
  std::optional<double> dt_s;
  std::string integrator;
  std::optional<int> fps;
  std::optional<double> duration_s;
  bool quiet = false, verbose = false;
};

// Adds the shared flags to a subcommand.
void addSceneOptions(CLI::App& command, SceneOptions& options);
// Loads the scene and applies the overrides, through the same checks as the file.
Scene loadSceneWithOverrides(const SceneOptions& options);

}  // namespace tumble
