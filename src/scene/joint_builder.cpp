#include "scene/joint_builder.h"

namespace tumble {
namespace {

// The loader has checked every name: a body's, or "world" (-1).
int bodyIndex(const World& world, const std::string& name) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i)
    if (world.bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

void addJoints(const std::vector<JointSpec>& specs, World& world) {
  constexpr double kDeg = M_PI / 180;
  for (const JointSpec& spec : specs) {
    Joint j = makeJoint(world, spec.type, bodyIndex(world, spec.body_a), bodyIndex(world, spec.body_b),
                        spec.anchor_m, spec.axis);
    j.name = spec.name;
    if (spec.limits_deg) {
      j.limited = true;
      j.lower_rad = (*spec.limits_deg)[0] * kDeg;
      j.upper_rad = (*spec.limits_deg)[1] * kDeg;
    }
    j.motor = spec.motor;
    world.joints.push_back(j);
  }
}

}  // namespace tumble
