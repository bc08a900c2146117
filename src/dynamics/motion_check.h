// A run-time check for motion no velocity explains: a step may move a body's points no farther
// than its speeds allow, (|v| + |g| dt + |w| r) dt with the largest of each speed at the step's
// two ends and within it (a model's sub-steps between two impacts of one step), plus what the
// position correction may move it by — at most the deepest overlap the fault check lets pass
// (half the body's thinnest piece), since a correction only removes overlap.
// A teleport (a body moved metres in one step while its velocity stays small) exceeds this; a
// fall, a bounce, a spin or an impact mid-step does not.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "dynamics/body_extent.h"
#include "dynamics/world.h"

namespace tumble {

struct UnexplainedMotion {
  int body = -1;
  double moved = 0;     // m: the farthest any point of the body moved in the step (bound)
  double allowed = 0;   // m
};

class MotionCheck {
 public:
  // The position correction may move a body within one step by `depth_share` of its thinnest
  // piece (the deepest overlap the fault check lets pass).
  MotionCheck(const World& world, const std::vector<BodyExtent>& extents, double depth_share);
  // Takes `world` as the next step's start (a step taken back and begun again).
  void remember(const World& world);
  // The body whose points moved farthest beyond what its speeds allow over the step of `dt`
  // seconds that led to `world`, if any; then remembers `world` as the next step's start.
  // `peak_speed` and `peak_spin` (per body, or empty) are the largest speeds a model moved each
  // body at within the step (between two impacts of one step, more than at either end).
  std::optional<UnexplainedMotion> afterStep(const World& world, double dt, const std::vector<double>& peak_speed = {},
                                             const std::vector<double>& peak_spin = {});

 private:
  struct State {
    Eigen::Vector3d x, v, w;
    Eigen::Quaterniond q;
  };
  static State stateOf(const RigidBody& body);
  std::vector<double> radius_, allowance_;
  std::vector<State> last_;
};

}  // namespace tumble
