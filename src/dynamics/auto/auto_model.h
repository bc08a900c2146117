// The automatic contact model, the default: the event-driven (Baraff) model unless the scene
// starts with a crowd of free bodies, then the time-stepping model with a speed setting. Chosen
// once, at the start, from what the scene holds; `tumble check` and `-v` say which and why.
//
// Why this choice, and why at the start. The Baraff model goes back to every first contact:
// exact, and as cheap as time stepping while events are few (a roll, a rock, a stack, a wall
// struck by a ball: 1-8 sub-steps per step, measured). Its cost grows with the events: every
// body that starts free lands at least once, and a crowd of them lands at overlapping times,
// each landing cutting everyone's step (a 100-piece pile: 17 sub-steps per step and 14-40 s per
// simulated second, where time stepping with ten Gauss-Seidel sweeps takes 0.1-0.4). Bodies that
// start resting on something (a wall, an arch, a row of dominoes) rest, or fall one after another.
//
// An accuracy target (settings.h, AccuracyTarget) does not change the choice: time stepping meets
// a penetration target at a finer step far more cheaply than the Baraff model meets it at the
// scene's (the 100-piece pile's first second at dt = 1/240 s: 15 mm deep under time stepping at
// 0.07 s per simulated second, 0.16 mm under the Baraff model at 16 s; time stepping refined to a
// 1 mm target takes 0.23 s over the whole pile; measured 2026-11-25, before time stepping
// corrected at each step's end, which leaves 0.13 mm without a target). Auto meets a penetration target with the model it
// chose by its contact tolerance (no coarser than the target) and by refining the step where a
// step ends deeper (step_refinement.h). An energy target is measured and reported
// (target_watch.h): the largest rises measured are 1.3e-6 of the energy in play on the pile under
// time stepping and 3.9e-7 where a striker knocks down a row of blocks under the Baraff model
// (2026-11-25), far inside any target a scene would set, and the step that would shrink them is
// the one the penetration target already refines.
//
// Switching during the run, once the crowding shows, was tried and measured (2026-11-24): a
// switch needs a window of crowded Baraff steps to see the crowding, and on the 100-box pile one
// such window (0.05 s at 14-40 s per simulated second) costs more than the whole 5 s run with time
// stepping, so that a run could not stay within 1.25 times the fast setting; and sub-steps per
// step do not tell a landing pile (17) from a domino wave (6, with windows above 20) or a wall
// struck by a ball (8), which time stepping cannot keep within 1 mm. The start can tell them: a
// pile starts free, the others start resting.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/auto/step_refinement.h"
#include "dynamics/contact_model.h"

namespace tumble {

// Moving bodies that start free (touching nothing within the contact margin) at or above which
// the scene is a crowd of landings. A clip of a few bodies, a stack or a wall has a handful.
inline constexpr int kAutoCrowd = 20;
// The time-stepping setting auto uses for a crowd: Gauss-Seidel sweeps per step at most, islands
// by Gauss-Seidel alone (as Bullet and ODE's quickstep) but for the few below.
inline constexpr int kAutoCrowdSweeps = 10;
// Rows up to which an island of unequal masses the crowd's sweeps leave unconverged is pivoted
// exactly (a heavy shard on a light one on the ground: time_stepping/contact_impulses.h,
// kSweepsMassRatio), and up to which an island's drift is projected by pivoting; larger islands
// (a pile's) keep the sweeps' answers.
inline constexpr int kAutoCrowdPivotRows = 60;

class AutoModel final : public ContactModelStep {
 public:
  void start(const World& world, const StepSettings& settings, SharedStages& shared) override;
  void step(World& world, const StepSettings& settings, SharedStages& shared) override;
  std::vector<std::string> describe(const StepSettings& settings, const SharedStages& shared) const override;
  double storedEnergy() const override { return chosen_ ? chosen_->storedEnergy() : 0; }
  StepImpulses lastImpulses() const override { return chosen_ ? chosen_->lastImpulses() : StepImpulses{}; }
  ContactModel running(ContactModel) const override {
    return crowd_ ? ContactModel::TimeStepping : ContactModel::Baraff;
  }

  bool choseTimeStepping() const { return crowd_; }
  const std::string& reason() const { return reason_; }

 private:
  std::unique_ptr<ContactModelStep> chosen_;
  bool crowd_ = false;
  std::string reason_;
  // The settings the chosen model runs with: the scene's, with the fast time-stepping solve for a
  // crowd and the contact tolerance no coarser than a penetration target.
  StepSettings run_settings_;
  std::optional<StepRefinement> refinement_;   // only with a penetration target
  long reported_retakes_ = -1, reported_misses_ = -1;
};

// The settings auto runs a crowd with: the scene's, with the fast time-stepping solve.
StepSettings crowdSettings(const StepSettings& scene);

}  // namespace tumble
