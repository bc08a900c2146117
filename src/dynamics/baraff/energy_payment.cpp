#include "dynamics/baraff/energy_payment.h"

#include <algorithm>
#include <cmath>

namespace tumble {

double mechanicalEnergy(const World& world, int body) {
  const RigidBody& b = world.bodies[body];
  return b.is_static ? 0.0 : b.kineticEnergy() - b.mass * world.gravity.dot(b.x);
}

double payFrom(World& world, const std::vector<int>& bodies, double gain) {
  double kinetic = 0;
  for (int body : bodies)
    if (!world.bodies[body].is_static) kinetic += world.bodies[body].kineticEnergy();
  if (!(kinetic > 0)) return gain;
  const double scale = std::sqrt(std::max(0.0, 1 - gain / kinetic));
  for (int body : bodies)
    if (!world.bodies[body].is_static) {
      world.bodies[body].P *= scale;
      world.bodies[body].L *= scale;
    }
  return std::max(0.0, gain - kinetic);
}

}  // namespace tumble
