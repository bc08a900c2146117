// The scene's joints (JointSpec, names and world coordinates) as the world's (dynamics/joints/
// joint.h: body indices, anchors and axes in the bodies' frames), from the bodies' starting poses.
#pragma once

#include <vector>

#include "dynamics/world.h"
#include "scene/joint_spec.h"

namespace tumble {

// `world.bodies` must hold the scene's bodies in scene order, at their starting poses.
void addJoints(const std::vector<JointSpec>& specs, World& world);

}  // namespace tumble
