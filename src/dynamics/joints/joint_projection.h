// Drift correction for joints that adds no energy. Forces that hold a joint to second order still
// let its error grow with the integrator's truncation and rounding; a Baumgarte term would pull
// it back with a spring and a damper, i.e. with speed and energy. Instead, as the contacts' drift
// projection does (position_projection.h), the joints' position errors are removed by moving
// positions only, by the smallest mass-weighted displacement (dq = M^-1 J^T d with
// J M^-1 J^T d = -C, repeated while the rows are nonlinear), and the velocity error along the
// rows by an impulse (J M^-1 J^T p = -J v): an M-orthogonal projection of the velocities, which
// can only remove kinetic energy. A position projection that lifts the bodies (a joint a contact's
// correction pulled apart, put back higher) pays for the lift from their kinetic energy.
#pragma once

#include "dynamics/world.h"

namespace tumble {

struct JointProjection {
  int passes = 0;            // position passes taken
  double largest_error = 0;  // the largest row error left (m or rad)
};

// Positions: passes while an error exceeds `tolerance` (m, and rad for angular rows), at most
// `max_passes`. A hinge past a limit is brought back to it.
JointProjection projectJointPositions(World& world, double tolerance = 1e-12, int max_passes = 8);

// Velocities: the impulse that leaves every joint row's velocity zero, and no hinge at a limit
// turning further into it (limit rows push only). Also what keeps a joint together after an
// impact has struck one of its bodies.
void removeJointVelocityError(World& world);

}  // namespace tumble
