// Advances the state (x, q, P, L) of every moving body over one step, given the force and torque
// on each (held constant over the step). Static bodies are never integrated.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // N, through the centre of mass
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();   // N m, about the centre of mass
};

// `wrenches` has one entry per body (static bodies' entries are ignored). Returns how many bodies
// it advanced (the moving ones): the work counter that shows static bodies cost nothing.
long integrate(World& world, const std::vector<Wrench>& wrenches, const StepSettings& settings);

// The rotation by angle |w| dt about w, as a unit quaternion (the exact exponential map, not the
// first-order q + dt/2 w q that leaves the unit sphere).
Eigen::Quaterniond rotationOver(const Eigen::Vector3d& w, double dt);

}  // namespace tumble
