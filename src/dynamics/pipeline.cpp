#include "dynamics/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "dynamics/contact_islands.h"
#include "dynamics/gravity.h"
#include "dynamics/time_of_impact.h"

namespace tumble {
namespace {

const char* kStageNames[] = {"detect", "collide", "forces", "resting", "integrate", "back-step", "correct"};

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
      wrenches_(world.bodies.size()) {
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
}

double Pipeline::substep(World& world, const StepSettings& settings, double remaining) {
  ++counters_.substeps;
  if (has_contacts_ && !contacts_fresh_)
    timed(Detect, [&] { detector_.detect(world, settings.contact, contacts_now_, &pairs_now_); });
  if (has_contacts_) {
    bool hit = false;
    // A bounce slower than what gravity takes away in about two steps cannot leave the surface
    // for a whole step: resolved elastically it would come back every step (v -> e v - g dt has
    // the fixed point g dt / (1 - e)) and never come to rest. Such impacts are made inelastic.
    double min_bounce = std::max(settings.contact.resting_speed_m_s, 2 * world.gravity.norm() * settings.dt);
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
    timed(Resting, [&] { addRestingForces(world, contacts_now_, settings.contact, wrenches_, counters_.contacts, settings.dt); });

  double h = has_contacts_ ? std::min(remaining, tunnellingBound(world, remaining)) : remaining;
  StepSettings sub = settings;
  sub.dt = h;
  if (has_contacts_) snapshot_.save(world);
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
  // A pair is an impact to go back for when it ends deeper than the tolerance and was not touching
  // at the start. A pair that was already touching (resting, or landing its other corners as it
  // turns) is left to the impulse and position stages of the next sub-step: its depth is already
  // within the tolerance at the start, so bisection on it would find no better time and would cut
  // the step to nothing. This keeps back-stepping to the first contact of each pair.
  std::vector<PiecePair> offending;
  double deepest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < contacts_end_.size(); ++i) {
    if (contacts_end_[i].depth <= tol) continue;
    double before = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < contacts_now_.size(); ++j)
      if (pairs_now_[j] == pairs_end_[i]) before = std::max(before, contacts_now_[j].depth);
    if (before >= -tol) continue;
    if (offending.empty() || !(offending.back() == pairs_end_[i])) offending.push_back(pairs_end_[i]);
    deepest = std::max(deepest, contacts_end_[i].depth);
  }
  if (offending.empty()) return h;
  // The bracket needs every pair within the tolerance at the start. The manifold (which said the
  // pair was apart) and the separation bisection measures can disagree on a pair the narrow phase
  // missed at the start; such a pair is not a first contact to find but a penetration to project,
  // and bisecting on it would return t = 0 and stall the step. It is dropped and counted.
  snapshot_.restore(world);
  std::vector<PiecePair> watched;
  for (const PiecePair& pair : offending)
    if (detector_.maxDepth(world, {pair}) <= tol) watched.push_back(pair);
    else ++counters_.inconsistent_pairs;
  StepSettings sub = settings;
  auto depth_at = [&](double t) {
    snapshot_.restore(world);
    sub.dt = t;
    integrate(world, wrenches_, sub);
    return detector_.maxDepth(world, watched);
  };
  if (watched.empty()) {
    depth_at(h);
    return h;
  }
  deepest = depth_at(h);
  ++counters_.bisection_evaluations;
  if (deepest <= tol) return h;   // only the manifold saw it too deep: nothing to go back for
  ImpactSearch found = findFirstContact(depth_at, h, deepest, tol, settings.contact.max_bisections,
                                        settings.contact.regula_falsi);
  counters_.bisection_evaluations += found.evaluations;
  depth_at(found.time);
  return found.time;
}

// Drift: residual penetration deeper than the tolerance is removed by moving the two bodies apart
// along the normal, in inverse proportion to their masses. Only positions move, never velocities,
// so no kinetic energy is added (unlike a Baumgarte term, which pushes bodies apart with speed).
void Pipeline::correctPenetration(World& world, const StepSettings& settings) {
  // Once per pair of bodies, by its deepest point: the four corners of a face resting too deep
  // share one depth, and pushing once per corner would open a gap of three depths, leaving the
  // face unsupported (no resting force across a gap) for the next sub-step.
  const double tol = settings.contact.tolerance_m;
  const BodyPairGroups grouped = groupByBodyPair(contacts_now_);
  struct Push {
    std::size_t first_seen, deepest;
  };
  std::vector<Push> pushes;
  for (const auto& [begin, end] : grouped.groups) {
    Push p{SIZE_MAX, SIZE_MAX};
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = grouped.order[k];
      if (contacts_now_[i].depth <= tol) continue;
      p.first_seen = std::min(p.first_seen, i);
      if (p.deepest == SIZE_MAX || contacts_now_[i].depth > contacts_now_[p.deepest].depth) p.deepest = i;
    }
    if (p.deepest != SIZE_MAX) pushes.push_back(p);
  }
  // Pairs are pushed in the order their first too-deep point was detected (deterministic, and the
  // order the pushes had before they were grouped).
  std::sort(pushes.begin(), pushes.end(), [](const Push& x, const Push& y) { return x.first_seen < y.first_seen; });
  for (const Push& p : pushes) {
    const Contact& c = contacts_now_[p.deepest];
    RigidBody& A = world.bodies[c.a];
    RigidBody& B = world.bodies[c.b];
    double wa = A.inv_mass, wb = B.inv_mass;
    if (wa + wb <= 0) continue;
    double push = c.depth - 0.5 * tol;
    A.x -= c.normal * (push * wa / (wa + wb));
    B.x += c.normal * (push * wb / (wa + wb));
    ++counters_.projections;
    contacts_fresh_ = false;
  }
}

std::vector<std::string> Pipeline::describe() const {
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
