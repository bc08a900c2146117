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
// it advanced (the moving ones): the work counter that shows static bodies cost nothing. A world
// with joints is advanced as one system, the joints' forces evaluated at every stage
// (joints/joint_integrator.h); without joints each body is advanced on its own (integrateBodies).
// `velocity_motors`: whether the joints' velocity motors act through the step (the time-stepping
// model has already given them their impulse, bounded by max torque x dt, and passes false).
long integrate(World& world, const std::vector<Wrench>& wrenches, const StepSettings& settings,
               bool velocity_motors = true);
long integrateBodies(World& world, const std::vector<Wrench>& wrenches, const StepSettings& settings);

// The state of one body as the ODE sees it: y = (x, q, P, L), dy/dt = (P/m, 1/2 [0,w] q, F, tau)
// (Yang, "Rigid Bodies and Contacts", 2020: "rigid body state"). Derivatives of q are kept as plain
// 4-vectors (w, x, y, z).
struct BodyState {
  Eigen::Vector3d x, P, L;
  Eigen::Vector4d q;
};
BodyState stateOf(const RigidBody& body);
BodyState derivativeOf(const RigidBody& body, const BodyState& s, const Wrench& wrench);
BodyState advanced(const BodyState& s, const BodyState& d, double h);   // s + h d
Eigen::Quaterniond toQuaternion(const Eigen::Vector4d& v);             // normalised

// The rotation by angle |w| dt about w, as a unit quaternion (the exact exponential map, not the
// first-order q + dt/2 w q that leaves the unit sphere).
Eigen::Quaterniond rotationOver(const Eigen::Vector3d& w, double dt);

}  // namespace tumble
