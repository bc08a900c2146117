// The simulation step, written down in one place: a list of named stages, each in a file of its
// own, each timed. The pipeline holds only the stages the scene needs ("model only what a scene
// needs"): without gravity there is no force stage, without anything that can touch there is no
// contact stage, static bodies are never integrated.
//
//   detect     broad phase + narrow phase          contact_detection.cpp (collision/)
//   collide    classify; impulses (Newton)         contact_solver.cpp
//   forces     gravity                             gravity.cpp
//   resting    contact forces, LCP + friction      contact_solver.cpp (lcp/)
//   integrate  (x, q, P, L) over the sub-step      integrator.cpp
//   back-step  bisection to the first contact      time_of_impact.cpp
//   correct    project out residual penetration    pipeline.cpp (correctPenetration)
//   sleep      freeze islands at rest; wake on touch  sleeping.cpp
//
// With the time-stepping contact model (time_stepping.h, pipeline_time_stepping.cpp) a step is
// instead: detect (within a speculative margin), correct, forces, resting (the velocity-level
// impulse problem), integrate — never cut.
//
// A step of dt may be cut into sub-steps: at each first contact found by back-stepping, and where
// a body could pass through a piece it may meet within the sub-step (the tunnelling bound).
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "dynamics/body_snapshot.h"
#include "dynamics/contact_detection.h"
#include "dynamics/contact_solver.h"
#include "dynamics/integrator.h"
#include "dynamics/sleeping.h"
#include "dynamics/step_settings.h"
#include "dynamics/time_stepping.h"
#include "dynamics/world.h"

namespace tumble {

// Wall time per stage, summed over the steps taken (for -v and benchmarks).
struct StageTime {
  std::string name;
  double seconds = 0;
};

struct PipelineCounters {
  long substeps = 0, back_steps = 0, bisection_evaluations = 0, stuck_substeps = 0;
  long projections = 0;
  long inconsistent_pairs = 0;   // impacts already too deep at the start (projected, not bisected)
  ContactSolveStats contacts;
  std::vector<double> impact_times;   // s: the first 1000 times at which impulses were applied
};

class Pipeline {
 public:
  Pipeline(const World& world, const StepSettings& settings);
  void step(World& world, const StepSettings& settings);

  // One line per stage: what it does in this scene (for `tumble check`).
  std::vector<std::string> describe(const StepSettings& settings) const;
  const std::vector<StageTime>& profile() const { return profile_; }
  const PipelineCounters& counters() const { return counters_; }
  // The contacts found at the end of the last step (for overlays and tests).
  const std::vector<Contact>& contacts() const { return contacts_now_; }
  const SleepCounters& sleepCounters() const { return sleep_.counters(); }

 private:
  struct Watch {                // back-stepping: a pair to time
    PiecePair pair;
    bool landing = false;        // touching at the start: timed by its points away from `resting`
    double near = 0;             // m: how close to a resting point a point is that point
    std::vector<Eigen::Vector3d> resting;
  };
  enum Stage { Detect, Collide, Forces, Resting, Integrate, BackStep, Correct, Sleep, StageCount };
  double substep(World& world, const StepSettings& settings, double remaining);
  void timeStep(World& world, const StepSettings& settings);
  double tunnellingBound(const World& world, double h);
  double backStep(World& world, const StepSettings& settings, double h);
  double landingRadius(const Contact& c) const;
  static double minBounce(const World& world, const StepSettings& settings);
  double watchedDepth(const World& world, const Watch& w, const StepSettings& settings);
  void correctPenetration(World& world, const StepSettings& settings);
  std::vector<std::string> describeStages() const;
  // The world's contacts now into contacts_now_ / pairs_now_: within each body's reach for the
  // time-stepping model (its speculative margin), within the margin for the Baraff model.
  void detectNow(World& world, const StepSettings& settings);
  // Wakes sleeping islands that `contacts_now_` shows touched by awake bodies, and detects again
  // (with each body's reach for the time-stepping model) until none is: a solve never meets a
  // sleeper.
  void wakeTouched(World& world, const StepSettings& settings);
  void settleAtRest(World& world, const StepSettings& settings);
  void projectContacts(World& world, const StepSettings& settings);   // time stepping
  static constexpr int kProjectionPasses = 8;
  template <typename F> void timed(Stage stage, F&& work) {
    auto start = std::chrono::steady_clock::now();
    work();
    profile_[stage].seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  bool apply_gravity_ = false;
  bool has_contacts_ = false;
  int moving_ = 0, static_ = 0;
  Integrator integrator_ = Integrator::Rk4;
  ContactModel model_ = ContactModel::Baraff;
  TimeStepper stepper_;
  double dt_ = 0;
  ContactDetector detector_;
  std::vector<Contact> contacts_now_, contacts_end_;
  std::vector<PiecePair> pairs_now_, pairs_end_;
  bool contacts_fresh_ = false;
  std::vector<char> lifting_;   // per contact of contacts_now_: separating as the sub-step starts
  std::vector<Watch> watched_;
  std::vector<Contact> landing_points_;
  std::vector<Wrench> wrenches_;
  RestingMemory resting_memory_;   // warm start of resting islands too large to pivot
  SleepKeeper sleep_;
  BodySnapshot snapshot_;
  double min_thickness_ = 0;
  std::vector<double> body_radius_;
  std::vector<double> reach_;   // how far each body can travel in the (sub-)step
  std::vector<double> speed_;   // tunnelling bound: each body's point-speed bound
  std::vector<ContactDetector::NearPair> near_;
  std::vector<Eigen::Vector3d> moved_;   // time stepping: each body's displacement by projection
  std::vector<StageTime> profile_;
  PipelineCounters counters_;
};

}  // namespace tumble
