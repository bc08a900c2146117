// Advances a world with joints as one system. The joints' constraint forces depend on the state
// (a pendulum's centripetal pull grows with its speed squared), so they cannot be held over a step
// as the applied wrenches are: the integrator holds wrenches constant per body, and a joint force
// held at its start-of-step value lags the swing, which drifts the energy by O(dt) per step (an
// RK4 whose stages all see the first stage's force is first order in the constraint). Instead
// every RK4 stage sets the bodies to the stage's state, evaluates the joint forces (and PD
// motor torques) there (joint_forces.h) on top of the held applied wrenches, and takes the
// derivatives: the classical scheme on the coupled system, fourth order in the joints too.
// Semi-implicit Euler is first order anyway: its joint forces are evaluated once, at the start,
// and held over the step at the velocity level (joint_forces.h, JointHold::Velocity): the force
// that leaves each joint's relative velocity zero at the step's end. Held at the acceleration
// level, the centripetal pull, explicit in the speed, gave the whip of the ten-link chain
// (scenes/demos/chain.json, dt 1/480 s) energy at every step from about 0.35 s, under both
// contact models, until its state was not finite; at 1/3840 s it still gained 2.4 J in 4 s. At
// the velocity level it gains none and loses some (5.5-7.5 J of the 14.7 J its fall releases over
// 4 s, where RK4 keeps all but the impacts between links take): the dissipation of the velocity
// level that Bullet's and ODE's chains show too (measured 2026-11-28).
#pragma once

#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

long integrateJoined(World& world, const std::vector<Wrench>& wrenches, const StepSettings& settings,
                     bool velocity_motors);

}  // namespace tumble
