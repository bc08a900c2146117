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

namespace {

// How many times the collision stage looks again for touching contacts that its impulses set
// approaching. Each round resolves every island with a colliding contact; a sandwich of two light
// plates between blocks takes a few.
constexpr int kCollisionRounds = 4;

}  // namespace

bool resolveCollisions(World& world, const std::vector<Contact>& contacts, const ContactSettings& s,
                       const BounceThreshold& min_bounce_speed, double dt, ContactSolveStats& stats) {
  // Every touching contact takes part, resting ones too: an impact is passed on through what it
  // presses against. Islands are independent; within one, impulse_propagation.h says how the
  // impact travels pair by pair while each pair's points are solved together.
  //
  // An impact can set approaching a touching contact that was separating when it began, so not in
  // its island (a block landing on a plate drives it, and the plate under it, down onto the block
  // below, which they had just bounced off): the stage repeats, as Baraff's collision loop does,
  // until no touching contact approaches. Left for the next sub-step, that contact went 1.2-1.8 mm
  // deep within the sub-step, since back-stepping takes a touching pair that is not lifting off for
  // one at rest. After kCollisionRounds, the islands still colliding take one inelastic impact.
  std::vector<const Contact*> set, outside;
  std::vector<char> colliding(contacts.size());   // per contact, this round
  bool hit = false;
  for (int round = 0; round <= kCollisionRounds; ++round) {
    set.clear();
    outside.clear();
    bool any = false;
    for (const Contact& c : contacts) {
      ContactClass k = classify(world, c, s);
      colliding[static_cast<std::size_t>(&c - contacts.data())] = k == ContactClass::Colliding;
      if (k == ContactClass::Separating) {
        outside.push_back(&c);   // may yet close on a body an impact sets moving (neighbour_turn_back.h)
        continue;
      }
      any |= k == ContactClass::Colliding;
      if (round == 0) stats.colliding += k == ContactClass::Colliding;
      set.push_back(&c);
    }
    if (!any) break;
    hit = true;
    for (const std::vector<const Contact*>& island : splitIntoIslands(world, set)) {
      // Islands share no moving body: what the others' impulses did leaves this one's classes.
      bool any_colliding = false;
      for (const Contact* c : island) any_colliding |= colliding[static_cast<std::size_t>(c - contacts.data())] != 0;
      if (!any_colliding) continue;
      if (round < kCollisionRounds) propagateImpulses(world, island, outside, s, min_bounce_speed, dt, stats);
      else plasticIslandImpact(world, island, s, min_bounce_speed, dt, stats);
    }
  }
  return hit;
}

}  // namespace tumble
