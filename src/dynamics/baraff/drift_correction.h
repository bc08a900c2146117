// The Baraff model's drift correction: residual penetration deeper than the tolerance is removed
// by moving and turning the two bodies of each pair, the smallest displacement (weighted by mass
// and inertia) that lifts the pair's too-deep points back within the tolerance
// (position_projection.h). Only positions move, so no speed is added (unlike a Baumgarte term,
// which pushes bodies apart with speed); and where a projection raises the pair's energy (a lift
// out of drift that took none), the gain is paid from the pair's kinetic energy (the .cpp).
// What one pass of pairs leaves too deep is projected island by island (correctIslands,
// island_projection.h): pair by pair, a light body pinched between heavy ones takes nearly all
// of every push, and the passes trade its overlap back and forth.
//
// Its reach is bounded: within one step the corrections may move a body's points by no more, in
// all, than the deepest overlap the fault check lets pass (half its thinnest piece; fault_check.h).
// Summed over the sub-steps of one step, corrections once moved a piece of the pile 0.26 m and
// turned it 29 degrees while its speed was 2 m/s (single projections out of proportion to their
// lift, which position_projection.cpp now refuses). The bound keeps any such case within what the
// fault check tolerates: a projection that would pass a body's reach is not made (counted).
#pragma once

#include <vector>

#include "dynamics/body_extent.h"
#include "dynamics/contact.h"
#include "dynamics/contact_islands.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/island_projection.h"
#include "dynamics/world.h"

namespace tumble {

struct CorrectionCount {
  int moved = 0;    // pairs projected
  int capped = 0;   // pairs left as they were: a body would have passed its reach for the step
};

class DriftCorrection {
 public:
  // A new step: every body's reach is whole again.
  void startStep(const World& world);
  // Projects every pair of bodies with a contact deeper than `tolerance_m`, once per pair with all
  // its points together, in the order their first too-deep point appears in `contacts`.
  CorrectionCount correct(World& world, const std::vector<Contact>& contacts, double tolerance_m,
                          const std::vector<BodyExtent>& extents);
  // Projects each island of `contacts` (touching or within the margin) with a point deeper than
  // `tolerance_m` as a whole (island_projection.h): by pivoting where its rows can be pivoted (at
  // most `max_direct_rows`, three per contact), by sweeps where not. The same reach and the same
  // payment for a gain as a pair's projection, over the island's bodies. Counts islands.
  CorrectionCount correctIslands(World& world, const std::vector<Contact>& contacts, double tolerance_m,
                                 const std::vector<BodyExtent>& extents, int max_direct_rows, ContactSolveStats& stats);

 private:
  std::vector<double> used_;    // m: how far this step's corrections have moved each body's points
  std::vector<const Contact*> near_;         // correctIslands' buffers
  ContactIslands islands_;
  std::vector<BodyDisplacement> moves_;
  std::vector<int> moved_bodies_;
};

}  // namespace tumble
