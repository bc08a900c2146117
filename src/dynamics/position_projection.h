// Drift projection (contact pipeline step 7, DESIGN.md) for one pair of bodies: the smallest
// displacement of the two, translation and rotation weighted by mass and inertia, that lifts each
// point of the pair deeper than the tolerance back to half of it while every other touching point
// stays where it is. With J the normal rows of those points and M the pair's mass matrix, the
// displacement is M^-1 J^T p with p the least-squares, least-norm solution of
//   J M^-1 J^T p = d,   d_i = depth_i - tol/2 (too deep) or 0 (touching, |depth| <= tol);
// points separated by more than the tolerance are free. (The pseudo-inverse copes with redundant
// points, four corners of one face, whose rows are dependent.)
//
// Why not push the whole body out along the normal by its deepest point: a box landing one edge
// while its other edge rests was lifted off that other edge too, and fell the gap (gaining m g d
// at every landing; rocking on its face was fed that way for ever). And why keep touching points
// where they are rather than only forbid them to sink: lifted past the tolerance by the rotation,
// a resting edge stops being a contact, loses its support force for a sub-step, and the box turns
// about the other edge under gravity.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// `points`: the contacts of one pair of bodies, any depth. Moves the two bodies' x and q (never P
// or L: no kinetic energy is added). Returns false when no point was deeper than tol or the pair
// cannot move (both static).
bool projectPair(World& world, const std::vector<const Contact*>& points, double tol);

}  // namespace tumble
