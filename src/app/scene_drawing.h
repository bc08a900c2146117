// From the simulation's world to the renderer's GL-free draw list: meshes once, poses per frame.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/trajectory.h"
#include "dynamics/world.h"
#include "render/draw_list.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace tumble {

// One drawn piece of a body: a mesh (in the body's principal frame) and its albedo. A body drawn
// as its file holds it has one per mesh of the file, since each may carry its own material.
struct DrawnPart {
  int mesh = 0;                      // index into SceneDrawing::meshes
  Eigen::Vector3f colour{0.8f, 0.8f, 0.8f};   // linear RGB
};

// A mesh of a body drawn as its file holds it, and the colour its file gives it (none: the body's).
struct FilePartDrawing {
  int mesh = 0;
  std::optional<Eigen::Vector3f> file_colour;   // linear RGB
};

struct SceneDrawing {
  std::vector<DrawMesh> meshes;      // DrawMesh::texture indexes `textures`
  std::vector<DrawTexture> textures;
  std::vector<std::vector<DrawnPart>> parts_of_body;   // per body; empty for the ground
  DrawFrame frame;                   // lights, ground; camera and instances set per frame
  std::vector<std::string> warnings; // e.g. a texture that could not be decoded
  // Meshes and textures already made, so that a pile of the same mesh file shares them (and is
  // drawn instanced): by mesh file and scale, and by texture label.
  std::map<std::pair<std::string, double>, std::vector<FilePartDrawing>> visual_parts_of_file;
  std::map<std::string, int> texture_of_label;
};

// The camera is left at its default: the app sets it per frame (camera_rig.h).
SceneDrawing prepareDrawing(const Scene& scene, const World& world);
// Per body, the radius about its centre of mass that holds its drawn meshes; 0 for the ground.
std::vector<double> bodyRadii(const SceneDrawing& drawing);
// Uploads the textures and meshes; returns the renderer's index of each of drawing.meshes.
std::vector<int> uploadDrawing(Renderer& renderer, const SceneDrawing& drawing);
// Fills drawing.frame.instances from one frame of samples (rigid transform x + R(q) p).
void poseInstances(SceneDrawing& drawing, const std::vector<BodySample>& samples,
                   const std::vector<int>& uploaded_mesh_ids);

// sRGB (as colour pickers give colours) to linear light, the space the renderer shades in.
Eigen::Vector3f srgbToLinear(const Eigen::Vector3d& srgb);

}  // namespace tumble
