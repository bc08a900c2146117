// render --dry-run: what a render would do, after every override, without simulating, rendering or
// writing anything: the resolved settings, each frame with the simulated instant it shows, and the
// file it would go to.
#pragma once

#include <cstdio>
#include <vector>

#include "io/output_path.h"
#include "scene/scene.h"

namespace tumble {

struct DryRun {
  const Scene& scene;                  // with the command line's overrides applied
  const CameraSpec& camera;            // the one --camera picks
  const std::vector<int>& frames;      // the frames to render, from 1
  const OutputTarget& target;
  bool overwrite = false;              // -y: existing outputs would be replaced
};

// Prints the plan to `out`. Touches no file.
void printDryRun(const DryRun& plan, std::FILE* out);

}  // namespace tumble
