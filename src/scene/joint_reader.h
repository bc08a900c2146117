// Reads "joints": [{"name", "type", "bodies", "anchor_m", "axis", "limits_deg", "motor"}, ...]
// after the bodies (the names it refers to). Every error is located (file, line, JSON pointer) and
// exits 65, as the rest of the scene's: an unknown body name or key (with "did you mean"), an axis
// of zero length, limits with lo > hi, an axis, limits or a motor on a joint that has none (a ball
// or fixed joint), a joint of a body to itself or of two bodies that cannot move, and any joint
// under the penalty contact model, which does not simulate them.
#pragma once

#include "scene/object_reader.h"
#include "scene/scene.h"

namespace tumble {

void readJoints(ObjectReader& root, const ParseContext& ctx, Scene& scene);

}  // namespace tumble
