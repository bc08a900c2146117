#include "dynamics/penalty/contact_stiffness.h"

#include <cmath>
#include <limits>

#include "dynamics/penalty/force_laws.h"

namespace tumble {

double effectiveModulus(const RigidBody& a, const RigidBody& b) {
  const double compliance = (1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus_pa +
                            (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus_pa;
  return 1 / compliance;
}

double effectiveRadius(double radius_a, double radius_b) {
  const double curvature = (std::isfinite(radius_a) ? 1 / radius_a : 0) + (std::isfinite(radius_b) ? 1 / radius_b : 0);
  return curvature > 0 ? 1 / curvature : std::numeric_limits<double>::infinity();
}

double materialStiffness(NormalForceLaw law, double e_star, double r_star) {
  if (lawIsLinear(law)) return 2 * e_star * r_star;
  return 4.0 / 3.0 * e_star * std::sqrt(r_star);
}

}  // namespace tumble
