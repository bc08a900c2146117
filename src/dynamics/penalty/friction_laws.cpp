#include "dynamics/penalty/friction_laws.h"

#include <algorithm>
#include <cmath>

namespace tumble {

FrictionLawState frictionLawOf(const PenaltySettings& settings, double mu) {
  FrictionLawState s;
  s.law = settings.friction_law;
  s.mu = mu;
  s.mu_static = settings.static_friction_ratio * mu;
  s.v1 = settings.ramp_speed_m_s;
  s.v0 = settings.ambrosio_dead_speed_m_s;
  s.kappa = settings.stribeck_decay_s_m;
  return s;
}

double frictionForce(const FrictionLawState& s, double v, double fn) {
  if (!(fn > 0) || !(v > 0) || s.mu <= 0) return 0;
  switch (s.law) {
    case FrictionLaw::Coulomb: return s.mu * fn * std::min(v / s.v1, 1.0);
    case FrictionLaw::Threlfall: return v <= s.v1 ? s.mu * fn * (1 - std::exp(-3 * v / s.v1)) : 0.95 * s.mu * fn;
    case FrictionLaw::BengisuAkay: {
      if (v <= s.v1) {
        const double u = (v - s.v1) / s.v1;
        return s.mu_static * fn * (1 - u * u);
      }
      return (s.mu + (s.mu_static - s.mu) * std::exp(-s.kappa * (v - s.v1))) * fn;
    }
    case FrictionLaw::Ambrosio:
      if (v < s.v0) return 0;
      if (v <= s.v1) return s.mu * fn * (v - s.v0) / (s.v1 - s.v0);
      return s.mu * fn;
  }
  return 0;
}

double frictionSlope(const FrictionLawState& s) {
  switch (s.law) {
    case FrictionLaw::Coulomb: return s.mu / s.v1;
    case FrictionLaw::Threlfall: return 3 * s.mu / s.v1;
    case FrictionLaw::BengisuAkay: return 2 * s.mu_static / s.v1;
    case FrictionLaw::Ambrosio: return s.mu / (s.v1 - s.v0);
  }
  return 0;
}

}  // namespace tumble
