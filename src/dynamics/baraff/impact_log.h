// The impacts of one collide stage, for overlays (SharedStages::impact_log): which pairs collided,
// where, and the impulse each pair's body took. Built only while a log is set; it reads the world
// before and after the impulses and writes nothing back, so the motion is the same with or without.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/shared_stages.h"
#include "dynamics/world.h"

namespace tumble {

class ImpactLogger {
 public:
  // Before the impulses: the colliding contacts (classify, collisions.h) and the momenta.
  void before(const World& world, const std::vector<Contact>& contacts, const ContactSettings& settings);
  // After them: one ImpactMark per colliding pair, appended to `log`.
  void after(const World& world, std::vector<ImpactMark>& log) const;

 private:
  std::vector<ImpactMark> pairs_;            // point summed, then averaged over `counts_`
  std::vector<int> counts_;
  std::vector<Eigen::Vector3d> momentum_;    // per body, before
};

}  // namespace tumble
