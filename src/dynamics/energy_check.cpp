#include "dynamics/energy_check.h"

#include <algorithm>

namespace tumble {

EnergyCheck::EnergyCheck(const World& world, double share, double drift_m, int repaid_within)
    : share_(share), repaid_within_(repaid_within) {
  for (const RigidBody& b : world.bodies)
    if (!b.fixedByScene()) drift_allowance_ += b.mass * world.gravity.norm() * drift_m;
  sample(world);
  largest_kinetic_ = kinetic_;
  lowest_potential_ = highest_potential_ = potential_;
}

// Kinetic energy of the moving bodies (a sleeping one is at rest) plus potential energy -m g.x of
// every body that can move (the world origin is its zero, which the tolerance does not depend on).
EnergyCheck::Sample EnergyCheck::sample(const World& world) {
  Sample s;
  s.per_body.assign(world.bodies.size(), 0.0);
  kinetic_ = potential_ = 0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.fixedByScene()) continue;
    const double k = b.is_static ? 0.0 : b.kineticEnergy(), p = -b.mass * world.gravity.dot(b.x);
    kinetic_ += k;
    potential_ += p;
    s.per_body[i] = k + p;
  }
  s.total = kinetic_ + potential_;
  return s;
}

std::optional<EnergyGain> EnergyCheck::afterStep(const World& world, double stored) {
  recent_.push_back(sample(world));
  recent_.back().total += stored;
  largest_kinetic_ = std::max(largest_kinetic_, kinetic_);
  lowest_potential_ = std::min(lowest_potential_, potential_);
  highest_potential_ = std::max(highest_potential_, potential_);
  if (recent_.size() > static_cast<std::size_t>(repaid_within_) + 1) recent_.erase(recent_.begin());
  // The largest of the last repaid_within + 1 totals is a level the energy held (or came back to).
  if (recent_.size() == static_cast<std::size_t>(repaid_within_) + 1) {
    const auto held = std::max_element(recent_.begin(), recent_.end(),
                                       [](const Sample& x, const Sample& y) { return x.total < y.total; });
    if (!started_ || held->total < lowest_.total) lowest_ = *held;
    started_ = true;
  }
  if (!started_) return std::nullopt;
  const Sample& now = recent_.back();
  const double scale = largest_kinetic_ + (highest_potential_ - lowest_potential_);
  const double tolerance = share_ * scale + drift_allowance_;
  rise_ = std::max(0.0, now.total - lowest_.total);
  scale_ = scale;
  if (now.total - lowest_.total <= tolerance) return std::nullopt;
  EnergyGain gain{now.total, lowest_.total, tolerance, -1};
  double most = 0;   // the total rose, so some body's energy rose by more than nothing
  for (std::size_t i = 0; i < now.per_body.size(); ++i)
    if (now.per_body[i] - lowest_.per_body[i] > most) {
      most = now.per_body[i] - lowest_.per_body[i];
      gain.body = static_cast<int>(i);
    }
  return gain;
}

}  // namespace tumble
