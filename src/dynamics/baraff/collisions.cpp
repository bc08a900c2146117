#include "dynamics/baraff/collisions.h"

#include "dynamics/baraff/impulse_propagation.h"
#include "dynamics/contact_islands.h"
#include "dynamics/contact_rows.h"

namespace tumble {

ContactClass classify(const World& world, const Contact& c, const ContactSettings& s) {
  if (!(c.depth >= -s.tolerance_m)) return ContactClass::Separating;   // not touching
  double vn = normalVelocity(world, c);
  if (vn < -s.resting_speed_m_s) return ContactClass::Colliding;
  if (vn > s.resting_speed_m_s) return ContactClass::Separating;
  return ContactClass::Resting;
}

bool resolveCollisions(World& world, const std::vector<Contact>& contacts, const ContactSettings& s,
                       double min_bounce_speed, double dt, ContactSolveStats& stats) {
  // Every touching contact takes part, resting ones too: an impact is passed on through what it
  // presses against. Islands are independent; within one, impulse_propagation.h says how the
  // impact travels pair by pair while each pair's points are solved together.
  std::vector<const Contact*> set, outside;
  bool any = false;
  for (const Contact& c : contacts) {
    ContactClass k = classify(world, c, s);
    if (k == ContactClass::Separating) {
      outside.push_back(&c);   // may yet close on a body an impact sets moving (neighbour_turn_back.h)
      continue;
    }
    any |= k == ContactClass::Colliding;
    stats.colliding += k == ContactClass::Colliding;
    set.push_back(&c);
  }
  if (!any) return false;
  for (const std::vector<const Contact*>& island : splitIntoIslands(world, set))
    propagateImpulses(world, island, outside, s, min_bounce_speed, dt, stats);
  return true;
}

}  // namespace tumble
