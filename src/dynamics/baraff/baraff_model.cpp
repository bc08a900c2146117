#include "dynamics/baraff/baraff_model.h"

#include <algorithm>
#include <limits>

#include "dynamics/baraff/collisions.h"
#include "dynamics/baraff/drift_correction.h"
#include "dynamics/baraff/impact_log.h"
#include "dynamics/contact_rows.h"
#include "dynamics/gravity.h"
#include "dynamics/joints/joint_projection.h"
#include "dynamics/joints/joint_summary.h"

namespace tumble {

void BaraffModel::start(const World& world, const StepSettings& /*settings*/, SharedStages& /*shared*/) {
  if (!world.joints.empty())
    joints_line_ = "joints      " + describeJoints(world) +
                   ": constraint forces at every integrator stage, their rows in the resting islands' solve, "
                   "impacts solved with the joints holding, drift projected (positions, then velocities)";
}

void BaraffModel::step(World& world, const StepSettings& settings, SharedStages& shared) {
  last_dt_ = settings.dt;
  const double start_time = world.time;
  const double done = tuning::kStepRemainder * settings.dt;
  double remaining = settings.dt;
  if (shared.has_contacts) correction_.startStep(world);
  for (int i = 0; i < tuning::kMaxSubsteps && remaining > done; ++i) {
    world.time = start_time + (settings.dt - remaining);
    remaining -= substep(world, settings, shared, remaining);
  }
  if (remaining > done) ++shared.counters.stuck_substeps;
  world.time = start_time + settings.dt;
}

double BaraffModel::substep(World& world, const StepSettings& settings, SharedStages& shared, double remaining) {
  PipelineCounters& counters = shared.counters;
  ++counters.substeps;
  auto detect = [&] {
    shared.detector.detect(world, settings.contact, shared.contacts, &shared.pairs, nullptr, false, settings.threads);
  };
  if (shared.has_contacts && !shared.contacts_fresh) shared.timed(Detect, detect);
  if (shared.has_contacts) shared.wakeTouched(world, detect);
  if (shared.has_contacts) {
    bool hit = false;
    const BounceThreshold min_bounce = minBounceSpeed(world, settings.contact, settings.dt);   // slower: inelastic
    ImpactLogger impacts;   // overlays only: reads the state around the impulses, writes none
    if (shared.impact_log) impacts.before(world, shared.contacts, settings.contact);
    shared.timed(Collide, [&] {
      const JointsHoldImpulses joints_hold(!world.joints.empty());
      hit = resolveCollisions(world, shared.contacts, settings.contact, min_bounce, settings.dt,
                               counters.contacts);
    });
    if (shared.impact_log && hit) impacts.after(world, *shared.impact_log);
    if (hit && counters.impact_times.size() < 1000) counters.impact_times.push_back(world.time);
    // The impacts were solved with the joints holding (JointsHoldImpulses: a struck pendulum turns
    // about its hinge); what velocity error rounding left along the joints' rows is removed.
    if (hit && !world.joints.empty()) removeJointVelocityError(world);
  }
  shared.timed(Forces, [&] {
    if (shared.apply_gravity) applyGravity(world, shared.wrenches);
    else for (Wrench& w : shared.wrenches) w = Wrench{};
  });
  if (shared.has_contacts)
    shared.timed(Resting, [&] {
      addRestingForces(shared.contacts, {world, settings.contact, settings.dt, &resting_memory_, shared.wrenches,
                                         counters.contacts});
    });

  const double h = shared.has_contacts
                       ? std::min(remaining, tunnelling_.limit(world, shared.wrenches, shared.body_radius,
                                                               shared.min_thickness, shared.detector, remaining))
                       : remaining;
  StepSettings sub = settings;
  sub.dt = h;
  if (shared.has_contacts) {
    start_state_.save(world);
    // Which touching points are lifting off as the sub-step starts (after the impulses): if one
    // ends the sub-step too deep it has come down again, a landing that back-stepping must find.
    lifting_.resize(shared.contacts.size());
    for (std::size_t i = 0; i < shared.contacts.size(); ++i)
      lifting_[i] = normalVelocity(world, shared.contacts[i]) > settings.contact.resting_speed_m_s;
  }
  // Contact forces may not do positive work (contact_work_bound.h); only where nothing drives.
  const bool bound_work = shared.has_contacts && world.joints.empty();
  if (bound_work) work_bound_.before(world, shared.contacts, settings.contact.tolerance_m, shared.extents);
  // The speeds this sub-step moves the bodies at (the fault check's bound on a step's motion).
  shared.notePeakSpeeds(world);
  shared.timed(Integrate, [&] { shared.counters.bodies_integrated += integrate(world, shared.wrenches, sub); });
  if (!shared.has_contacts) {
    correctJoints(world, shared);
    return h;
  }

  shared.timed(Detect, [&] {
    shared.detector.detect(world, settings.contact, contacts_end_, &pairs_end_, nullptr, false, settings.threads);
  });
  double taken = h;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Contact& c : contacts_end_) deepest = std::max(deepest, c.depth);
  if (deepest > settings.contact.tolerance_m)
    shared.timed(BackStep, [&] {
      taken = back_step_.firstContact(world, settings, h, {contacts_end_, pairs_end_, lifting_, start_state_}, shared);
    });
  if (bound_work) counters.contact_work_paid += work_bound_.after(world);
  if (taken == h) {
    std::swap(shared.contacts, contacts_end_);
    std::swap(shared.pairs, pairs_end_);
    shared.contacts_fresh = true;
  } else {
    shared.contacts_fresh = false;
  }
  // Drift correction on the contacts of the state the sub-step ends in: after a back-step the ones
  // in hand are the sub-step's start's, so they are found again first (the next sub-step would
  // find them anyway). Passes repeat while a push moved something, each on the contacts the last
  // left: a block pushed out of the one above it can be pushed into the ground below.
  for (int pass = 0; pass < tuning::kProjectionPasses; ++pass) {
    if (!shared.contacts_fresh) {
      shared.timed(Detect, detect);
      shared.contacts_fresh = true;
    }
    CorrectionCount n;
    shared.timed(Correct, [&] {
      // Pair by pair first; what one pass leaves too deep is an island whose pairs push each
      // other back (a light plate pinched between heavy blocks), projected as a whole.
      if (pass > 0)
        n = correction_.correctIslands(world, shared.contacts, settings.contact.tolerance_m, shared.extents,
                                       settings.contact.max_direct_rows, counters.contacts);
      if (n.moved == 0) n = correction_.correct(world, shared.contacts, settings.contact.tolerance_m, shared.extents);
    });
    counters.projections += n.moved;
    counters.capped_projections += n.capped;
    if (n.moved == 0) break;
    shared.contacts_fresh = false;
  }
  correctJoints(world, shared);
  return taken;
}

