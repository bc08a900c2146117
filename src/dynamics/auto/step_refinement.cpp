#include "dynamics/auto/step_refinement.h"

#include <algorithm>
#include <cstdio>

namespace tumble {

StepRefinement::StepRefinement(const World& world, double target_m) : target_m_(target_m), detector_(world) {}

void StepRefinement::step(World& world, const StepSettings& settings, SharedStages& shared, ContactModelStep& model) {
  const double start = world.time;
  StepSettings sub = settings;
  for (;;) {
    attempt_.begin(world, shared);
    sub.dt = settings.dt / level_;
    for (int i = 0; i < level_; ++i) {
      world.time = start + i * sub.dt;
      model.step(world, sub, shared);
    }
    const double deepest = detector_.deepestOverlap(world).depth;
    if (deepest <= target_m_ || level_ >= kMaxRefinement) {
      if (deepest > target_m_) ++counters_.missed_steps;
      calm_ = deepest <= 0.5 * target_m_ ? calm_ + 1 : 0;
      if (calm_ >= kCalmSteps && level_ > 1) {
        level_ /= 2;
        calm_ = 0;
      }
      break;
    }
    attempt_.takeBack(world, shared);
    ++counters_.retaken_steps;
    level_ *= 2;
    calm_ = 0;
    if (counters_.first_refined_s < 0) counters_.first_refined_s = start;
    counters_.finest = std::max(counters_.finest, level_);
  }
  world.time = start;   // the caller keeps the time (Simulator: k dt exactly)
}

std::string StepRefinement::summary() const {
  char line[300];
  if (counters_.finest == 1)
    std::snprintf(line, sizeof line, "penetration target %g m: met at the scene's step, none refined", target_m_);
  else
    std::snprintf(line, sizeof line,
                  "penetration target %g m: steps refined to %d sub-steps at most (first at t = %g s), %ld taken "
                  "back%s",
                  target_m_, counters_.finest, counters_.first_refined_s, counters_.retaken_steps,
                  counters_.missed_steps > 0
                      ? (", " + std::to_string(counters_.missed_steps) + (counters_.missed_steps == 1 ? " step" : " steps") +
                             " deeper even at the finest").c_str()
                      : "");
  return line;
}

}  // namespace tumble
