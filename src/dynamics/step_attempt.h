// A step that may be taken back: the bodies' states and the overlay logs' lengths where it began.
// A model that judges a step once it is taken (auto's refinement to a penetration target,
// auto/step_refinement.h; time stepping's split of a step its rows could not hold,
// time_stepping/step_split.h) puts the world back with takeBack() and runs it again finer. What
// the attempt leaves behind is only the solvers' warm starts, so a rerun is deterministic.
#pragma once

#include <cstddef>

#include "dynamics/body_snapshot.h"
#include "dynamics/shared_stages.h"
#include "dynamics/world.h"

namespace tumble {

class StepAttempt {
 public:
  void begin(const World& world, const SharedStages& shared) {
    snapshot_.save(world);
    logged_ = shared.impact_log ? shared.impact_log->size() : 0;
    stepped_back_ = shared.back_step_log ? shared.back_step_log->added() : 0;
  }
  void takeBack(World& world, SharedStages& shared) const {
    snapshot_.restore(world);
    shared.contacts_fresh = false;   // the model's contacts were of the attempt's end
    if (shared.impact_log) shared.impact_log->resize(logged_);   // the attempt's impacts never happened
    if (shared.back_step_log) shared.back_step_log->rollback(stepped_back_);   // nor its back-steps
  }

 private:
  BodySnapshot snapshot_;
  std::size_t logged_ = 0, stepped_back_ = 0;
};

}  // namespace tumble
