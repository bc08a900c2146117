#include "dynamics/baraff/time_of_impact.h"

#include <cmath>

namespace tumble {

ImpactSearch findFirstContact(const std::function<double(double)>& depth_at, double h,
                              double depth_at_h, double tolerance, int max_iterations,
                              bool regula_falsi) {
  // Bracket [lo, hi]: at lo the pairs are at most `tolerance` deep, at hi deeper. The depth at lo
  // is unknown until evaluated; starting from the step's beginning it is taken as -inf (apart).
  double lo = 0, hi = h;
  double f_lo = -std::numeric_limits<double>::infinity(), f_hi = depth_at_h;
  ImpactSearch out;
  int side = 0;   // Illinois: which end was kept last, to halve its weight when kept twice
  if (regula_falsi) {
    // The secant needs the depth at the start of the step too.
    f_lo = depth_at(0);
    ++out.evaluations;
  }
  for (int i = 0; i < max_iterations; ++i) {
    double t = 0.5 * (lo + hi);
    if (regula_falsi && std::isfinite(f_lo)) {
      // The root of the secant through (lo, f_lo - tol) and (hi, f_hi - tol): the time the depth
      // crosses the tolerance if it changes linearly within the bracket.
      double a = f_lo - tolerance, b = f_hi - tolerance;
      double secant = lo + (hi - lo) * a / (a - b);
      if (secant > lo && secant < hi) t = secant;
    }
    double f = depth_at(t);
    ++out.evaluations;
    if (f > tolerance) {
      hi = t;
      f_hi = f;
      if (side == -1) f_lo = 0.5 * (f_lo + tolerance);   // Illinois: lo kept twice
      side = -1;
    } else {
      lo = t;
      f_lo = f;
      if (side == +1) f_hi = 0.5 * (f_hi + tolerance);
      side = +1;
      if (f >= -tolerance) break;   // touching within the tolerance: the contact time
    }
    if (hi - lo <= 1e-15 * h) break;
  }
  out.time = lo;
  out.depth = f_lo;
  return out;
}

}  // namespace tumble
