// The regularised family's friction laws: the friction force's magnitude as a function of the
// slip speed v (m/s) and the normal force f_n, opposing the slip. Each is continuous at v = 0, so
// a body held by friction creeps at a speed of the order of the law's ramp speed: the creep is
// the law's, not an error (P. Flores, "Contact mechanics for dynamical systems: a comprehensive
// review", Multibody System Dynamics, 2022, equations 35-40):
//
//   coulomb       μ f_n min(v / v1, 1)                              Coulomb's law with a velocity ramp
//   threlfall     μ f_n (1 - exp(-3 v / v1))  for v <= v1,          D. C. Threlfall, Mech. Mach.
//                 0.95 μ f_n above (continuous to 0.02 %)           Theory, 1978
//   bengisu_akay  μs f_n (1 - (v - v1)² / v1²)  for v <= v1,        M. T. Bengisu and A. Akay,
//                 (μ + (μs - μ) exp(-κ (v - v1))) f_n above         J. Sound Vib., 1994
//   ambrosio      0 below v0, μ f_n (v - v0)/(v1 - v0) up to v1,    J. Ambrósio, Virtual Nonlinear
//                 μ f_n above                                       Multibody Systems, NATO ASI, 2003
//
// μ is the pair's friction coefficient (the dynamic one), μs = static_friction_ratio μ. The review
// prints Bengisu and Akay's parabola with v0 where v0² keeps it a force, and Ambrósio's ramp as
// (v - v0)/(v - v0); the forms above are the dimensionally consistent ones its figure 8 draws.
#pragma once

#include "dynamics/settings.h"

namespace tumble {

struct FrictionLawState {
  FrictionLaw law = FrictionLaw::Coulomb;
  double mu = 0;              // the pair's (dynamic) coefficient
  double mu_static = 0;       // Bengisu and Akay only
  double v1 = 1e-3;           // m/s: the ramp speed
  double v0 = 1e-4;           // m/s: Ambrosio's dead speed
  double kappa = 10;          // s/m: Bengisu and Akay's decay
};

FrictionLawState frictionLawOf(const PenaltySettings& settings, double mu);
// The friction force's magnitude (N, >= 0) at slip speed v >= 0 under normal force f_n.
double frictionForce(const FrictionLawState& s, double slip_speed, double normal_force);
// The steepest slope d|f_t| / dv of the law per newton of normal force (s/m): how stiff its
// regularisation is, which bounds the sub-step of an explicit integration.
double frictionSlope(const FrictionLawState& s);

}  // namespace tumble
