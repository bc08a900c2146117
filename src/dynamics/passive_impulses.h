// An unconverged impulse answer may not do worse than no impulses at all.
//
// Gauss-Seidel lowers the merit 1/2 p^T A p + (b - target)^T p at every row it visits (A = J M^-1
// J^T; b the rows' velocities without the impulses). Where every target is zero or a gap that may
// close (v_n >= -gap / dt <= 0), that merit bounds what the impulses do to the kinetic energy from
// above: dKE = 1/2 p^T A p + p^T J v = merit + p_n . target <= merit. The exact answer has merit <=
// 0 (p = 0 is feasible and the answer minimises it over the feasible cone for frictionless rows;
// with friction, each row's p w <= 0 at the answer), so contacts only take energy. Sweeps from
// zero start at merit 0; sweeps warm-started from the last step's impulses start where that
// guess puts them, which can be above zero, and a sweep cap can stop them there: the 101-stone
// arch's first settling steps, its impulses adding 770 J to a ring that held 750 J, and the ring
// then rang for seconds, its kinetic energy swinging between 0.2 and 9 kJ every 0.1 s. (Friction
// bounds move with the normal impulses, so even sweeps from zero do not lower the merit at every
// update.)
//
// So an answer left above merit 0 is scaled by the factor that minimises the merit along it, the
// whole island alike: alpha p stays inside every friction pyramid and keeps every normal impulse
// non-negative, and the merit at it is -(aim . p)^2 / (2 p^T A p) <= 0.
//
// The merit sees kinetic energy only. In a time step under gravity the impulses also decide where
// the step ends, and an answer that adds no kinetic energy can still lift: on the 101-stone arch,
// settled and at rest, unconverged sweeps (a chain of 100 joints) pushed the ring up at about
// 6 mm/s, 180 J of potential energy a step with 10 J of kinetic energy, its total rising 850 J
// above the lowest it had reached. So a time-stepping solve (gravity_dt > 0: the velocities in
// hand are the step's start plus gravity's impulse g dt) also bounds the total energy the step ends
// with. With v the velocities in hand, the impulses change them by M^-1 J^T p, and the step moves
// each body by its new velocity times dt: against the step's start the energy rises by
//   alpha (p^T J v - dt g . P) + alpha^2 p^T A p / 2 - sum m |g|^2 dt^2 / 2
// (P: the impulses' sum on the moving bodies; the last term is what gravity's impulse alone takes:
// semi-implicit Euler's free fall ends a step that much lower than it began). The answer is scaled
// to the largest alpha at which that is not above zero; the exact answer of a body at rest lands
// on zero itself, and is kept. This bounds a step's rise, not a sum over steps, and it is applied
// only to unconverged answers, as the merit is: the arch's ring still ends above the lowest it
// reached, lifted out of the overlaps of its settling by the drift projection.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact_jacobian.h"
#include "dynamics/row_gauss_seidel.h"
#include "dynamics/world.h"

namespace tumble {

struct ImpulseMerit {
  double linear = 0;      // (b - target)^T p
  double quadratic = 0;   // p^T A p
  // With gravity over a step (gravity_dt > 0): p^T J v, the impulses' work on the velocities in
  // hand; -dt g . P, the potential energy the step's motion gains from P, the sum of the impulses
  // on the moving bodies; and sum m |g|^2 dt^2 / 2 over those bodies (the header).
  double work = 0, lift = 0, fall = 0;
  double value() const { return linear + 0.5 * quadratic; }
};

// The merit of impulses `p` along `rows` (b and the sliding targets of `limits` as Gauss-Seidel
// reads them). Visits the rows' bodies only; allocates nothing once its buffers have grown.
ImpulseMerit impulseMerit(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                          const std::vector<RowLimit>& limits, Eigen::Ref<const Eigen::VectorXd> p,
                          double gravity_dt = 0);

// The share of the terms of the step's energy an unconverged answer may still add (rounding: the
// exact answer of a resting island lands on the bound itself).
inline constexpr double kEnergySlack = 1e-9;

// Scales `p` down where its merit is above zero (see above), and, with gravity_dt > 0 (a
// time-stepping solve: the velocities in hand are the step's start plus gravity's impulse over
// gravity_dt), where it would end the step with more total energy than it started with. Returns
// the factor applied (1: kept).
double keepPassive(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                   const std::vector<RowLimit>& limits, Eigen::Ref<Eigen::VectorXd> p, double gravity_dt = 0);

}  // namespace tumble
