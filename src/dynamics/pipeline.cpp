#include "dynamics/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "dynamics/contact_islands.h"
#include "dynamics/contact_lcp.h"
#include "dynamics/gravity.h"
#include "dynamics/position_projection.h"
#include "dynamics/time_of_impact.h"

namespace tumble {
namespace {

const char* kStageNames[] = {"detect", "collide", "forces", "resting", "integrate", "back-step", "correct", "sleep"};

int movingBodies(const World& world) {
  int n = 0;
  for (const RigidBody& b : world.bodies) n += b.is_static ? 0 : 1;
  return n;
}

}  // namespace

Pipeline::Pipeline(const World& world, const StepSettings& settings)
    : apply_gravity_(world.gravity.squaredNorm() > 0),
      moving_(movingBodies(world)),
      static_(static_cast<int>(world.bodies.size()) - moving_),
      integrator_(settings.integrator),
      model_(settings.model),
      dt_(settings.dt),
      detector_(world),
      wrenches_(world.bodies.size()),
      sleep_(world) {
  has_contacts_ = detector_.hasCollidablePairs();
  min_thickness_ = detector_.thinnestPiece();
  for (const RigidBody& body : world.bodies) {
    double radius = 0;
    for (const ConvexPiece& piece : body.pieces) {
      for (const Eigen::Vector3d& v : piece.vertices) radius = std::max(radius, v.norm());
    }
    body_radius_.push_back(radius);
  }
  for (const char* name : kStageNames) profile_.push_back({name});
}

void Pipeline::step(World& world, const StepSettings& settings) {
  if (settings.model == ContactModel::TimeStepping) {
    timeStep(world, settings);
    settleAtRest(world, settings);
    return;
  }
  double start_time = world.time;
  double remaining = settings.dt;
  // Sub-steps end at first contacts; a few per step is normal. The cap only stops a pathological
  // case (a contact that back-stepping cannot resolve) from hanging the run; it is counted.
  for (int i = 0; i < 256 && remaining > 1e-12 * settings.dt; ++i) {
    world.time = start_time + (settings.dt - remaining);
    remaining -= substep(world, settings, remaining);
  }
  if (remaining > 1e-12 * settings.dt) ++counters_.stuck_substeps;
  world.time = start_time + settings.dt;
  settleAtRest(world, settings);
}

void Pipeline::detectNow(World& world, const StepSettings& settings) {
  if (settings.model == ContactModel::TimeStepping) {
    bodyReach(world, body_radius_, settings.dt, reach_);
    detector_.detect(world, settings.contact, contacts_now_, &pairs_now_, &reach_);
  } else {
    detector_.detect(world, settings.contact, contacts_now_, &pairs_now_);
  }
}

void Pipeline::wakeTouched(World& world, const StepSettings& settings) {
  if (sleep_.counters().asleep_now == 0) return;
  bool woke = false;
  timed(Sleep, [&] { woke = sleep_.wakeTouched(world, contacts_now_, detector_); });
  while (woke) {
    timed(Detect, [&] { detectNow(world, settings); });   // the woken bodies can move now
    timed(Sleep, [&] { woke = sleep_.wakeTouched(world, contacts_now_, detector_); });
  }
}

// After a whole step, so that a body is judged by the velocity the step leaves it with.
void Pipeline::settleAtRest(World& world, const StepSettings& settings) {
  if (!has_contacts_ || !settings.sleep.enabled) return;
  bool slept = false;
  timed(Sleep, [&] { slept = sleep_.settle(world, contacts_now_, settings.sleep, settings.dt, detector_); });
  // The sleepers' contacts with each other and the ground are gone from the next detection.
  if (slept) contacts_fresh_ = false;
}

double Pipeline::substep(World& world, const StepSettings& settings, double remaining) {
  ++counters_.substeps;
  if (has_contacts_ && !contacts_fresh_) timed(Detect, [&] { detectNow(world, settings); });
  if (has_contacts_) wakeTouched(world, settings);
  if (has_contacts_) {
    bool hit = false;
    const double min_bounce = minBounce(world, settings);   // slower impacts are inelastic
    timed(Collide, [&] {
      hit = resolveCollisions(world, contacts_now_, settings.contact, min_bounce, counters_.contacts);
    });
    if (hit && counters_.impact_times.size() < 1000) counters_.impact_times.push_back(world.time);
  }
  timed(Forces, [&] {
    if (apply_gravity_) applyGravity(world, wrenches_);
    else for (Wrench& w : wrenches_) w = Wrench{};
  });
  if (has_contacts_)
    timed(Resting, [&] { addRestingForces(world, contacts_now_, settings.contact, wrenches_, counters_.contacts, settings.dt, &resting_memory_); });

  double h = has_contacts_ ? std::min(remaining, tunnellingBound(world, remaining)) : remaining;
  StepSettings sub = settings;
  sub.dt = h;
  if (has_contacts_) {
    snapshot_.save(world);
    // Which touching points are lifting off as the sub-step starts (after the impulses): if one
    // ends the sub-step too deep it has come down again, a landing that back-stepping must find.
    lifting_.resize(contacts_now_.size());
    for (std::size_t i = 0; i < contacts_now_.size(); ++i)
      lifting_[i] = normalVelocity(world, contacts_now_[i]) > settings.contact.resting_speed_m_s;
  }
  timed(Integrate, [&] { integrate(world, wrenches_, sub); });
  if (!has_contacts_) return h;

  timed(Detect, [&] { detector_.detect(world, settings.contact, contacts_end_, &pairs_end_); });
  double taken = h;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Contact& c : contacts_end_) deepest = std::max(deepest, c.depth);
  if (deepest > settings.contact.tolerance_m) timed(BackStep, [&] { taken = backStep(world, settings, h); });
  if (taken == h) {
    std::swap(contacts_now_, contacts_end_);
    std::swap(pairs_now_, pairs_end_);
    contacts_fresh_ = true;
  } else {
    contacts_fresh_ = false;
  }
  timed(Correct, [&] { correctPenetration(world, settings); });
  return taken;
}

