// The scene's cameras: "camera" (one) and "cameras" (named, for --camera), each in one of four
// forms (scene.h, CameraSpec): fixed, orbit, follow or fit.
#pragma once

#include "scene/object_reader.h"
#include "scene/scene.h"

namespace tumble {

// Reads "camera" and "cameras" of the scene's top level. Without "camera" the first of "cameras"
// is the default.
void readCameras(ObjectReader& root, Scene& scene);
// Once the bodies are read: every body a camera names exists and is not the ground, or the error
// points at the name, with "did you mean".
void checkCameraBodies(const Scene& scene, const ParseContext& ctx);

}  // namespace tumble
