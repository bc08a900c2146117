// Scene -> World: imports meshes, computes exact mass properties, moves each body's pieces into
// its principal frame (origin at the centre of mass), and sets the initial state (x, q, P, L).
#pragma once

#include <string>
#include <vector>

#include "dynamics/settings.h"
#include "dynamics/world.h"
#include "scene/scene.h"

namespace tumble {

struct BuiltWorld {
  World world;
  StepSettings step;
  std::vector<std::string> warnings;   // e.g. a mesh that was not convex and was hulled
};

// Throws tumble::Error with the scene file, line and JSON pointer of the body at fault.
BuiltWorld buildWorld(const Scene& scene);

}  // namespace tumble
