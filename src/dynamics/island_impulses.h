// The velocity-level impulse problem of one island of contacts (Moreau 1988; Stewart and Trinkle
// 1996), the solve both contact models share: the time-stepping model solves every island this
// way, the Baraff model its resting islands too large to pivot. With w = A p + b the rows'
// velocities after the impulses p (b: the velocities without them, less each row's target):
//
//   normal rows    w >= 0, p >= 0, w p = 0
//   tangent rows   w = 0 while |p_t| <= mu p_n (a friction pyramid), else p_t at the bound
//
// solved by projected Gauss-Seidel (row_gauss_seidel.h) from a warm start (contact_rows.h).
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "dynamics/contact_rows.h"

namespace tumble {

struct IslandImpulseSettings {
  int max_sweeps = 200;
  double tolerance = 1e-6;   // of the largest velocity term (row_gauss_seidel.h)
  // Subspace rounds where the sweeps stop unconverged (island_impulses.cpp); off for a speed
  // setting that takes an unconverged answer by choice.
  bool subspace_rounds = true;
  // A time-stepping solve: the step's length, over which gravity's impulse is in the velocities
  // (passive_impulses.h: an unconverged answer may not raise the step's total energy). 0: other solves.
  double gravity_dt = 0;
};

struct IslandImpulses {
  Eigen::VectorXd p;         // impulse along each row (N s)
  bool converged = false;
};

// `rows` holds the island's contacts (`island`) with their friction pyramids (buildContactRows).
// Counts the island, its sweeps and whether it hit the cap in `stats`. An empty `start` starts
// from zero.
IslandImpulses solveIslandImpulses(const World& world, const ContactRows& rows, std::span<const Contact* const> island,
                                   const Eigen::VectorXd& b, const Eigen::VectorXd& start,
                                   const IslandImpulseSettings& settings, ContactSolveStats& stats);

// The same solve in place, allocating nothing once its buffers have grown to the island: `p` (one
// entry per row) holds the first guess on entry and the impulses on exit. Returns whether it
// converged.
bool solveIslandImpulsesInPlace(const World& world, const ContactRows& rows, std::span<const Contact* const> island,
                                Eigen::Ref<const Eigen::VectorXd> b, Eigen::Ref<Eigen::VectorXd> p,
                                const IslandImpulseSettings& settings, ContactSolveStats& stats);

}  // namespace tumble
