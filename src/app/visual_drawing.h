// A mesh body drawn as its file holds it (geometry/visual_mesh_import.h): one Surface draw mesh per
// mesh of the file, moved into the body's principal frame, with the material's base colour and
// base-colour texture, unless the scene gives the body a colour, which then replaces both.
#pragma once

#include <vector>

#include "app/scene_drawing.h"

namespace tumble {

// Appends the parts of `spec`'s mesh body to `drawing` and `parts`. `body` is the body as built,
// before any step: its pose and the scene's place the file's coordinates in the body's frame.
// A texture that is missing or cannot be decoded is a warning in drawing.warnings naming the file;
// the part is then drawn in its base colour. Mesh errors are the collision import's (already
// reported by then): tumble::Error with the file named.
void appendVisualParts(const BodySpec& spec, const RigidBody& body, SceneDrawing& drawing,
                       std::vector<DrawnPart>& parts);

}  // namespace tumble
