// The camera of every frame, from the scene's camera spec and the simulated motion. The motion is
// simulated before anything is rendered, so a follow camera's lag and a fit camera's framing of
// the whole clip are known, and each frame's camera is computed from the first frame on: it is
// the same whichever frames are rendered, and the same on every run.
#pragma once

#include <vector>

#include "dynamics/trajectory.h"
#include "render/draw_list.h"
#include "scene/scene.h"

namespace tumble {

// One camera per frame of `trajectory`. `body_radius_m`: per body, a sphere about its centre of
// mass holding it (what a fit camera keeps in view). `aspect`: width / height.
std::vector<DrawCamera> cameraPath(const CameraSpec& spec, const Trajectory& trajectory,
                                   const std::vector<double>& body_radius_m, double aspect);

// "fixed", "orbit", "follow" or "fit", for messages and listings.
const char* cameraFormName(CameraSpec::Form form);

// The scene's camera named `name` ("" for the default); throws Error(Usage) naming the cameras
// there are when none is.
const CameraSpec& pickCamera(const Scene& scene, const std::string& name);

}  // namespace tumble
