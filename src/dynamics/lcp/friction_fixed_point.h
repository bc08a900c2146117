// The friction-bound fixed point of solveDantzig, solved at once instead of by passes.
//
// Each pass of solveDantzig freezes the friction bounds ±mu f_n at the last pass's normal forces.
// While the passes keep the same active set (which variables sit at a bound and which are clamped
// inside), the map from one pass's normals to the next is affine, f_n <- c + G f_n, and it
// contracts only at the rate |G| ~ mu x (the contact's moment-arm ratio): about one half for a box
// corner at mu = 0.5, so 12 passes leave 1e-4 of the force unsettled and the solve is reported
// as stopped short (2806 of them in 2 s of the pile, on single contacts). For that active set the
// fixed point is one linear system: the clamped variables satisfy w = 0 with every saturated
// friction variable written as ±mu times its (unknown) normal force,
//
//   (A_II + A_IB D) f_I = -b_I - A_IB d
//
// where D holds ±mu for friction at its bound whose normal is clamped, and d the bounds that are
// constants. The candidate is accepted only if it solves the whole LCP (measureResidual); when
// the active set was not the final one it fails that check and the passes go on.
#pragma once

#include <optional>

#include "dynamics/lcp/lcp_problem.h"

namespace tumble::lcp {

// Which set each variable of an iterate is in, against the bounds it was solved with.
enum class Bound : signed char { Lower = -1, Inside = 0, Upper = 1 };
std::vector<Bound> activeSet(const Eigen::VectorXd& f, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);
void activeSet(const Eigen::VectorXd& f, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, std::vector<Bound>& set);

// The exact solution for the given active set, if it solves p to `tolerance` relative to the
// size of its terms; std::nullopt otherwise.
std::optional<Eigen::VectorXd> solveFrictionFixedPoint(const LcpProblem& p, const std::vector<Bound>& set,
                                                       const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                                       double tolerance = 1e-9);

}  // namespace tumble::lcp
