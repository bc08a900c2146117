// Advances a world with joints as one system. The joints' constraint forces depend on the state
// (a pendulum's centripetal pull grows with its speed squared), so they cannot be held over a step
// as the applied wrenches are: the integrator holds wrenches constant per body, and a joint force
// held at its start-of-step value lags the swing, which drifts the energy by O(dt) per step (an
// RK4 whose stages all see the first stage's force is first order in the constraint). Instead
// every RK4 stage sets the bodies to the stage's state, evaluates the joint forces (and PD
// motor torques) there (joint_forces.h) on top of the held applied wrenches, and takes the
// derivatives: the classical scheme on the coupled system, fourth order in the joints too.
// Semi-implicit Euler is first order anyway: its joint forces are evaluated once, at the start.
#pragma once

#include <vector>

#include "dynamics/integrator.h"
#include "dynamics/settings.h"
#include "dynamics/world.h"

namespace tumble {

long integrateJoined(World& world, const std::vector<Wrench>& wrenches, const StepSettings& settings,
                     bool velocity_motors);

}  // namespace tumble
