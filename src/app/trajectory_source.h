// Motion computed once: `tumble simulate --trajectory` writes it with a header line naming the
// scene's motion hash, and `tumble render --from-trajectory` reads it back instead of simulating.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/trajectory.h"
#include "scene/scene.h"

namespace tumble {

// The comment line a trajectory starts with:
//   "tumble trajectory; motion-hash=0123456789abcdef; rows=frame; scene=knockdown.json"
// rows=step for a trajectory written with --every-step.
std::string trajectoryComment(const Scene& scene, bool every_step);

// Reads frames 1..last_frame of `file` for rendering `scene`, whose bodies are `body_names` in world
// order: the frames a render that simulates would hold (a camera may look at all of them).
// Throws Error(MissingInput) when the file cannot be read, and Error(BadInput), naming the file
// and what would fix it, when it is not a tumble trajectory, comes from another scene (its motion
// hash differs), was written per step, lists other bodies, or lacks a frame asked for.
Trajectory readTrajectoryFor(const Scene& scene, const std::vector<std::string>& body_names,
                             const std::filesystem::path& file, int last_frame);

}  // namespace tumble
