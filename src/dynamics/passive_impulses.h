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
  double value() const { return linear + 0.5 * quadratic; }
};

// The merit of impulses `p` along `rows` (b and the sliding targets of `limits` as Gauss-Seidel
// reads them). Visits the rows' bodies only; allocates nothing once its buffers have grown.
ImpulseMerit impulseMerit(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                          const std::vector<RowLimit>& limits, Eigen::Ref<const Eigen::VectorXd> p);

// Scales `p` down where its merit is above zero (see above). Returns the factor applied (1: kept).
double keepPassive(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                   const std::vector<RowLimit>& limits, Eigen::Ref<Eigen::VectorXd> p);

}  // namespace tumble
