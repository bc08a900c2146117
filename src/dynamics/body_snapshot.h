// The state (x, q, P, L) of every body, saved before a trial step so that bisection can go back,
// or after a step so that the next can tell whether anything has moved the bodies since.
#pragma once

#include <vector>

#include "dynamics/world.h"

namespace tumble {

class BodySnapshot {
 public:
  void save(const World& world) {
    states_.clear();
    for (const RigidBody& b : world.bodies) states_.push_back({b.x, b.q, b.P, b.L});
  }
  // Whether every body is exactly where, and moving exactly as, it was saved.
  bool matches(const World& world) const {
    if (states_.size() != world.bodies.size()) return false;
    for (std::size_t i = 0; i < states_.size(); ++i) {
      const RigidBody& b = world.bodies[i];
      const State& s = states_[i];
      if (b.x != s.x || b.q.coeffs() != s.q.coeffs() || b.P != s.P || b.L != s.L) return false;
    }
    return true;
  }
  void restore(World& world) const {
    for (std::size_t i = 0; i < states_.size(); ++i) {
      RigidBody& b = world.bodies[i];
      b.x = states_[i].x;
      b.q = states_[i].q;
      b.P = states_[i].P;
      b.L = states_[i].L;
    }
  }

 private:
  struct State {
    Eigen::Vector3d x;
    Eigen::Quaterniond q;
    Eigen::Vector3d P, L;
  };
  std::vector<State> states_;
};

}  // namespace tumble
