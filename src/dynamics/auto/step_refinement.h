// How the automatic model meets a penetration target (settings.h, AccuracyTarget): by refining
// the step. A step is run as k sub-steps of dt / k of the chosen model, k a power of two; if the
// step ends with two pieces overlapping deeper than the target (what the target promises: the
// state at every step's end, which frames and trajectories show), the bodies are put back where
// the step began and it is run again at 2k, up to kMaxRefinement. Once steps have kept within half the
// target for a while, k comes back down by halves.
//
// Why the step: both models' overlaps shrink with it. Time stepping closes a landing in one
// velocity-level solve, left short by its few sweeps, so a landing at speed v ends about a
// fraction of v dt deep (the 100-piece pile, deepest overlap at a step's end over its first
// second: 15 mm at dt = 1/240 s, 6.2 mm at 1/480, 2.4 mm at 1/960, 1.6 mm at 1/1920; measured
// 2026-11-25, while the drift projection ran at the next step's start: at the step's end it now
// leaves 0.63 mm at 1/240 s, 2026-11-28, and 0.13 mm since its deep passes hold the lower body of a
// stacked pair, 2026-11-29); the Baraff model
// keeps contacts within its tolerance except where a pair is already deep when a sub-step begins,
// which a shorter step makes rarer. Taking a step back is cheap: the bodies' states, and the
// contacts detected again. A taken-back attempt leaves only warm starts behind (a solver's
// impulses from the attempt), so a rerun is bit-identical.
#pragma once

#include <string>
#include <vector>

#include "dynamics/contact_detection.h"
#include "dynamics/contact_model.h"
#include "dynamics/step_attempt.h"

namespace tumble {

// Sub-steps per step at most: seven halvings, a step of 1/240 s down to 1/30720 s.
inline constexpr int kMaxRefinement = 128;
// Steps within half the target after which the refinement tries half as many sub-steps.
inline constexpr int kCalmSteps = 24;

class StepRefinement {
 public:
  StepRefinement(const World& world, double target_m);

  // One step of settings.dt by `model`, refined until it ends no deeper than the target.
  void step(World& world, const StepSettings& settings, SharedStages& shared, ContactModelStep& model);

  struct Counters {
    long retaken_steps = 0;      // attempts taken back and run again finer
    long missed_steps = 0;       // steps deeper than the target even at kMaxRefinement
    int finest = 1;              // the most sub-steps per step used
    double first_refined_s = -1; // s: when a step first needed more than one sub-step
  };
  const Counters& counters() const { return counters_; }
  // "penetration target 0.001 m: steps refined to 8 sub-steps at most (from t = 0.42 s), 37 taken back".
  std::string summary() const;

 private:
  double target_m_;
  ContactDetector detector_;
  StepAttempt attempt_;
  int level_ = 1, calm_ = 0;
  Counters counters_;
};

}  // namespace tumble
