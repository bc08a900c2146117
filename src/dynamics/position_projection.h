// Drift projection (docs/architecture.md) for one pair of bodies with a point
// deeper than the tolerance. Every touching point of the pair (|depth| <= tol) is brought to half
// the tolerance deep; points further apart are free.
//  - A pair flush within the tolerance (its touching points' depths differ by at most 2 tol: a
//    face resting a little too deep) moves straight out along the normal by its deepest point, in
//    inverse proportion to mass, and is never turned.
//  - Otherwise (a landing edge or corner, deeper than the points it rests on) the two bodies move
//    and turn by the smallest displacement, weighted by mass and inertia, that does it: with J the
//    normal rows of the touching points and M the pair's mass matrix, M^-1 J^T p with p the
//    least-squares, least-norm solution of J M^-1 J^T p = depth - tol/2 (the pseudo-inverse copes
//    with redundant points, whose rows are dependent). A displacement that would move a body's
//    points farther than turning it about an axis half its thinnest piece away needs (nearly
//    dependent rows with targets that disagree) is refused: then only the too-deep points are
//    lifted, the others left free, and if that too is out of proportion the pair moves straight
//    out along the deepest point's normal.
//
// Why turn: pushed out by its deepest point, a box landing one edge was lifted off its resting
// edge too and fell the gap, gaining m g d at every landing (rocking on its face was fed that way
// for ever). Why hold the resting points at tol/2 rather than only forbid them to sink: lifted
// past the tolerance, a resting edge stops being a contact, loses its support force for a
// sub-step, and the box turns about the other edge under gravity; left where they are (anywhere
// within the tolerance), the 1000:1 stack and the pile went wrong (see the .cpp for the flush
// case; the pile overlapped by 3.5 mm).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/body_extent.h"
#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// `points`: the contacts of one pair of bodies, any depth. Moves the two bodies' x and q (never P
// or L: no kinetic energy is added). Returns false when no point was deeper than tol or the pair
// cannot move (both static).
bool projectPair(World& world, const std::vector<const Contact*>& points, double tol,
                 const std::vector<BodyExtent>& extents);

// Moves and turns a body by a small displacement: x += dx, q = exp(dtheta) q.
void displaceBody(RigidBody& body, const Eigen::Vector3d& dx, const Eigen::Vector3d& dtheta);

}  // namespace tumble
