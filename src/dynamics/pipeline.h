// The simulation step, written down in one place: a list of named stages, each in a file of its
// own, each timed. The pipeline holds only the stages the scene needs ("model only what a scene
// needs"): a world without gravity skips the force stage, static bodies are never integrated.
//
// Stages today:  forces (gravity) -> integrate.
// The contact pipeline (DESIGN.md steps 1-6: broad phase, narrow phase, back-stepping, classify,
// impulses, resting forces) slots in between and is not built yet: bodies pass through each other.
#pragma once

#include <string>
#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/step_settings.h"
#include "dynamics/world.h"

namespace tumble {

// Wall time per stage, summed over the steps taken (for --stats and benchmarks).
struct StageTime {
  std::string name;
  double seconds = 0;
};

class Pipeline {
 public:
  Pipeline(const World& world, const StepSettings& settings);
  void step(World& world, const StepSettings& settings);

  // One line per stage: what it does in this scene (for `tumble check`).
  std::vector<std::string> describe() const;
  const std::vector<StageTime>& profile() const { return profile_; }

 private:
  bool apply_gravity_ = false;
  int moving_ = 0, static_ = 0;
  Integrator integrator_ = Integrator::Rk4;
  double dt_ = 0;
  std::vector<Wrench> wrenches_;
  std::vector<StageTime> profile_;
};

}  // namespace tumble
