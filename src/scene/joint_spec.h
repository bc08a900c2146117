// A joint as the scene file gives it ("joints": [...]), before the world is built: bodies by name
// ("world" for the fixed world), the anchor and axis in world coordinates at the start, limits and
// motor in degrees. world_builder.cpp turns it into a dynamics/joints/joint.h Joint, with anchors
// and axes in the bodies' own frames.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "dynamics/joints/joint.h"

namespace tumble {

struct JointSpec {
  std::string name;                                      // optional; "" if not given
  JointType type = JointType::Ball;
  std::string body_a, body_b;                            // body names, or "world"
  Eigen::Vector3d anchor_m = Eigen::Vector3d::Zero();    // world, at the start
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();       // world, at the start (unit); hinges only
  std::optional<Eigen::Vector2d> limits_deg;             // hinge angle [lo, hi], 0 at the start
  JointMotor motor;                                      // radians inside (the file: degrees)
};

}  // namespace tumble
