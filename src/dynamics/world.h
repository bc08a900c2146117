// Everything that is simulated: the bodies, the joints between them and the fields acting on them.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dynamics/joints/joint.h"
#include "dynamics/rigid_body.h"

namespace tumble {

struct World {
  std::vector<RigidBody> bodies;                         // in scene order; index = body id
  std::vector<Joint> joints;                             // dynamics/joints/joint.h; none: no joint stage
  Eigen::Vector3d gravity{0, 0, -9.81};                 // m/s^2
  double time = 0;                                       // s
};

}  // namespace tumble