// The joints' drift correction at the end of a sub-step (joints/joint_projection.h): positions by
// a mass-weighted projection, then the velocity error along the rows by an impulse that only
// removes energy. A move leaves the contacts in hand stale.
void BaraffModel::correctJoints(World& world, SharedStages& shared) {
  if (world.joints.empty()) return;
  shared.timed(Correct, [&] {
    if (projectJointPositions(world).passes > 0) shared.contacts_fresh = false;
    removeJointVelocityError(world);
  });
}

std::vector<std::string> BaraffModel::describe(const StepSettings& settings, const SharedStages& shared) const {
  std::vector<std::string> lines;
  if (shared.has_contacts) {
    lines.push_back("detect      sweep and prune over piece AABBs, SAT narrow phase, ground half-space");
    lines.push_back("collide     Newton impulses on colliding contacts (LCP on impulses, friction)");
  }
  if (shared.apply_gravity) lines.push_back("forces      gravity on " + shared.movingBodies());
  if (shared.has_contacts) lines.push_back("resting     contact forces: LCP a = A f + b (Dantzig pivoting) + Coulomb friction");
  lines.push_back(shared.integrateLine(settings));
  if (!joints_line_.empty()) lines.push_back(joints_line_);
  if (shared.has_contacts) {
    lines.push_back("back-step   bisection to the first contact when a step ends too deep");
    lines.push_back("correct     position projection of residual penetration");
  } else {
    lines.push_back("contacts    none needed: nothing in this scene can touch");
  }
  return lines;
}

}  // namespace tumble
