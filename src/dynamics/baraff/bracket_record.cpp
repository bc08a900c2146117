#include "dynamics/baraff/bracket_record.h"

#include <algorithm>

namespace tumble {

BracketRecord::BracketRecord(BackStepLog* log, double time, double h) : log_(log) {
  mark_.time = time;
  mark_.h = h;
}

void BracketRecord::watch(const World& world, int a, int b, const Eigen::Vector3d& point) {
  if (!log_) return;
  mark_.point += point;
  ++points_;
  for (int body : {a, b}) {
    if (world.bodies[static_cast<std::size_t>(body)].fixedByScene()) continue;
    if (mark_.bodies.size() >= BackStepMark::kMaxBodies) break;
    if (std::find(mark_.bodies.begin(), mark_.bodies.end(), body) == mark_.bodies.end()) mark_.bodies.push_back(body);
  }
}

void BracketRecord::trial(const World& world, double t, bool too_deep) {
  if (!log_) return;
  BackStepTrial trial{t, too_deep, {}};
  trial.poses.reserve(mark_.bodies.size());
  for (int body : mark_.bodies) {
    const RigidBody& b = world.bodies[static_cast<std::size_t>(body)];
    trial.poses.push_back({b.x, b.q});
  }
  mark_.trials.push_back(std::move(trial));
}

void BracketRecord::found(double t, int evaluations) {
  if (!log_) return;
  mark_.found = t;
  mark_.iterations = evaluations;
  if (points_ > 0) mark_.point /= points_;
  log_->add(std::move(mark_));
  log_ = nullptr;   // one mark per back-step
}

}  // namespace tumble
