// Drift projection of a whole island at once. Pair by pair (position_projection.h), a projection
// moves each pair in inverse proportion to mass, so a light body pinched between heavy ones takes
// nearly all of every push: lifted out of the block above it goes into the block below, and back,
// while the heavy blocks, which are the ones that must part, move by the mass ratio's fraction
// each time. Passes of pair projections are Gauss-Seidel on positions, and at 6400:1 they do not
// converge: a 10 g plate under a 64 kg block was turned 5 mrad back and forth within one step's
// passes until a corner of it stood 1.6 mm in the block above.
//
// Here the island's touching points are solved together, as M. B. Cline and D. K. Pai solve them
// ("Post-stabilization for rigid body simulation with contact and constraints", ICRA 2003): the
// smallest displacement weighted by mass and inertia, M^-1 J^T p with pushes p >= 0 along the
// normal rows, that leaves every point at most tol/2 deep,
//
//   w = J M^-1 J^T p + (tol/2 - depth) >= 0,   p >= 0,   p^T w = 0,
//
// a linear complementarity problem with the resting solve's matrix, solved exactly by pivoting.
// A point is pushed only where it would otherwise end deeper than tol/2, and then to tol/2.
//
// With friction, as the impulse problem has it: each touching point's two tangent rows hold its
// two surfaces from sliding over each other, within mu times its push (a friction pyramid). By
// normals alone the smallest displacement slides a light body wherever a slide lowers a depth: the
// 10 g plate, between two faces 1 mrad apart, squeezed out sideways 3.2 mm to gain 3 um. With
// friction it holds, as the same squeeze holds it in the dynamics; without (mu = 0) it slides.
// The displacement is then M^-1 J^T p over the normal and the friction rows.
//
// The Baraff model's drift correction uses it from its second pass on (baraff/drift_correction.h),
// by pivoting where the island is small enough and by sweeps where it is not.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "dynamics/contact.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/world.h"

namespace tumble {

// One moving body's share of an island's projection.
struct BodyDisplacement {
  int body = -1;
  Eigen::Vector3d dx = Eigen::Vector3d::Zero();       // m, world
  Eigen::Vector3d dtheta = Eigen::Vector3d::Zero();   // rad, world (a rotation vector)
};

// The displacement (above) of the moving bodies of `island`, the contacts of one island, into
// `out`, one entry per moving body in order of first appearance (applied by displaceBody,
// position_projection.h). Contacts apart (a gap within the
// detection margin) take part too: their rows push only if the displacement would close the gap.
// False when the pivoting solve has no usable answer.
bool islandProjection(const World& world, std::span<const Contact* const> island, double tol,
                      std::vector<BodyDisplacement>& out, ContactSolveStats& stats);

// The same problem for an island too large to pivot (tooLargeToPivot), by projected Gauss-Seidel
// sweeps from no push with the impulse solve's subspace rounds (island_impulses.h). Pair by pair,
// the projection cannot open a closed chain: the 101-stone arch, its joints 3 um deep between two
// feet on the ground, took eight passes of pair pushes every step without lowering its deepest
// point, each pass lifting the ring a little (360 J in 6 s). Where the sweeps stop unconverged
// the push is part of the way, and the next pass goes on from there.
bool islandProjectionBySweeps(const World& world, std::span<const Contact* const> island, double tol,
                              std::vector<BodyDisplacement>& out, ContactSolveStats& stats);

}  // namespace tumble
