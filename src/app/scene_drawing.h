// From the simulation's world to the renderer's GL-free draw list: meshes once, poses per frame.
#pragma once

#include <vector>

#include "dynamics/trajectory.h"
#include "dynamics/world.h"
#include "render/draw_list.h"
#include "scene/scene.h"

namespace tumble {

struct SceneDrawing {
  std::vector<DrawMesh> meshes;     // one per drawn body, in the body's principal frame
  std::vector<int> mesh_of_body;    // index into meshes, -1 for bodies not drawn as meshes (ground)
  DrawFrame frame;                  // camera, lights, ground; instances filled per frame
};

SceneDrawing prepareDrawing(const Scene& scene, const World& world);
// Fills drawing.frame.instances from one frame of samples (rigid transform x + R(q) p).
void poseInstances(SceneDrawing& drawing, const std::vector<BodySample>& samples,
                   const std::vector<int>& uploaded_mesh_ids);

// sRGB (as colour pickers give colours) to linear light, the space the renderer shades in.
Eigen::Vector3f srgbToLinear(const Eigen::Vector3d& srgb);

}  // namespace tumble
