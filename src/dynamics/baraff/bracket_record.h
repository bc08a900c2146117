// The back_step overlay's record of one back-step (back_step_log.h), built while the search runs:
// the bodies of the pairs it times, then the poses at each trial time. Inert without a log, so a
// run without overlays pays one branch per trial. It copies poses the search integrated to and
// never writes the world.
#pragma once

#include <Eigen/Core>

#include "dynamics/back_step_log.h"
#include "dynamics/world.h"

namespace tumble {

class BracketRecord {
 public:
  // `log`: null when overlays are off. `time`: the sub-step's start; `h`: its length.
  BracketRecord(BackStepLog* log, double time, double h);
  // A pair the search times: its bodies (the static ones are not drawn) and its too-deep point at h.
  void watch(const World& world, int a, int b, const Eigen::Vector3d& point);
  // The world at trial time t, and whether the watched pairs were deeper than the tolerance there.
  void trial(const World& world, double t, bool too_deep);
  // The first contact found at t after `evaluations` trials: the mark goes into the log.
  void found(double t, int evaluations);

 private:
  BackStepLog* log_;
  BackStepMark mark_;
  int points_ = 0;
};

}  // namespace tumble
