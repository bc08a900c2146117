// --gltf FILE.glb: the simulated motion as an animated glTF 2.0 binary, for Blender and other
// tools — one node per drawn body with its visual mesh and material, one translation and one
// rotation key per frame, linearly interpolated. glTF is Y-up and tumble Z-up: the bodies hang
// under one root node that turns Z-up into Y-up, so each body's own transform is the
// trajectory's, in tumble's frame.
#pragma once

#include <filesystem>
#include <string>

#include "app/scene_drawing.h"
#include "dynamics/trajectory.h"

namespace tumble {

// Refuses, before any work, a file that exists (Error(CantCreate), 73) unless `overwrite`.
void checkGltfOutput(const std::filesystem::path& path, bool overwrite);

// Writes the GLB whole (a temporary sibling renamed onto `path`). Bodies with nothing drawn (the
// ground plane) get no node. Textures are not exported: a textured part keeps its base colour.
void writeGltf(const std::filesystem::path& path, bool overwrite, const SceneDrawing& drawing,
               const Trajectory& trajectory);

}  // namespace tumble
