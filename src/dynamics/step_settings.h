// Settings of one simulation step. Read-only during a step: stages take `const StepSettings&`.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/sleeping.h"
#include "scene/scene.h"

namespace tumble {

struct StepSettings {
  double dt = 1.0 / 240;                          // s: fixed step, divides the frame interval
  Integrator integrator = Integrator::Rk4;        // how (x, q, P, L) advance over dt
  ContactSettings contact;                        // detection margin, tolerances, thresholds
  ContactModel model = ContactModel::Baraff;      // event-driven, or velocity-level time stepping
  int time_stepping_sweeps = 200;                 // Gauss-Seidel sweeps per step at most (TimeStepping)
  SleepSettings sleep;                            // when quiet islands freeze (sleeping.h)
};

}  // namespace tumble
