#include "dynamics/baraff/impact_log.h"

#include "dynamics/baraff/collisions.h"

namespace tumble {

void ImpactLogger::before(const World& world, const std::vector<Contact>& contacts, const ContactSettings& settings) {
  pairs_.clear();
  counts_.clear();
  for (const Contact& c : contacts) {
    if (classify(world, c, settings) != ContactClass::Colliding) continue;
    std::size_t k = 0;
    while (k < pairs_.size() && !(pairs_[k].a == c.a && pairs_[k].b == c.b)) ++k;
    if (k == pairs_.size()) {
      ImpactMark m;
      m.time = world.time;
      m.a = c.a;
      m.b = c.b;
      m.on = world.bodies[static_cast<std::size_t>(c.b)].is_static ? c.a : c.b;
      m.normal = c.normal;
      pairs_.push_back(m);
      counts_.push_back(0);
    }
    pairs_[k].point += c.point;
    ++counts_[k];
  }
  momentum_.clear();
  if (pairs_.empty()) return;
  for (const RigidBody& b : world.bodies) momentum_.push_back(b.P);
}

void ImpactLogger::after(const World& world, std::vector<ImpactMark>& log) const {
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    ImpactMark m = pairs_[k];
    m.point /= counts_[k];
    const auto on = static_cast<std::size_t>(m.on);
    m.impulse = world.bodies[on].P - momentum_[on];
    log.push_back(m);
  }
}

}  // namespace tumble
