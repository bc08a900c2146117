#include "dynamics/baraff/contact_work_bound.h"

#include <cmath>

#include "dynamics/baraff/energy_payment.h"
#include "dynamics/contact_islands.h"

namespace tumble {
namespace {

// Rounding in an island's energy: a share of what is in play in it (its kinetic energy plus what
// lifting each body by its radius takes). RK4 on a body at rest on the ground moves its energy by
// about 1e-16 of that; a gain above 1e-9 of it is no rounding.
constexpr double kRounding = 1e-9;

double islandEnergy(const World& world, const std::vector<int>& bodies) {
  double e = 0;
  for (int b : bodies) e += mechanicalEnergy(world, b);
  return e;
}

}  // namespace

void ContactWorkBound::before(const World& world, const std::vector<Contact>& contacts, double tolerance_m,
                              const std::vector<BodyExtent>& extents) {
  islands_.clear();
  energy_.clear();
  slack_.clear();
  std::vector<const Contact*> touching;
  for (const Contact& c : contacts)
    if (c.depth >= -tolerance_m) touching.push_back(&c);
  if (touching.empty()) return;
  std::vector<char> seen(world.bodies.size(), 0);
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, touching)) {
    std::vector<int>& members = islands_.emplace_back();
    double in_play = 0;
    for (const Contact* c : island)
      for (int b : {c->a, c->b})
        if (!world.bodies[b].is_static && !seen[b]) {
          seen[b] = 1;
          members.push_back(b);
          const RigidBody& body = world.bodies[b];
          in_play += body.kineticEnergy() + body.mass * world.gravity.norm() * extents[b].radius;
        }
    energy_.push_back(islandEnergy(world, members));
    slack_.push_back(kRounding * in_play);
  }
}

int ContactWorkBound::after(World& world) const {
  int paid = 0;
  for (std::size_t i = 0; i < islands_.size(); ++i) {
    const double gain = islandEnergy(world, islands_[i]) - energy_[i];
    if (!(gain > slack_[i])) continue;
    payFrom(world, islands_[i], gain);
    ++paid;
  }
  return paid;
}

}  // namespace tumble
