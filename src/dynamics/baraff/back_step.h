// Contact pipeline step 3 of the Baraff model: a trial sub-step ended with pairs deeper than the
// tolerance; go back and find the first time they touch (bisection back-stepping,
// time_of_impact.h), re-integrating from the saved state for each trial time.
#pragma once

#include <vector>

#include "dynamics/body_snapshot.h"
#include "dynamics/settings.h"
#include "dynamics/shared_stages.h"
#include "dynamics/world.h"

namespace tumble {

// The trial sub-step back-stepping looks at: its contacts at the end (the contacts at its start
// are `SharedStages::contacts`), which touching points were lifting off as it started, and the
// state it started from.
struct TrialSubstep {
  const std::vector<Contact>& end;
  const std::vector<PiecePair>& end_pairs;
  const std::vector<char>& lifting;   // per start contact
  const BodySnapshot& start_state;
};

class BackStepper {
 public:
  // Leaves `world` at the first contact found (or at the end of the trial sub-step, h, when there
  // is none to go back for) and returns that time into the sub-step.
  double firstContact(World& world, const StepSettings& settings, double h, const TrialSubstep& trial,
                      SharedStages& shared);

 private:
  struct Watch {                // a pair to time
    PiecePair pair;
    bool landing = false;        // touching at the start: timed by its points away from `resting`
    double near = 0;             // m: how close to a resting point a point is that point
    std::vector<Eigen::Vector3d> resting;
    int a = -1, b = -1;          // its bodies, and its too-deep point at the sub-step's end: for
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   // the back_step overlay only
  };
  double watchedDepth(const World& world, const Watch& w, const StepSettings& settings, ContactDetector& detector);

  std::vector<Watch> watched_;
  std::vector<double> depths_;   // per watched pair, at one time
  std::vector<Contact> landing_points_;
};

}  // namespace tumble