// Bounds every body's motion within a sub-step so that no pair can pass through each other
// unseen (conservative advancement, seed 000). Per pair of pieces that can meet within the
// sub-step: they are now at least `gap` apart along an axis n, and the gap along a fixed axis
// closes no faster than
//   c = n . (v_a - v_b) + |w_a| r_a + |w_b| r_b + (|a_a| + |a_b|) h
// so within (gap + t/2) / c seconds they cannot overlap by more than half the thinner piece's
// width t along n, hence by no more than that at all, and cannot pass through each other without
// ending the sub-step overlapping, which back-stepping then resolves. A shot far from everything
// is not cut; one approaching a thin wall is cut once, at the wall; one sliding along a wall at
// speed is not cut by its speed along the wall.
double Pipeline::tunnellingBound(const World& world, double h) {
  double fastest = 0;
  speed_.assign(world.bodies.size(), 0.0);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.is_static) continue;
    // |v| + |a| h + |w| r bounds the body's point speeds over the sub-step
    speed_[i] = b.velocity().norm() + wrenches_[i].force.norm() * b.inv_mass * h +
                b.angularVelocity().norm() * body_radius_[i];
    fastest = std::max(fastest, speed_[i]);
  }
  // Nothing can cross even the thinnest piece: no pair needs looking at.
  if (fastest <= 0 || !std::isfinite(min_thickness_) || min_thickness_ >= 4 * fastest * h) return h;
  reach_.resize(world.bodies.size());
  for (std::size_t i = 0; i < world.bodies.size(); ++i) reach_[i] = speed_[i] * h;
  detector_.nearPairs(world, reach_, near_);
  auto approach = [&](int body, const Eigen::Vector3d& n) {
    const RigidBody& b = world.bodies[body];
    if (b.is_static) return 0.0;
    return n.dot(b.velocity()) + wrenches_[body].force.norm() * b.inv_mass * h +
           b.angularVelocity().norm() * body_radius_[body];
  };
  double bound = h;
  for (const ContactDetector::NearPair& p : near_) {
    const bool has_axis = p.axis.squaredNorm() > 0.5;
    const double closing = has_axis ? approach(p.body_a, p.axis) + approach(p.body_b, -p.axis)
                                    : speed_[p.body_a] + speed_[p.body_b];
    if (closing > 0) bound = std::min(bound, (p.gap + 0.5 * p.thickness) / closing);
  }
  return std::max(bound, 1e-9 * h);
}

