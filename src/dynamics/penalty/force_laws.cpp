#include "dynamics/penalty/force_laws.h"

#include <algorithm>
#include <cmath>

namespace tumble {

double lawExponent(NormalForceLaw law) { return lawIsLinear(law) ? 1.0 : 1.5; }

bool lawIsLinear(NormalForceLaw law) { return law == NormalForceLaw::Hooke || law == NormalForceLaw::KelvinVoigt; }

double hertzDampingFactor(NormalForceLaw law, double e) {
  switch (law) {
    case NormalForceLaw::HuntCrossley: return 1.5 * (1 - e);
    case NormalForceLaw::LankaraniNikravesh: return 0.75 * (1 - e * e);
    case NormalForceLaw::Flores: {
      double ef = std::max(e, kMinFloresRestitution);
      return 8 * (1 - ef) / (5 * ef);
    }
    default: return 0;
  }
}

double kelvinVoigtRestitution(double zeta) {
  constexpr double kPi = 3.14159265358979323846;
  if (zeta <= 0) return 1;
  if (zeta < 1) {
    const double s = std::sqrt(1 - zeta * zeta);
    const double theta = kPi - 2 * std::asin(zeta);   // ω_d t at the end of the contact
    return std::exp(-zeta * theta / s) * (-std::cos(theta) + zeta / s * std::sin(theta));
  }
  if (zeta == 1) zeta = 1 + 1e-9;   // the critical case is the limit of both sides
  // Overdamped, in units of ω: δ = (exp(r1 t) - exp(r2 t)) / (r1 - r2) for unit closing speed;
  // the force k δ + D δ' = -m δ'' is zero where r1² exp(r1 t) = r2² exp(r2 t).
  const double root = std::sqrt(zeta * zeta - 1);
  const double r1 = -zeta + root, r2 = -zeta - root;
  const double t = 2 * std::log(r2 / r1) / (r1 - r2);
  const double rate = (r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)) / (r1 - r2);
  return -rate;
}

double kelvinVoigtDampingRatio(double e) {
  e = std::clamp(e, kMinKelvinVoigtRestitution, 1.0);
  if (e >= 1) return 0;
  // kelvinVoigtRestitution falls monotonically from 1 at ζ = 0 towards 0 as ζ grows: bisect on
  // log ζ between 1e-6 and 1e6.
  double lo = std::log(1e-6), hi = std::log(1e6);
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kelvinVoigtRestitution(std::exp(mid)) > e ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

double normalForce(const NormalLawState& s, double delta, double delta_rate) {
  if (!(delta > 0)) return 0;
  const double elastic = s.exponent == 1 ? s.stiffness * delta : s.stiffness * std::pow(delta, s.exponent);
  double f = elastic + s.damping * delta_rate;
  if (s.damping_factor > 0) f = elastic * (1 + s.damping_factor * delta_rate / s.closing_speed);
  return std::max(f, 0.0);
}

double storedEnergy(const NormalLawState& s, double delta) {
  if (!(delta > 0)) return 0;
  return s.stiffness * std::pow(delta, s.exponent + 1) / (s.exponent + 1);
}

}  // namespace tumble
