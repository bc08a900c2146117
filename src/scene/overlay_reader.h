#pragma once

#include "scene/object_reader.h"
#include "scene/scene.h"

namespace tumble {

// Reads "overlays" (a list of overlay names, overlay_spec.h) and "overlay_bodies" (names of moving
// bodies whose velocities are drawn) of the scene's top level, once the bodies are read. A wrong
// name is refused at its place in the file, with "did you mean".
void readOverlays(ObjectReader& root, const ParseContext& ctx, Scene& scene);

}  // namespace tumble
