// Warm start for the time-stepping model: the impulse each contact point took in the last step,
// found again in this step by its pair of bodies and its position on them. A pile at rest then
// starts Gauss-Seidel at last step's answer and needs a few sweeps instead of hundreds (Xiang, "Robot Control and Physical Simulation", 2020:
// PGS converges slowly from zero on stacks).
//
// A point is kept in body A's frame, so it follows A as it moves; two points of the same pair of
// bodies within `radius` of each other across the contact normal are the same contact. Lookup is
// among body A's records (sorted by body pair), then by nearest point: deterministic.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

struct ImpulseRecord {
  int a = -1, b = -1;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();     // the contact point in body A's frame
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();   // N s on B, world axes (normal + friction)
  // The time-stepping model's impact phase, solved before the step's load (N s on B, world): drawn
  // with the contact's force, never a warm start.
  Eigen::Vector3d impact = Eigen::Vector3d::Zero();
  double landing_speed = 0;   // m/s: approach speed of a landing closed speculatively, owed a bounce
  int landing_carried = 0;    // steps that bounce has been carried past a step that did not touch
};

class ImpulseMemory {
 public:
  // The contact point in body A's frame.
  static Eigen::Vector3d localPoint(const World& world, const Contact& c);
  // Contacts nearer than this (m, across the normal, in A's frame) to a recorded point on the
  // same pair of bodies are that contact: both the time-stepping model and the Baraff model's
  // large resting islands match with it.
  static constexpr double kMatchRadius = 5e-3;
  // Last step's record nearest to contact c (same bodies, within `radius` m), or nullptr.
  const ImpulseRecord* find(const World& world, const Contact& c, double radius) const;
  // Replaces the records with a copy of this step's (any order; sorted here). Its buffers are
  // kept from one step to the next: a warm step allocates nothing here.
  void replace(const std::vector<ImpulseRecord>& records);
  std::size_t size() const { return records_.size(); }

 private:
  std::vector<ImpulseRecord> records_;   // sorted by (a, b), stable within a pair
  std::vector<ImpulseRecord> spare_;     // the records before, their storage reused
  std::vector<std::size_t> first_of_a_;  // per body: its first record as A; one past the last body
  std::vector<std::size_t> order_;
};

}  // namespace tumble