// The trial sub-step of length h ended with pairs deeper than the tolerance: go back and find the
// first time they touch (seed 000). Only the pairs that became too deep are watched; the world is
// re-integrated from the saved state for each trial time.
double Pipeline::backStep(World& world, const StepSettings& settings, double h) {
  ++counters_.back_steps;
  const double tol = settings.contact.tolerance_m;
  // A pair is an impact to go back for when it ends deeper than the tolerance and either was not
  // touching at the start (a first contact), or was touching but its too-deep point is a landing:
  // a corner or edge away from where the pair touched (a box rocking back onto its face lands one
  // edge while the other rests), or a touching point that was lifting off and came down again
  // within the sub-step. Left to the next sub-step's impulse, a landing is resolved a sub-step
  // late, after gravity has sped it up for that long: the box rocked on its face for ever. A pair
  // whose too-deep point was touching and not lifting (resting, or sinking by drift) is left to the
  // impulse and position stages: bisection on it would find no better time.
  //
  // A first contact is timed by the pair's separation; a landing by the depth of the pair's
  // contact points away from its resting ones, so that the resting points' drift does not time it.
  std::vector<Watch> offending;
  for (std::size_t i = 0; i < contacts_end_.size(); ++i) {
    const Contact& end = contacts_end_[i];
    if (end.depth <= tol) continue;
    double before = -std::numeric_limits<double>::infinity();
    bool touched_here = false;
    const double near = landingRadius(end);
    for (std::size_t j = 0; j < contacts_now_.size(); ++j) {
      if (!(pairs_now_[j] == pairs_end_[i])) continue;
      const Contact& start = contacts_now_[j];
      before = std::max(before, start.depth);
      touched_here |= start.depth >= -tol && !lifting_[j] && (start.point - end.point).squaredNorm() <= near * near;
    }
    // A landing slower than settleSpeed is not timed: the next sub-step's impulse settles it
    // whenever it came (impulse_propagation.cpp), and timing every slow corner that settles in a
    // pile cut its steps into about a hundred sub-steps.
    if (before >= -tol && (touched_here || -normalVelocity(world, end) <= settleSpeed(settings.contact))) continue;
    if (!offending.empty() && offending.back().pair == pairs_end_[i]) continue;
    Watch w{pairs_end_[i], before >= -tol, near, {}};
    if (w.landing)
      for (std::size_t j = 0; j < contacts_now_.size(); ++j)
        if (pairs_now_[j] == w.pair && contacts_now_[j].depth >= -tol && !lifting_[j])
          w.resting.push_back(contacts_now_[j].point);
    offending.push_back(std::move(w));
  }
  if (offending.empty()) return h;
  // The bracket needs every pair within the tolerance at the start. The manifold (which said the
  // pair was apart) and the separation bisection measures can disagree on a pair the narrow phase
  // missed at the start; such a pair is not a first contact to find but a penetration to project,
  // and bisecting on it would return t = 0 and stall the step. It is dropped and counted.
  snapshot_.restore(world);
  watched_.clear();
  for (Watch& w : offending)
    if (watchedDepth(world, w, settings) <= tol) watched_.push_back(std::move(w));
    else ++counters_.inconsistent_pairs;
  StepSettings sub = settings;
  auto depth_at = [&](double t) {
    snapshot_.restore(world);
    sub.dt = t;
    integrate(world, wrenches_, sub);
    double worst = -std::numeric_limits<double>::infinity();
    for (const Watch& w : watched_) worst = std::max(worst, watchedDepth(world, w, settings));
    return worst;
  };
  if (watched_.empty()) {
    depth_at(h);
    return h;
  }
  const double deepest = depth_at(h);
  ++counters_.bisection_evaluations;
  if (deepest <= tol) return h;   // only the manifold saw it too deep: nothing to go back for
  ImpactSearch found = findFirstContact(depth_at, h, deepest, tol, settings.contact.max_bisections,
                                        settings.contact.regula_falsi);
  counters_.bisection_evaluations += found.evaluations;
  if (found.time < 1e-6 * h) {
    // The landing is there at once: found again at the start after its impulse (a point the
    // impulse could not stop, or whose manifold moved), cutting here would stall the step in
    // sub-steps of nothing. The next sub-step's impulse and the projection take it.
    depth_at(h);
    return h;
  }
  depth_at(found.time);
  return found.time;
}

// The depth back-stepping times a watched pair by: its separation for a first contact; for a
// landing, the deepest of its contact points away from every point it rested on at the start.
double Pipeline::watchedDepth(const World& world, const Watch& w, const StepSettings& settings) {
  if (!w.landing) return detector_.maxDepth(world, {w.pair});
  landing_points_.clear();
  detector_.pairContacts(world, w.pair, settings.contact.margin_m, landing_points_);
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Contact& c : landing_points_) {
    bool resting = false;
    for (const Eigen::Vector3d& p : w.resting) resting |= (p - c.point).squaredNorm() <= w.near * w.near;
    if (!resting) deepest = std::max(deepest, c.depth);
  }
  return deepest;
}

// A bounce slower than what gravity takes away in about two steps cannot leave the surface for a
// whole step: resolved elastically it would come back every step (v -> e v - g dt has the fixed
// point g dt / (1 - e)) and never come to rest. Such impacts are made inelastic.
double Pipeline::minBounce(const World& world, const StepSettings& settings) {
  return std::max(settings.contact.resting_speed_m_s, 2 * world.gravity.norm() * settings.dt);
}

