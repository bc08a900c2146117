// A time step whose motion its rows could not hold, taken again as two halves.
//
// The model's rows hold a contact to first order: a gap closing along a normal fixed at the
// step's start. A body an impact sets turning by a good part of a radian within one step sweeps
// its corners through neighbours no such row follows, and the drift projection at the step's end
// pushes it out by centimetres: a jump no velocity explains, which the run-time fault check stops
// (motion_check.h). An untuned bin of shards: a 0.18 kg shard pinched against the ground by a
// 6.2 kg one thrown in at 18 m/s was squeezed out at 17.6 m/s spinning at 248 rad/s, about a
// radian within the 1/240 s step; it ended the step 13 cm into its neighbours and the projection
// moved it 7 cm farther than its speeds allow. Solving the step again with the contacts of the new
// motion (outrun_contacts.h) did not help: no velocity-level row holds a radian of turn.
//
// So where a step moves a body farther than its speeds explain by more than kSplitShare of its
// thinnest piece (half what the fault check lets pass), the step is taken back
// (step_attempt.h) and run as two steps of half the length, each judged the same way, down to
// 1 / 2^kMaxSplitDepth of the step. Each half detects and corrects at its end, so the second half
// holds the contacts of the turn the first one made. A step that keeps within the bound (every
// step of the piles and stacks the trajectory hashes pin) is taken once, as before.
#pragma once

#include <optional>

#include "dynamics/motion_check.h"
#include "dynamics/settings.h"
#include "dynamics/shared_stages.h"
#include "dynamics/step_attempt.h"
#include "dynamics/world.h"

namespace tumble {

// The unexplained motion, as a share of a body's thinnest piece, past which a step is split: half
// of the fault check's (FaultSettings::depth_share), so that a step the fault check would stop is
// split first, with room for the halves' own corrections.
inline constexpr double kSplitShare = 0.25;
// Halvings at most: a step of 1/240 s down to 1/3840 s, a spin of 248 rad/s turning 0.065 rad.
inline constexpr int kMaxSplitDepth = 4;

class StepSplit {
 public:
  void start(const World& world, const std::vector<BodyExtent>& extents) {
    check_.emplace(world, extents, kSplitShare);
  }

  // Runs `attempt(sub_settings)`, one step of sub_settings.dt from the world's state, and splits
  // it as the header says. The world's time is left where it was (the caller keeps the time).
  template <typename Attempt>
  void step(World& world, const StepSettings& settings, SharedStages& shared, Attempt&& attempt, int depth = 0) {
    const double start = world.time;
    if (depth < kMaxSplitDepth) {
      taken_.begin(world, shared);
      check_->remember(world);
    }
    attempt(settings);
    if (depth >= kMaxSplitDepth || !check_->afterStep(world, settings.dt)) return;
    taken_.takeBack(world, shared);
    ++shared.counters.split_steps;
    StepSettings half = settings;
    half.dt = 0.5 * settings.dt;
    step(world, half, shared, attempt, depth + 1);
    shared.notePeakSpeeds(world);   // the speeds mid-step, for the fault check's bound on the step
    world.time = start + half.dt;
    step(world, half, shared, attempt, depth + 1);
    world.time = start;
  }

 private:
  std::optional<MotionCheck> check_;
  StepAttempt taken_;
};

}  // namespace tumble
