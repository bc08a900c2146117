// What the back_step overlay draws of the Baraff model's bisection back-stepping
// (baraff/back_step.cpp): for each first contact found by going back, the trial times the search
// tried, whether the watched pairs were too deep at each (the bracket's upper end) or not (its
// lower end), the poses of the pairs' moving bodies there, and how many trials it took.
//
// Kept only while SharedStages::back_step_log is set (overlays on). Logging copies poses the
// search has already integrated to and writes nothing back, so the motion is the same with or
// without it (tests/dynamics/test_frame_record.cpp). The log is bounded: a pile can back-step
// many times between two frames, and a frame shows only the last few.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

namespace tumble {

struct TrialPose {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();             // m, centre of mass, world
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();   // body -> world
};

struct BackStepTrial {
  double t = 0;                  // s into the trial sub-step
  bool too_deep = false;         // deeper than the tolerance: the bracket's upper end
  std::vector<TrialPose> poses;  // one per BackStepMark::bodies
};

struct BackStepMark {
  double time = 0;               // s: the world's time at the trial sub-step's start
  double h = 0;                  // s: the trial sub-step's length
  double found = 0;              // s into the sub-step: the first contact found
  int iterations = 0;            // trial times the search evaluated (ImpactSearch::evaluations)
  std::vector<int> bodies;       // the watched pairs' moving bodies, at most kMaxBodies
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // m: mean of the too-deep points at t = h
  std::vector<BackStepTrial> trials;                 // in the order tried; t = h first
  static constexpr std::size_t kMaxBodies = 8;       // a chain of pairs draws its first few
};

class BackStepLog {
 public:
  // At most `cap` marks are held; adding past it drops the oldest (a frame shows the last ones).
  explicit BackStepLog(std::size_t cap = kDefaultCap) : cap_(cap) {}
  static constexpr std::size_t kDefaultCap = 8;

  void add(BackStepMark mark);
  // How many marks were ever added: a point to roll back to.
  std::size_t added() const { return added_; }
  // Forgets the marks added since added() was `to` (auto's refinement retakes a step whose
  // back-steps never happened); those already dropped by the cap stay dropped.
  void rollback(std::size_t to);
  // The marks held, oldest first; the log is left empty (the next frame's start).
  std::vector<BackStepMark> take();
  const std::vector<BackStepMark>& marks() const { return marks_; }

 private:
  std::size_t cap_;
  std::size_t added_ = 0;
  std::vector<BackStepMark> marks_;
};

}  // namespace tumble
