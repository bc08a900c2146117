#include "dynamics/joints/joint_summary.h"

namespace tumble {

std::string describeJoints(const World& world) {
  int count[3] = {0, 0, 0}, motors = 0, limits = 0;
  for (const Joint& j : world.joints) {
    ++count[static_cast<int>(j.type)];
    motors += j.motor.kind != JointMotor::Kind::None;
    limits += j.limited;
  }
  const char* names[3] = {"ball", "hinge", "fixed"};
  std::string kinds;
  for (int k = 0; k < 3; ++k)
    if (count[k]) kinds += (kinds.empty() ? "" : ", ") + std::to_string(count[k]) + " " + names[k];
  std::string out = std::to_string(world.joints.size()) + (world.joints.size() == 1 ? " joint (" : " joints (") + kinds + ")";
  if (limits) out += ", " + std::to_string(limits) + " with limits";
  if (motors) out += ", " + std::to_string(motors) + " with motors";
  return out;
}

}  // namespace tumble
