// One impact at one point, followed through the impact in normal-impulse space as Routh ("Dynamics
// of a System of Rigid Bodies", 1877/1905, his graphical method) and Stronge ("Rigid body
// collisions with friction", Proc. R. Soc. Lond. A, 1990; "Impact Mechanics", 2000) do. The bodies
// do not move during the impact; their relative velocity at the point is linear in the impulse
// accumulated so far, du = K dp, with K the inverse effective mass at the point (both bodies'
// inverse mass and inertia). The normal impulse p_n is the clock:
//  - while the point slides, friction takes dp_t = -mu (slip direction) dp_n;
//  - when the slip stops, it sticks if the impulse that holds it (dp_t = -K_tt^-1 K_tn dp_n) lies
//    in the friction cone, else it slides on along the one direction in which K gives a slip that
//    grows along itself;
//  - compression ends where the normal velocity reaches 0: the impulse p_c and the work
//    W(p_c) = integral of u_n dp_n (< 0, the energy compression absorbed);
//  - restitution ends at p_f = (1 + e) p_c (Poisson) or where W(p_f) = (1 - e^2) W(p_c) (Stronge),
//    or earlier if the normal velocity comes back to 0 (then the point stays in contact).
// The slip keeps its direction where the tangential part of du/dp_n is parallel to it (always in
// a planar impact, and after a stop): those pieces are linear in p_n and are taken whole, events
// solved exactly. Where the slip turns (3-D) the impact is followed in short pieces, each with the
// slip direction of its middle.
#pragma once

#include <Eigen/Core>

#include "dynamics/settings.h"

namespace tumble {

struct PointImpact {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();   // impulse in the contact frame (normal, t1, t2), N s
  double p_c = 0;          // N s: the normal impulse at the end of compression
  double work_c = 0;       // J: the normal impulse's work up to then (<= 0)
  double work_f = 0;       // J: its work over the whole impact
  int pieces = 0;          // pieces of constant slip direction the impact was followed in
  bool ended = false;      // false: compression never ends (the normal velocity stops rising
                           // while it approaches), or the impact took too many pieces
};

// The impact of a point approaching at u (contact frame: normal first, u[0] < 0) with inverse
// effective mass K (symmetric positive definite, same frame), friction mu and restitution e under
// `law` (Poisson or Stronge). A point that does not approach takes no impulse.
PointImpact followPointImpact(const Eigen::Matrix3d& K, const Eigen::Vector3d& u, double mu, double e,
                              RestitutionLaw law);

}  // namespace tumble
