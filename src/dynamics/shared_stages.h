// What every contact model's step shares, owned by the Pipeline: detection and the contacts it
// found, the applied forces, waking sleepers that are touched, the stage profile and the counters.
// A model reads and writes these; everything else it keeps in its own state.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "dynamics/back_step_log.h"
#include "dynamics/body_extent.h"
#include "dynamics/contact_detection.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/integrator.h"
#include "dynamics/settings.h"
#include "dynamics/sleeping.h"
#include "dynamics/world.h"

namespace tumble {

// The stages a step may run, in the order the profile lists them.
enum Stage { Detect, Collide, Forces, Resting, Integrate, BackStep, Correct, Sleep, StageCount };

// Wall time per stage, summed over the steps taken (for -v and benchmarks).
struct StageTime {
  std::string name;
  double seconds = 0;
};

struct PipelineCounters {
  long substeps = 0, back_steps = 0, bisection_evaluations = 0, stuck_substeps = 0;
  long projections = 0;
  long bodies_integrated = 0;    // body advances over dt or a sub-step (trial ones too): static bodies never
  long capped_projections = 0;   // Baraff model: corrections not made, a body's reach for the step spent
  long contact_work_paid = 0;    // sub-steps whose contact forces did positive work, taken back
  long inconsistent_pairs = 0;   // impacts already too deep at the start (projected, not bisected)
  long resolved_for_outrun = 0;  // time stepping: steps solved again, a body sent past its reach (outrun_contacts.h)
  long split_steps = 0;          // time stepping: steps taken again as two halves (step_split.h)
  ContactSolveStats contacts;
  std::vector<double> impact_times;   // s: the first 1000 times at which impulses were applied
  std::string model_choice;           // what the automatic model chose and why (empty otherwise)
  std::string target_refinement;      // how auto refined its steps to a penetration target (empty otherwise)
};

// An impact a model resolved, kept for overlays (frame_record.h) while SharedStages::impact_log
// is set: the net impulse the impact gave one body of the pair (B, or A when B is static), at the
// mean of the pair's colliding points. Logging reads the state and never changes it.
struct ImpactMark {
  double time = 0;                                     // s, when the impulse was applied
  int a = -1, b = -1;                                  // the pair, as in Contact
  int on = -1;                                         // the body `impulse` acted on
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     // m, world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // unit, from A to B
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();   // N s on `on`, world
};

struct SharedStages {
  explicit SharedStages(const World& world);

  template <typename F> void timed(Stage stage, F&& work) {
    auto start = std::chrono::steady_clock::now();
    work();
    profile[stage].seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // Wakes sleeping islands that `contacts` shows touched by awake bodies, and calls `detect` (the
  // model's detection into `contacts`) again until none is: a solve never meets a sleeper.
  template <typename F> void wakeTouched(World& world, F&& detect) {
    if (sleep.counters().asleep_now == 0) return;
    bool woke = false;
    timed(Sleep, [&] { woke = sleep.wakeTouched(world, contacts, detector); });
    while (woke) {
      timed(Detect, detect);   // the woken bodies can move now
      timed(Sleep, [&] { woke = sleep.wakeTouched(world, contacts, detector); });
    }
  }

  // "12 moving bodies", and the integrate stage's line, for `tumble check`.
  std::string movingBodies() const;
  std::string integrateLine(const StepSettings& settings) const;

  const bool apply_gravity;     // the world has gravity: a force stage runs
  const int moving, fixed;      // bodies that move; static ones, never integrated
  ContactDetector detector;
  const bool has_contacts;      // something can touch: the contact stages run
  const double min_thickness;   // m: the thinnest piece of any body
  std::vector<BodyExtent> extents;   // each body's radius and thinnest piece
  std::vector<double> body_radius;   // m: each body's farthest vertex from its centre of mass
  // Each body's largest speed (m/s) and spin (rad/s) a model integrated it with within the step,
  // sub-steps included, for the fault check's bound on motion (motion_check.h): the Baraff model
  // may move a body faster between two of a step's impacts than at either end of the step. Reset by
  // the pipeline before each step; a model without sub-steps leaves them at zero.
  std::vector<double> peak_speed, peak_spin;
  // Raises peak_speed and peak_spin to the speeds each moving body has now.
  void notePeakSpeeds(const World& world);
  SleepKeeper sleep;

  std::vector<Contact> contacts;     // the world's contacts now (for overlays and the fault check)
  std::vector<PiecePair> pairs;      // the piece pair of each contact
  bool contacts_fresh = false;       // `contacts` hold the present state: no detection needed
  std::vector<Wrench> wrenches;      // applied forces of the (sub-)step, per body
  std::vector<ImpactMark>* impact_log = nullptr;   // set: impacts are appended (overlays only)
  BackStepLog* back_step_log = nullptr;            // set: back-steps' brackets are kept (overlays only)

  std::vector<StageTime> profile;
  PipelineCounters counters;
};

}  // namespace tumble
