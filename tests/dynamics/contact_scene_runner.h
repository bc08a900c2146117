// Runs a scene from scenes/ without rendering, sampling every step, and measures what the
// benchmark (docs/bench/scenes.md) measures: penetration from the poses, not from the solver.
#pragma once

#include <cmath>
#include <functional>
#include <string>

#include "dynamics/simulator.h"
#include "scene/scene.h"

namespace tumble::test {

struct SceneRun {
  double max_penetration = 0;   // m: deepest overlap of any pair (ground, static, bodies) seen
  Trajectory trajectory;        // one sample per frame
  PipelineCounters counters;
  long faults = 0;              // steps the run-time fault check found at fault (keep_going only)
  std::string first_fault;      // its description, empty when there was none
};

// Simulates scenes/NAME.json for `seconds` (rounded to whole frames), calling `on_step` after
// every step. Penetration is measured after every `penetration_every`-th step (all pairs by SAT:
// costly in a pile) and after the last.
// `edit` (if set) changes the loaded scene first (another contact model, say). Sleeping is off
// unless `edit` turns it on: the tests measure what the contact solve reaches.
// A run-time fault (fault_check.h) stops the run with an Error, unless `keep_going`: then the run
// goes on and the faults are counted in the result.
SceneRun runScene(const std::string& name, double seconds,
                  const std::function<void(const World&)>& on_step = {}, int penetration_every = 1,
                  const std::function<void(Scene&)>& edit = {}, bool keep_going = false);

// Deepest overlap in the world now (m, 0 when nothing overlaps), measured geometrically.
double worldPenetration(const World& world);

// Energy from nowhere, as the run-time fault check sees it (dynamics/energy_check.h): fed the world
// after every step, the largest rise of the moving bodies' total energy (kinetic + gravitational)
// above the lowest it had reached, as a share of the energy in play (the largest kinetic energy
// plus the range of the potential energy seen so far).
class EnergyRise {
 public:
  void add(const World& world);
  double largest() const { return largest_; }

 private:
  double lowest_ = INFINITY, largest_kinetic_ = 0, low_potential_ = INFINITY, high_potential_ = -INFINITY;
  double largest_ = 0;
};

// The hard cases' energy criterion: a passive scene's total energy may rise above the lowest it has
// reached by at most this share of its energy scale (EnergyRise), rounding's room and no more. The
// run-time check allows far more (1e-3 of the scale plus a 0.1 mm lift of every body,
// dynamics/energy_check.h); this is what a passive scene should keep.
inline constexpr double kEnergyRiseBound = 1e-6;

}  // namespace tumble::test
