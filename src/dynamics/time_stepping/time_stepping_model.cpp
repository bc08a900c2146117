#include "dynamics/time_stepping/time_stepping_model.h"

#include <algorithm>

#include "dynamics/contact_rows.h"
#include "dynamics/gravity.h"
#include "dynamics/time_stepping/speculative_contacts.h"

namespace tumble {

void bodyReach(const World& world, const std::vector<double>& body_radius, double dt, std::vector<double>& reach) {
  reach.assign(world.bodies.size(), 0.0);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.is_static) continue;
    reach[i] = (b.velocity().norm() + world.gravity.norm() * dt + b.angularVelocity().norm() * body_radius[i]) * dt;
  }
}

long TimeSteppingModel::contactsOfSolvedMotion(const World& world, const StepSettings& settings, SharedStages& shared) {
  const double dt = settings.dt;
  long added = 0;
  // Pairs farther apart than the detection reached: only where the solve made a body faster.
  bodyReach(world, shared.body_radius, dt, solved_reach_);
  bool farther = false;
  for (std::size_t i = 0; i < solved_reach_.size(); ++i) farther = farther || solved_reach_[i] > reach_[i];
  if (farther) {
    shared.detector.detect(world, settings.contact, solved_contacts_, &solved_pairs_, &solved_reach_);
    keepReachableContacts(world, shared.detector, solved_contacts_, solved_pairs_, dt, false,
                          settings.contact.tolerance_m);
    known_pairs_ = shared.pairs;
    std::sort(known_pairs_.begin(), known_pairs_.end());
    for (std::size_t i = 0; i < solved_contacts_.size(); ++i) {
      if (std::binary_search(known_pairs_.begin(), known_pairs_.end(), solved_pairs_[i])) continue;
      shared.contacts.push_back(solved_contacts_[i]);
      shared.pairs.push_back(solved_pairs_[i]);
      ++added;
    }
  }
  // Gravity's impulse is in the solved velocities already.
  return added + addSweptContacts(world, shared.detector, shared.contacts, shared.pairs, dt, false,
                                  settings.contact.margin_m, settings.contact.tolerance_m);
}

void TimeSteppingModel::step(World& world, const StepSettings& settings, SharedStages& shared) {
  ++shared.counters.substeps;
  const double dt = settings.dt;
  if (shared.has_contacts) {
    auto detect = [&] {
      bodyReach(world, shared.body_radius, dt, reach_);
      shared.detector.detect(world, settings.contact, shared.contacts, &shared.pairs, &reach_);
      keepReachableContacts(world, shared.detector, shared.contacts, shared.pairs, dt, shared.apply_gravity,
                            settings.contact.tolerance_m);
      addSweptContacts(world, shared.detector, shared.contacts, shared.pairs, dt, shared.apply_gravity,
                       settings.contact.margin_m, settings.contact.tolerance_m);
    };
    shared.timed(Detect, detect);
    shared.wakeTouched(world, detect);
    shared.timed(Correct, [&] {
      shared.counters.projections += projection_.project(world, shared.contacts, settings.contact.tolerance_m);
    });
  }
  // Approach speeds before gravity's impulse: the speed an impact reverses.
  approach_.resize(shared.contacts.size());
  for (std::size_t i = 0; i < shared.contacts.size(); ++i) approach_[i] = -normalVelocity(world, shared.contacts[i]);
  shared.timed(Forces, [&] {
    if (shared.apply_gravity) applyGravityImpulse(world, dt);
  });
  if (shared.has_contacts) {
    const double min_bounce = minBounceSpeed(world, settings.contact, dt);
    shared.timed(Resting, [&] {
      before_solve_.save(world);
      impulses_.apply(world, shared.contacts, approach_, settings, min_bounce, shared.counters.contacts);
      // The speculative contacts above follow the motion the bodies had before the solve; the
      // solve can set still bodies moving and spinning (a brick struck by a ball: 60 m/s and 160
      // rad/s within the step), into neighbours the detection did not reach, and a pair held at
      // the one point its manifold had turns another corner into its neighbour, as deep as the
      // turn sweeps (2.4 cm in scenes/hard/debris_wall.json). So the solved motion is detected
      // and swept again; what it finds becomes rows of its own and the step is solved again from
      // the momenta it started with (warm-started from the answer before), until nothing new is
      // found.
      for (int round = 0; round < tuning::kSweptResolves; ++round) {
        if (contactsOfSolvedMotion(world, settings, shared) == 0) break;
        approach_.resize(shared.contacts.size(), 0.0);   // apart at the start: no bounce to give
        before_solve_.restore(world);   // positions are as they were: only momenta changed
        impulses_.apply(world, shared.contacts, approach_, settings, min_bounce, shared.counters.contacts);
      }
    });
  }
  for (Wrench& w : shared.wrenches) w = Wrench{};
  shared.timed(Integrate, [&] { integrate(world, shared.wrenches, settings); });
}

std::vector<std::string> TimeSteppingModel::describe(const StepSettings& settings, const SharedStages& shared) const {
  std::vector<std::string> lines;
  if (shared.has_contacts) {
    lines.push_back("detect      sweep and prune over piece AABBs, SAT narrow phase, ground half-space, "
                    "within a speculative margin (how far bodies can close in a step)");
    lines.push_back("correct     position projection of residual penetration");
  }
  if (shared.apply_gravity) lines.push_back("forces      gravity impulse on " + shared.movingBodies());
  if (shared.has_contacts)
    lines.push_back("resting     time stepping: velocity-level impulses (restitution, friction pyramid), "
                    "warm-started Gauss-Seidel; small islands it leaves unconverged pivoted exactly");
  lines.push_back(shared.integrateLine(settings) + " (free motion with the new momenta)");
  if (!shared.has_contacts) lines.push_back("contacts    none needed: nothing in this scene can touch");
  return lines;
}

}  // namespace tumble
