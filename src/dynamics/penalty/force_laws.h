// The regularised family's normal force laws: the force between two bodies as a function of
// their overlap δ (m, > 0 while they touch) and its rate δ' (m/s, > 0 while they close), with the
// damping of each law tied to the pair's coefficient of restitution e (P. Flores, "Contact
// mechanics for dynamical systems: a comprehensive review", Multibody System Dynamics, 2022,
// equations 29-34):
//
//   hooke                k δ                                   elastic, e = 1 whatever the body says
//   kelvin_voigt         k δ + D δ'                            D = 2 ζ sqrt(k m), ζ from e (below)
//   hertz                K δ^1.5                               elastic
//   hunt_crossley        K δ^1.5 (1 + 3(1 - e)/2 δ'/δ'-)       Hunt and Crossley, J. Appl. Mech., 1975
//   lankarani_nikravesh  K δ^1.5 (1 + 3(1 - e²)/4 δ'/δ'-)      Lankarani and Nikravesh, J. Mech. Des., 1990
//   flores               K δ^1.5 (1 + 8(1 - e)/(5e) δ'/δ'-)    Flores, Machado, Silva and Martins,
//                                                              Multibody Syst. Dyn., 2011
//
// δ'- is the closing speed when the contact began. Bodies cannot pull each other: a law's force is
// never negative, so a contact ends when its force reaches zero, which may be before δ does.
//
// The relations between damping and e of the three Hertz-type laws come from energy balances that
// assume e near 1 (Hunt and Crossley's and Lankarani and Nikravesh's say so; Flores et al.'s was
// fitted over the whole range). The e they give departs from the one asked as e falls: see
// restitutionOf below, and the figures in docs/penalty.md.
//
// Kelvin and Voigt's linear damper gives a closed form: the contact is a damped oscillator of
// damping ratio ζ, and it ends when k δ + D δ' = 0 (the force would turn to a pull). With ω the
// undamped frequency, for ζ < 1 that is at ω_d t = π - 2 asin ζ, where
//   e = exp(-ζ ω t) (-cos ω_d t + ζ / sqrt(1 - ζ²) sin ω_d t),   ω_d = ω sqrt(1 - ζ²),
// and for ζ > 1 at the inflection of the overdamped motion. kelvinVoigtDamping inverts it.
#pragma once

#include "dynamics/settings.h"

namespace tumble {

// The exponent n of a law: 1 for the linear laws, 1.5 for the Hertz-type ones.
double lawExponent(NormalForceLaw law);
bool lawIsLinear(NormalForceLaw law);
// The factor χ of a Hertz-type law's damping term χ δ'/δ'-, for restitution e (0 for Hertz).
double hertzDampingFactor(NormalForceLaw law, double e);
// Kelvin-Voigt: the damping ratio ζ whose contact (ending when the force reaches zero) gives
// restitution e; e below kMinKelvinVoigtRestitution takes that value's ζ.
double kelvinVoigtDampingRatio(double e);
// Kelvin-Voigt: the restitution a damping ratio gives (the closed form above).
double kelvinVoigtRestitution(double zeta);
inline constexpr double kMinKelvinVoigtRestitution = 0.01;
// Flores et al.'s factor 8(1 - e)/(5e) is infinite at e = 0: below this e it takes this value's.
inline constexpr double kMinFloresRestitution = 0.01;

// What a contact's law needs beyond δ and δ'.
struct NormalLawState {
  double stiffness = 0;       // k (N/m) or K (N/m^1.5)
  double exponent = 1;        // n
  double damping = 0;         // D (N s/m), Kelvin-Voigt only
  double damping_factor = 0;  // χ, Hertz-type laws only
  double closing_speed = 0;   // δ'- (m/s), Hertz-type damped laws only, > 0
};

// The normal force (N, >= 0) at overlap δ and rate δ'; 0 when δ <= 0.
double normalForce(const NormalLawState& s, double delta, double delta_rate);
// The elastic energy the law's spring holds at overlap δ (J): K δ^(n+1) / (n + 1).
double storedEnergy(const NormalLawState& s, double delta);

}  // namespace tumble
