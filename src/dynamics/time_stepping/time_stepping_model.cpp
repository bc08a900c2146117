#include "dynamics/time_stepping/time_stepping_model.h"

#include "dynamics/contact_rows.h"
#include "dynamics/gravity.h"
#include "dynamics/joints/joint_impulses.h"
#include "dynamics/joints/joint_projection.h"
#include "dynamics/joints/joint_summary.h"
#include "dynamics/time_stepping/contact_impulses.h"
#include "dynamics/time_stepping/outrun_contacts.h"
#include "dynamics/time_stepping/speculative_contacts.h"

namespace tumble {

void TimeSteppingModel::step(World& world, const StepSettings& settings, SharedStages& shared) {
  if (!shared.has_contacts) {
    stepOnce(world, settings, shared);
    return;
  }
  // A step whose motion its rows could not hold is taken again in halves (step_split.h).
  split_.step(world, settings, shared, [&](const StepSettings& s) { stepOnce(world, s, shared); });
}

void TimeSteppingModel::stepOnce(World& world, const StepSettings& settings, SharedStages& shared) {
  last_dt_ = settings.dt;
  ++shared.counters.substeps;
  const double dt = settings.dt;
  // The contacts the last step ended with, already corrected, unless the state has changed since
  // (bodies put to sleep, a step taken back, a joint's projection, a first step) or this step is of
  // another length.
  if (shared.has_contacts && !(shared.contacts_fresh && end_state_.matches(world) && detected_dt_ == dt))
    detectAndCorrect(world, settings, shared);
  if (shared.has_contacts) step_start_.save(world);
  const BounceThreshold min_bounce = shared.has_contacts ? minBounceSpeed(world, settings.contact, dt) : BounceThreshold{};
  auto solve = [&](const std::vector<Contact>& contacts) {
    // Approach speeds before gravity's impulse: the speed an impact reverses.
    // The projection has turned bodies: their spins are read again.
    bodySpins(world, spin_);
    approach_.resize(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i) approach_[i] = -normalVelocity(world, contacts[i], spin_);
    // Impacts first, then gravity's impulse and the load (contact_impulses.h).
    bool impacts_solved = false;
    if (shared.has_contacts)
      shared.timed(Resting, [&] {
        impulses_.prepare(world, contacts, approach_, settings, min_bounce);
        impacts_solved = impulses_.applyImpacts(world, contacts, settings, shared.counters.contacts);
      });
    shared.timed(Forces, [&] {
      if (shared.apply_gravity) applyGravityImpulse(world, dt);
    });
    if (shared.has_contacts)
      shared.timed(Resting, [&] {
        impulses_.apply(world, contacts, approach_, settings, !impacts_solved, shared.counters.contacts);
      });
  };
  solve(shared.contacts);
  // A body the solve sent farther than the contacts were found for (an impact spinning up a light
  // plate): the step again from its start, with the contacts of its new motion (outrun_contacts.h).
  if (shared.has_contacts && outrunsReach(world, shared.extents, reach_, dt, settings.contact.margin_m)) {
    shared.timed(Detect, [&] {
      outrun_.assign(shared.contacts.begin(), shared.contacts.end());
      outrun_found_.add(world, shared.detector, settings, shared.body_radius, shared.apply_gravity, reach_, outrun_);
    });
    ++shared.counters.resolved_for_outrun;
    step_start_.restore(world);
    solve(outrun_);
  }
  if (shared.has_contacts) impulses_.remember();
  // The joints' impulses: with the contacts', in one problem (contact_impulses.h); alone where
  // nothing can touch (joints/joint_impulses.h).
  if (!world.joints.empty() && !shared.has_contacts) shared.timed(Resting, [&] { applyJointStepImpulses(world, dt); });
  for (Wrench& w : shared.wrenches) w = Wrench{};
  shared.timed(Integrate, [&] { shared.counters.bodies_integrated += integrate(world, shared.wrenches, settings, false); });
  // Post-stabilisation: the state the step ends in, which frames, checks and the next step see,
  // is detected and corrected now (see the header).
  if (shared.has_contacts) {
    detectAndCorrect(world, settings, shared);
    end_state_.save(world);
    detected_dt_ = dt;
    shared.contacts_fresh = true;
  }
  // Free motion with joints still follows them (their forces in the integrator: at every RK4 stage,
  // holding the centripetal pull; joint_integrator.h); what drift is left is projected out,
  // positions only (joint_projection.h).
  // Last, so that a joint ends the step closed; a move leaves the contacts in hand stale.
  if (!world.joints.empty())
    shared.timed(Correct, [&] {
      if (projectJointPositions(world).passes > 0) shared.contacts_fresh = false;
    });
}

void TimeSteppingModel::detectAndCorrect(World& world, const StepSettings& settings, SharedStages& shared) {
  const double dt = settings.dt;
  auto detect = [&] {
    bodySpins(world, spin_);
    bodyReach(world, shared.body_radius, dt, reach_, &spin_);
    shared.detector.detect(world, settings.contact, shared.contacts, &shared.pairs, &reach_,
                           settings.contact.reuse_manifolds, settings.threads);
    keepReachableContacts(world, shared.detector, shared.contacts, shared.pairs, dt, shared.apply_gravity,
                          settings.contact.tolerance_m);
    addSweptContacts(world, shared.detector, shared.contacts, shared.pairs, spin_, dt, shared.apply_gravity,
                     settings.contact.margin_m, settings.contact.tolerance_m, settings.threads);
  };
  shared.timed(Detect, detect);
  shared.wakeTouched(world, detect);
  shared.timed(Correct, [&] {
    shared.counters.projections +=
        projection_.project(world, shared.contacts, settings.contact.tolerance_m, isSpeedSetting(settings));
  });
}

void TimeSteppingModel::start(const World& world, const StepSettings& /*settings*/, SharedStages& shared) {
  split_.start(world, shared.extents);
  if (!world.joints.empty())
    joints_line_ = "joints      " + describeJoints(world) +
                   ": velocity-level impulses in one pivoted problem with the contacts' (equality rows, limits "
                   "that may close within the step, velocity motors bounded by torque x dt), forces at every "
                   "integrator stage, position drift projected";
}

std::vector<std::string> TimeSteppingModel::describe(const StepSettings& settings, const SharedStages& shared) const {
  std::vector<std::string> lines;
  if (shared.apply_gravity) lines.push_back("forces      gravity impulse on " + shared.movingBodies());
  if (shared.has_contacts)
    lines.push_back(std::string("resting     time stepping: velocity-level impulses (restitution, friction pyramid), ") +
                    (isSpeedSetting(settings) || !joints_line_.empty()
                         ? ""
                         : "a step's impacts solved first, before gravity's impulse and the load; ") +
                    "warm-started Gauss-Seidel, at most " + std::to_string(settings.time_stepping_sweeps) +
                    " sweeps; " + (settings.contact.max_direct_rows == 0 ? "every island by Gauss-Seidel alone"
                                   : isSpeedSetting(settings)
                                       ? "small islands of bodies " + std::to_string(static_cast<int>(kSweepsMassRatio)) +
                                             ":1 or more apart in mass it leaves unconverged pivoted exactly"
                                       : "small islands it leaves unconverged pivoted exactly"));
  if (!joints_line_.empty()) lines.push_back(joints_line_);
  lines.push_back(shared.integrateLine(settings) + " (free motion with the new momenta)");
  if (shared.has_contacts) {
    lines.push_back("detect      sweep and prune over piece AABBs, SAT narrow phase, ground half-space, "
                    "within a speculative margin (how far bodies can close in a step); at the end of "
                    "each step, for the state it ends in and the next step");
    lines.push_back(isSpeedSetting(settings)
                        ? "correct     position projection of penetration deeper than " +
                              std::to_string(static_cast<int>(tuning::kProjectionDeepFactor)) +
                              " times the contact tolerance (a speed setting), at the end of each step"
                        : "correct     position projection of residual penetration, at the end of each step");
    lines.push_back("split       a step that moved a body farther than its speeds explain (by a quarter of its "
                    "thinnest piece) taken again as two halves, down to 1/" +
                    std::to_string(1 << kMaxSplitDepth) + " of the step");
  }
  if (!shared.has_contacts) lines.push_back("contacts    none needed: nothing in this scene can touch");
  return lines;
}

}  // namespace tumble
