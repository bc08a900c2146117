// The penalty model's normal force laws (dynamics/penalty/force_laws.h) for the tests: their
// names, and a law's own one-dimensional impact integrated independently of the model, the
// reference the model's bounces are held to.
#pragma once

#include <cmath>

#include "dynamics/penalty/force_laws.h"

namespace tumble::test {

// Every law with its scene-file name (settings.h).
using NamedLaw = LawName<NormalForceLaw>;
inline constexpr const auto& kNormalLaws = kNormalForceLawNames;
// hooke and hertz: no damper, every contact gives back its closing speed.
inline bool isElastic(NormalForceLaw law) { return law == NormalForceLaw::Hooke || law == NormalForceLaw::Hertz; }

// m δ'' = -F(δ, δ') + m g from δ = 0 at closing speed v0 (g: a steady pull pressing the point in,
// 0 for none), by RK4 in 4000 steps per peak time; returns the speed it leaves with over v0.
// Without a pull it is done when the force is zero on the way out (from then on nothing acts);
// with one, when δ is back to 0 (a damped law's force may end before δ does, and the pull still
// slows it on the way out).
inline double oneDimensionalRestitution(const NormalLawState& law, double mass, double v0, double g = 0) {
  const double n = law.exponent;
  const double peak = std::pow((n + 1) * mass * v0 * v0 / (2 * law.stiffness), 1 / (n + 1));
  const double h = peak / v0 / 4000;
  double d = 0, v = v0;
  auto acc = [&](double dd, double vv) { return g - normalForce(law, dd, vv) / mass; };
  for (long i = 0; i < 100000000; ++i) {
    const double k1v = acc(d, v), k1d = v;
    const double k2v = acc(d + h / 2 * k1d, v + h / 2 * k1v), k2d = v + h / 2 * k1v;
    const double k3v = acc(d + h / 2 * k2d, v + h / 2 * k2v), k3d = v + h / 2 * k2v;
    const double k4v = acc(d + h * k3d, v + h * k3v), k4d = v + h * k3v;
    d += h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (d <= 0 || (g == 0 && v < 0 && normalForce(law, d, v) <= 0)) return -v / v0;
  }
  return NAN;
}

}  // namespace tumble::test
