// Contacts and joints in one impulse problem. A joint's reaction and a contact's push act on the
// same bodies: solved one after the other, each undoes part of the other (a chain lying on the
// ground pressed into it by its joints' impulses, then lifted out by the contacts'). Here the
// contact rows (normal rows f >= 0, friction rows bounded by mu times their normal, ODE's findex)
// and the joint rows (bilateral, limits f >= 0, motors boxed) make one LCP with
// A = J M^-1 J^T over both, solved by pivoting where it is small enough: exact, where
// Gauss-Seidel passes a change along a chain about one link per sweep. A larger one (a joined body
// in a pile) is swept by projected Gauss-Seidel over all its rows.
#pragma once

#include <vector>

#include "dynamics/contact_rows.h"
#include "dynamics/joints/joint_rows.h"
#include "dynamics/settings.h"

namespace tumble {

// A contact row as a generic row: a force f along it pushes B by +f dir at rb, A by -f dir at ra.
JointRow asGenericRow(const ContactRow& row);

// The contact problem (its rows first, b filled) with the joint rows and their b appended: A over
// both, the joints' own bounds.
lcp::LcpProblem withJointRows(const World& world, const lcp::LcpProblem& contacts,
                              const std::vector<ContactRow>& contact_rows, const std::vector<JointRow>& joints,
                              const Eigen::VectorXd& joint_b);

struct ContactJointSettings {
  int max_direct_rows = 256;      // more rows in all: projected Gauss-Seidel instead of pivoting
  int max_sweeps = 200;           // Gauss-Seidel's cap
  Eigen::VectorXd contact_start;  // the contact rows' warm start (last step's impulses), or empty
};

// Solves the contact LCP `contacts` (its b filled) together with the joint rows and their b, by
// pivoting up to max_direct_rows rows in all and by Gauss-Seidel beyond (generic_gauss_seidel.h);
// applies the joints' impulses to the world and returns the contact rows' impulses, which the
// caller applies and records.
Eigen::VectorXd solveContactsWithJoints(World& world, const ContactLcp& contacts, const std::vector<JointRow>& joints,
                                        const Eigen::VectorXd& joint_b, const ContactJointSettings& settings,
                                        ContactSolveStats& stats);

// The same rows by projected Gauss-Seidel only, for a solve that is iterative anyway (the Baraff
// model's resting islands at the velocity level, and its acceleration sweeps): `limits` are the
// contact rows' limits (row_gauss_seidel.h: pyramids, or a slide's row against it with its target),
// b both sets' velocity (or acceleration) terms. Returns the contact rows' impulses (forces), then
// the joint rows'; applies nothing.
Eigen::VectorXd sweepContactsWithJoints(const World& world, const ContactRows& contacts,
                                        const std::vector<RowLimit>& limits, const Eigen::VectorXd& contact_b,
                                        const std::vector<JointRow>& joints, const Eigen::VectorXd& joint_b,
                                        const Eigen::VectorXd& contact_start, ContactSolveStats& stats,
                                        double tolerance = tuning::kImpulseTolerance);

}  // namespace tumble
