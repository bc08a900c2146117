#include "dynamics/target_watch.h"

#include <algorithm>
#include <cstdio>


namespace tumble {

TargetWatch::TargetWatch(const World& world, const AccuracyTarget& target, int energy_repaid_within)
    : target_(target), energy_(world, 0, 0, energy_repaid_within), detector_(world) {
  for (const RigidBody& b : world.bodies)
    if (!b.is_static) floor_energy_ += b.mass * world.gravity.norm() * kLiftFloor;
}

void TargetWatch::afterStep(const World& world, const Pipeline& pipeline) {
  if (target_.penetration_m > 0) {
    const ContactDetector::Overlap o = detector_.deepestOverlap(world);
    if (o.depth > deepest_.value)
      deepest_ = {o.depth, world.time, "\"" + world.bodies[o.a].name + "\" and \"" + world.bodies[o.b].name + "\""};
  }
  if (target_.energy_drift <= 0) return;
  energy_.afterStep(world, pipeline.storedEnergy());
  const double in_play = std::max(energy_.scale(), floor_energy_);
  // Nothing in play (nothing moves, nothing falls): nothing can rise by a share of it.
  if (in_play <= 0) return;
  const double share = energy_.rise() / in_play;
  if (share > rise_.value) rise_ = {share, world.time, ""};
}

std::vector<TargetWatch::Line> TargetWatch::report() const {
  std::vector<Line> lines;
  char line[400];
  if (target_.penetration_m > 0) {
    if (deepest_.where.empty())
      std::snprintf(line, sizeof line, "no contact overlapped at a step's end, target %.3g m: met", target_.penetration_m);
    else
      std::snprintf(line, sizeof line, "deepest contact %.3g m at t = %.6g s (%s), target %.3g m: %s", deepest_.value,
                    deepest_.time, deepest_.where.c_str(), target_.penetration_m, penetrationMet() ? "met" : "missed");
    lines.push_back({line, penetrationMet()});
  }
  if (target_.energy_drift > 0) {
    char when[64] = "";
    if (rise_.value > 0) std::snprintf(when, sizeof when, " at t = %.6g s", rise_.time);
    std::snprintf(line, sizeof line, "largest energy rise %.3g of the energy in play%s, target %.3g: %s", rise_.value,
                  when, target_.energy_drift, energyMet() ? "met" : "missed");
    lines.push_back({line, energyMet()});
  }
  return lines;
}

}  // namespace tumble
