// The LCP over a set of contacts that both the impulse solve (colliding contacts) and the force
// solve (resting contacts) build: one normal row per contact, two tangent rows per contact with
// friction, bounded by +-mu times that contact's normal variable (ODE's findex convention).
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/lcp/lcp_problem.h"
#include "dynamics/world.h"

namespace tumble {

struct ContactSolveStats;

struct ContactLcp {
  std::vector<ContactRow> rows;
  lcp::LcpProblem problem;       // A = J M^-1 J^T, b = 0, bounds set; the caller fills b
  std::vector<int> normal_row;   // per contact: its normal row
};

// `friction[i]` says whether contact i gets friction rows (and it gets them only if mu > 0).
ContactLcp buildContactLcp(const World& world, const std::vector<const Contact*>& set,
                           const std::vector<char>& friction);

// Solves with the Dantzig pivoting solver at the settings contacts need; counts pivots and failures.
lcp::LcpResult solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats);

// Relative normal velocity of a contact (m/s, < 0 approaching).
double normalVelocity(const World& world, const Contact& c);

}  // namespace tumble