// How far a too-deep point may be from a touching point of the same pair at the sub-step's start
// and still be that point (moved by the sub-step's sliding or turning) rather than a landing: a
// tenth of the smaller body's radius.
double Pipeline::landingRadius(const Contact& c) const {
  double r = std::numeric_limits<double>::infinity();
  for (int body : {c.a, c.b})
    if (body_radius_[body] > 0) r = std::min(r, body_radius_[body]);
  return 0.1 * r;
}

// Drift: residual penetration deeper than the tolerance is removed by moving and turning the two
// bodies of each pair, the smallest displacement (weighted by mass and inertia) that lifts the
// pair's too-deep points back within the tolerance (position_projection.h). Only positions move,
// never velocities, so no kinetic energy is added (unlike a Baumgarte term, which pushes bodies
// apart with speed).
void Pipeline::correctPenetration(World& world, const StepSettings& settings) {
  // Once per pair of bodies, all its points together: the four corners of a face resting too deep
  // share one depth and are lifted together, and a landing edge is lifted by turning about the
  // resting one rather than by lifting both.
  const double tol = settings.contact.tolerance_m;
  const BodyPairGroups grouped = groupByBodyPair(contacts_now_);
  struct Push {
    std::size_t first_seen, group;
  };
  std::vector<Push> pushes;
  for (std::size_t g = 0; g < grouped.groups.size(); ++g) {
    const auto& [begin, end] = grouped.groups[g];
    std::size_t first = SIZE_MAX;
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = grouped.order[k];
      if (contacts_now_[i].depth > tol) first = std::min(first, i);
    }
    if (first != SIZE_MAX) pushes.push_back({first, g});
  }
  // Pairs are projected in the order their first too-deep point was detected (deterministic).
  std::sort(pushes.begin(), pushes.end(), [](const Push& x, const Push& y) { return x.first_seen < y.first_seen; });
  std::vector<const Contact*> points;
  for (const Push& p : pushes) {
    const auto& [begin, end] = grouped.groups[p.group];
    points.clear();
    for (std::size_t k = begin; k < end; ++k) points.push_back(&contacts_now_[grouped.order[k]]);
    if (!projectPair(world, points, tol)) continue;
    ++counters_.projections;
    contacts_fresh_ = false;
  }
}

std::vector<std::string> Pipeline::describe(const StepSettings& settings) const {
  std::vector<std::string> lines = describeStages();
  if (!has_contacts_) return lines;
  char line[200];
  if (settings.sleep.enabled)
    std::snprintf(line, sizeof line,
                  "sleep       islands slower than %g m/s and %g rad/s for %g s, resting on something "
                  "fixed, freeze until touched",
                  settings.sleep.speed_m_s, settings.sleep.spin_rad_s, settings.sleep.after_s);
  else
    std::snprintf(line, sizeof line, "sleep       off: every body is simulated to the end");
  lines.push_back(line);
  return lines;
}

std::vector<std::string> Pipeline::describeStages() const {
  std::vector<std::string> lines;
  std::string moving = std::to_string(moving_) + (moving_ == 1 ? " moving body" : " moving bodies");
  std::string integrate = std::string("integrate   ") +
                          (integrator_ == Integrator::Rk4 ? "RK4" : "semi-implicit Euler") + ", dt = " +
                          std::to_string(dt_) + " s, " + moving + "; " + std::to_string(static_) +
                          " static never integrated";
  if (model_ == ContactModel::TimeStepping) {
    if (has_contacts_) {
      lines.push_back("detect      sweep and prune over piece AABBs, SAT narrow phase, ground half-space, "
                      "within a speculative margin (how far bodies can close in a step)");
      lines.push_back("correct     position projection of residual penetration");
    }
    if (apply_gravity_) lines.push_back("forces      gravity impulse on " + moving);
    if (has_contacts_)
      lines.push_back("resting     time stepping: velocity-level impulses (restitution, friction pyramid), "
                      "warm-started Gauss-Seidel; small islands it leaves unconverged pivoted exactly");
    lines.push_back(integrate + " (free motion with the new momenta)");
    if (!has_contacts_) lines.push_back("contacts    none needed: nothing in this scene can touch");
    return lines;
  }
  if (has_contacts_) {
    lines.push_back("detect      sweep and prune over piece AABBs, SAT narrow phase, ground half-space");
    lines.push_back("collide     Newton impulses on colliding contacts (LCP on impulses, friction)");
  }
  if (apply_gravity_) lines.push_back("forces      gravity on " + moving);
  if (has_contacts_) lines.push_back("resting     contact forces: LCP a = A f + b (Dantzig pivoting) + Coulomb friction");
  lines.push_back(integrate);
  if (has_contacts_) {
    lines.push_back("back-step   bisection to the first contact when a step ends too deep");
    lines.push_back("correct     position projection of residual penetration");
  } else {
    lines.push_back("contacts    none needed: nothing in this scene can touch");
  }
  return lines;
}

}  // namespace tumble
