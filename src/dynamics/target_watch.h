// Measures a run against the scene's accuracy target (settings.h, AccuracyTarget): after every
// step, the deepest contact and the rise of the total energy above the lowest it reached, each
// with where and when it was worst. The automatic model chooses and tunes to meet the target
// before the run; this says afterwards whether it did, for every model.
#pragma once

#include <string>
#include <vector>

#include "dynamics/contact_detection.h"
#include "dynamics/energy_check.h"
#include "dynamics/pipeline.h"
#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

// m: the lift whose energy is the least the energy in play is taken to be. A millimetre is the
// smallest motion a render shows; a rise below what it takes is below anything a viewer sees.
inline constexpr double kLiftFloor = 1e-3;

class TargetWatch {
 public:
  // `energy_repaid_within`: steps within which the running model pays energy back (fault_check.h).
  TargetWatch(const World& world, const AccuracyTarget& target, int energy_repaid_within);

  void afterStep(const World& world, const Pipeline& pipeline);

  struct Worst {
    // m for the depth; for the rise, a share of the energy in play: the largest kinetic energy plus
    // the range of potential energy seen (the fault check's scale), and at least what lifting every
    // moving body by kLiftFloor takes (so that a stack at rest, with next to nothing in play, is
    // not measured against rounding)
    double value = 0;
    double time = 0;     // s
    std::string where;   // "\"a\" and \"b\"", or the body that gained most; empty if nothing
  };
  const Worst& deepest() const { return deepest_; }
  const Worst& energyRise() const { return rise_; }
  const AccuracyTarget& target() const { return target_; }

  bool penetrationMet() const { return target_.penetration_m <= 0 || deepest_.value <= target_.penetration_m; }
  bool energyMet() const { return target_.energy_drift <= 0 || rise_.value <= target_.energy_drift; }
  bool met() const { return penetrationMet() && energyMet(); }

  // One line per part of the target: the worst seen against it, and whether it was met.
  struct Line {
    std::string text;
    bool met = true;
  };
  std::vector<Line> report() const;

 private:
  AccuracyTarget target_;
  EnergyCheck energy_;
  ContactDetector detector_;   // its own: the end state's overlaps, whatever contacts the model holds
  double floor_energy_ = 0;   // J: what lifting every moving body by kLiftFloor takes
  Worst deepest_, rise_;
};

}  // namespace tumble
