#include "dynamics/baraff/impact_energy.h"

#include <algorithm>

namespace tumble {

ImpactMomenta::ImpactMomenta(const World& world, const std::vector<const Contact*>& points) {
  if (!world.joints.empty())
    for (std::size_t b = 0; b < world.bodies.size(); ++b)
      if (!world.bodies[b].is_static) bodies.push_back(static_cast<int>(b));
  for (const Contact* c : points)
    for (int b : {c->a, c->b})
      if (!world.bodies[b].is_static && std::find(bodies.begin(), bodies.end(), b) == bodies.end())
        bodies.push_back(b);
  for (int b : bodies) {
    P.push_back(world.bodies[b].P);
    L.push_back(world.bodies[b].L);
  }
}

double ImpactMomenta::energy(const World& world) const {
  double e = 0;
  for (int b : bodies) e += world.bodies[b].kineticEnergy();
  return e;
}

void ImpactMomenta::restore(World& world) const {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    world.bodies[bodies[i]].P = P[i];
    world.bodies[bodies[i]].L = L[i];
  }
}

void applyAddingNoEnergy(World& world, const std::vector<const Contact*>& points, double scale,
                         const std::function<void(double)>& apply, const std::function<void()>& inelastic) {
  ImpactMomenta before(world, points);
  const double energy = before.energy(world);
  auto gains = [&] { return before.energy(world) > energy * (1 + kEnergySlack); };
  apply(scale);
  if (!gains()) return;
  // The inelastic impact adds none (impulse_propagation.cpp, restitution_laws.cpp say why for each
  // law): keep the largest restitution that adds none.
  double ok = 0, bad = scale;
  for (int i = 0; i < 30 && bad - ok > 1e-6 * scale; ++i) {
    double mid = 0.5 * (ok + bad);
    before.restore(world);
    apply(mid);
    (gains() ? bad : ok) = mid;
  }
  before.restore(world);
  apply(ok);
  if (!gains()) return;
  before.restore(world);
  inelastic();
}

}  // namespace tumble
