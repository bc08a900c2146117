// A run-time check for energy from nowhere. In a passive scene (restitution at most 1, constant
// gravity, nothing driven) the total energy, kinetic plus gravitational, can only fall: impacts
// and friction dissipate, integration and position correction may return at most what they took.
// So the total may never rise above the lowest it has reached by more than a tolerance: a share of
// the scene's energy scale (the largest kinetic energy seen plus the range of potential energy
// seen: what is in play), plus what lifting every moving body by `drift_m` takes (the position
// correction gives back what drift into a contact took).
//
// A model may pay energy back late: the time-stepping model gives a landing's bounce one step
// after the step that closed its gap, so the total dips for that step and comes back. With
// `repaid_within` = k steps, a dip that is back within k steps is not a lowest: the lowest is taken
// over the largest total of every k + 1 consecutive steps.
//
// The start is not a level the energy held: bodies placed overlapping (a warning when the scene is
// built) are pushed apart by the first step's correction, which lifts them. The lowest is taken
// from the end of the first step on (the first k + 1 steps, for a model that pays back late).
#pragma once

#include <optional>
#include <vector>

#include "dynamics/world.h"

namespace tumble {

struct EnergyGain {
  double total = 0, lowest = 0, tolerance = 0;   // J
  int body = -1;                                  // the body whose energy rose most since the lowest
};

class EnergyCheck {
 public:
  EnergyCheck(const World& world, double share, double drift_m, int repaid_within);
  // The gain, if the world's total energy now exceeds its running lowest by more than the
  // tolerance; updates the lowest and the scale. `stored` (J) is energy the contact model holds
  // (a compliant contact's spring), counted in the total.
  std::optional<EnergyGain> afterStep(const World& world, double stored = 0);
  // After afterStep: how far the total stands above the lowest (J, 0 before a lowest is taken or
  // when it is the lowest), and the energy in play it is measured against (J).
  double rise() const { return rise_; }
  double scale() const { return scale_; }

 private:
  struct Sample {
    double total = 0;
    std::vector<double> per_body;   // J: kinetic + potential
  };
  Sample sample(const World& world);

  double share_, drift_allowance_ = 0;   // -, J
  int repaid_within_;
  std::vector<Sample> recent_;           // the last repaid_within + 1 samples, oldest first
  Sample lowest_;
  bool started_ = false;                 // a lowest has been taken
  double largest_kinetic_ = 0, lowest_potential_ = 0, highest_potential_ = 0;
  double kinetic_ = 0, potential_ = 0;   // J: of the last sample
  double rise_ = 0, scale_ = 0;          // J: of the last afterStep
};

}  // namespace tumble
