// Bodies that start inside one another: a scene-writing mistake (a crate placed below the ground,
// two bodies at the same position), found before the first step by the detection the steps use.
// buildWorld (world_builder.h) refuses an overlap deeper than the run-time penetration limit
// (fault_check.h: half the thinner body's thinnest piece) as a scene error: the first step would
// otherwise stop on it as a numerical fault, with advice (a smaller dt) that cannot help, or push
// the bodies apart along whichever axis is shortest, possibly the wrong way. A shallower overlap is
// pushed apart by the first steps' position projection (no velocity is added) and only warned about.
#pragma once

#include <vector>

#include "dynamics/world.h"

namespace tumble {

struct StartOverlap {
  int a = -1, b = -1;   // body indices, a < b
  double depth = 0;     // m: the deepest contact between the two
  double limit = 0;     // m: the deepest the steps accept (half the thinner body's thinnest piece)
  bool tooDeep() const { return depth > limit; }
};

// Every pair of bodies overlapping by more than `tolerance_m`, in body order, deepest contact per
// pair. Static pairs are never tested (nothing moves them apart, and nothing needs to).
std::vector<StartOverlap> findStartOverlaps(const World& world, double tolerance_m, double depth_share);

}  // namespace tumble
