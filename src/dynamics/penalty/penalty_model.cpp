#include "dynamics/penalty/penalty_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "base/error.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/gravity.h"
#include "dynamics/penalty/contact_stiffness.h"

namespace tumble {
namespace {

// Accuracy of a spring's explicit integration: ω h at most this (about 60 sub-steps per period;
// symplectic Euler's phase error is (ω h)² / 24 per step, a contact's duration good to 1e-3).
constexpr double kSpringStep = 0.1;
// Stability of a damper's (and a regularised friction law's) explicit integration: γ h < 2; half
// of it again keeps a decaying motion from flipping sign each sub-step.
constexpr double kDamperStep = 0.5;
// Accuracy of a damper in an impact: γ h at most this, e within about 1e-3 of the law's.
constexpr double kImpactDamperStep = 0.02;
// A point closer to touching than this share of the stable sub-step (in time) does not cut it.
constexpr double kTouchCut = 0.05;
// A damped Hertz-type law divides by the closing speed its contact began with; a contact that
// began at rest would get an infinite damper. Its closing speed is taken as at least this share
// of its natural speed ω δ (an impact's closing speed is more than ω δ at its deepest, so this
// floor never touches one; at rest it damps the spring more than critically).
constexpr double kRestingClosingShare = 0.1;

// The body's share of 1 / m_eff along `dir` at `point`.
double inverseMassAlong(const RigidBody& b, const Eigen::Vector3d& point, const Eigen::Vector3d& dir) {
  if (b.is_static) return 0;
  const Eigen::Vector3d rn = (point - b.x).cross(dir);
  return b.inv_mass + rn.dot(inverseInertiaWorld(b) * rn);
}

// The body's share of 1 / m_eff along the worst tangent at `point` (an upper bound).
double inverseMassTangent(const RigidBody& b, const Eigen::Vector3d& point) {
  if (b.is_static) return 0;
  return b.inv_mass + (point - b.x).squaredNorm() * b.inv_inertia_body.maxCoeff();
}

// The overlap a Hertz-type spring reaches from overlap δ closing at `rate`, with the weight of
// its point's effective mass W = m_eff |g| pressing on: its stiffest moment in this impact. The
// energy balance K δp^(n+1)/(n+1) - W δp = ½ m_eff v² + K δ^(n+1)/(n+1) - W δ, its larger root.
// Without the weight, a point resting at δ = 0 would reach no overlap and get no stiffness at all,
// and its first sub-step would span the whole step with no spring in it. The left side is convex,
// so Newton's method from the upper bound A + B (A the root without the weight, B the one without
// the motion) comes down onto the root; stopping within 1 % leaves it a little above, the safe
// side for a sub-step bound.
double peakOverlap(const PenaltyModel::Spring& s, double delta, double rate, double gravity) {
  const double n = s.law.exponent, K = s.law.stiffness;
  const double d = std::max(delta, 0.0), v = std::max(rate, 0.0);
  const double weight = gravity / s.inverse_mass;
  const double motion = 0.5 * v * v / s.inverse_mass + K * std::pow(d, n + 1) / (n + 1);
  const double free_peak = std::pow(motion * (n + 1) / K, 1 / (n + 1));
  if (!(weight > 0)) return free_peak;
  double x = free_peak + std::pow((n + 1) * weight / K, 1 / n);
  for (int i = 0; i < 30; ++i) {
    const double xn = std::pow(x, n);
    const double excess = K * xn * x / (n + 1) - weight * x - (motion - weight * d);
    const double slope = K * xn - weight;
    if (!(excess > 0) || !(slope > 0)) break;
    const double step = excess / slope;
    x -= step;
    if (step < 0.01 * x) break;
  }
  return x;
}

}  // namespace

void PenaltyModel::buildSprings(const World& world, const StepSettings& settings, const SharedStages& shared) {
  last_springs_.swap(springs_);
  springs_.clear();
  const PenaltySettings& p = settings.penalty;
  for (std::size_t i = 0; i < shared.contacts.size(); ++i) {
    const Contact& c = shared.contacts[i];
    const RigidBody& A = world.bodies[c.a];
    const RigidBody& B = world.bodies[c.b];
    Spring s;
    s.a = c.a;
    s.b = c.b;
    s.pair = shared.pairs[i];
    s.radius_a = c.radius_a;
    s.radius_b = c.radius_b;
    const Eigen::Vector3d surface_a = c.point + 0.5 * c.depth * c.normal;
    const Eigen::Vector3d surface_b = c.point - 0.5 * c.depth * c.normal;
    s.core_a = A.rotation().transpose() * (surface_a - c.radius_a * c.normal - A.x);
    s.core_b = B.rotation().transpose() * (surface_b + c.radius_b * c.normal - B.x);
    s.normal_b = B.rotation().transpose() * c.normal;
    s.inverse_mass = inverseMassAlong(A, c.point, c.normal) + inverseMassAlong(B, c.point, c.normal);

    s.law.exponent = lawExponent(p.law);
    if (p.stiffness > 0) {
      s.law.stiffness = p.stiffness;
    } else {
      // A rounded surface has its radius; a polyhedron's point is a tip of half its thinnest width.
      auto radius = [&](int body, double rounding) {
        if (world.bodies[body].pieces.empty()) return std::numeric_limits<double>::infinity();
        return rounding > 0 ? rounding : 0.5 * shared.extents[body].thinnest;
      };
      s.law.stiffness = materialStiffness(p.law, effectiveModulus(A, B), effectiveRadius(radius(c.a, c.radius_a), radius(c.b, c.radius_b)));
    }
    if (p.law == NormalForceLaw::KelvinVoigt)
      s.law.damping = 2 * kelvinVoigtDampingRatio(c.restitution) * std::sqrt(s.law.stiffness / s.inverse_mass);
    s.law.damping_factor = hertzDampingFactor(p.law, c.restitution);
    s.friction = frictionLawOf(p, c.friction);

    // The same point of the same pair last step keeps the closing speed its contact began with.
    const double match = 0.05 * std::min(shared.extents[c.a].thinnest, shared.extents[c.b].thinnest);
    double best = match;
    for (const Spring& old : last_springs_) {
      if (old.pair != s.pair || !old.touching) continue;
      const double d = (old.point - c.point).norm();
      if (d < best) {
        best = d;
        s.touching = true;
        s.law.closing_speed = old.law.closing_speed;
      }
    }
    springs_.push_back(s);
  }
  last_springs_.clear();
}

void PenaltyModel::evaluate(const World& world) {
  stored_energy_ = 0;
  for (Spring& s : springs_) {
    const RigidBody& A = world.bodies[s.a];
    const RigidBody& B = world.bodies[s.b];
    s.normal = B.rotation() * s.normal_b;
    const Eigen::Vector3d core_a = A.x + A.rotation() * s.core_a;
    const Eigen::Vector3d core_b = B.x + B.rotation() * s.core_b;
    const Eigen::Vector3d surface_a = core_a + s.radius_a * s.normal;
    const Eigen::Vector3d surface_b = core_b - s.radius_b * s.normal;
    s.depth = (surface_a - surface_b).dot(s.normal);
    s.point = 0.5 * (surface_a + surface_b);
    const Eigen::Vector3d relative = pointVelocity(A, s.point) - pointVelocity(B, s.point);
    s.rate = relative.dot(s.normal);
    s.slip = relative - s.rate * s.normal;
    if (s.depth <= 0) {
      s.touching = false;
      s.normal_force = 0;
      continue;
    }
    if (!s.touching) {   // the contact begins: the closing speed its damping is measured against
      s.touching = true;
      s.law.closing_speed = s.rate;
    }
    NormalLawState law = s.law;
    if (law.damping_factor > 0) {
      const double n = law.exponent;
      const double natural = s.depth * std::sqrt(n * law.stiffness * std::pow(s.depth, n - 1) * s.inverse_mass);
      law.closing_speed = std::max(law.closing_speed, kRestingClosingShare * natural);
      if (!(law.closing_speed > 0)) law.closing_speed = std::numeric_limits<double>::min();
    }
    s.normal_force = normalForce(law, s.depth, s.rate);
    stored_energy_ += tumble::storedEnergy(s.law, s.depth);
  }
}

// Friction is capped at what stops the slip within the sub-step h, with every touching point of
// the two bodies pulling at once (the sums of their tangential 1 / m_eff): a regularised law is a
// damper of slope dF/dv, and under an impact's peak force it would stop the slip in far less than
// any sub-step the springs need, then overshoot. Where the cap acts, the law would have brought
// the slip to rest within the sub-step anyway; where it does not (slope x 1/m_eff x h below 1, as
// the sub-step bound keeps it under the force a point carries at rest), the law is exact.
void PenaltyModel::addForces(const World& world, std::vector<Wrench>& wrenches, double h) const {
  for (const Spring& s : springs_) {
    if (s.depth <= 0) continue;
    Eigen::Vector3d force = -s.normal_force * s.normal;   // on A; B gets the opposite
    const double slip = s.slip.norm();
    if (slip > 0) {
      double friction = frictionForce(s.friction, slip, s.normal_force);
      const double mobility = sum_slip_mass_[s.a] + sum_slip_mass_[s.b];
      if (mobility > 0) friction = std::min(friction, slip / (mobility * h));
      force -= friction / slip * s.slip;
    }
    for (int side = 0; side < 2; ++side) {
      const int body = side == 0 ? s.a : s.b;
      if (world.bodies[body].is_static) continue;
      const Eigen::Vector3d f = side == 0 ? force : Eigen::Vector3d(-force);
      wrenches[body].force += f;
      wrenches[body].torque += (s.point - world.bodies[body].x).cross(f);
    }
  }
}

double PenaltyModel::stableSubstep(const World& world, double remaining, const Eigen::Vector3d& gravity) {
  const std::size_t n_bodies = world.bodies.size();
  sum_stiffness_.assign(n_bodies, 0.0);
  sum_damping_.assign(n_bodies, 0.0);
  sum_friction_.assign(n_bodies, 0.0);
  sum_slip_mass_.assign(n_bodies, 0.0);
  impact_damping_.assign(springs_.size(), 0.0);
  // Each spring's linearised stiffness and damping at its stiffest in this impact, and its friction
  // law's slope under the force it may reach, shared out to both bodies by their parts of 1 / m_eff.
  for (const Spring& s : springs_) {
    double k = s.law.stiffness, c = s.law.damping;
    const double delta = s.law.exponent == 1 ? std::max(s.depth, 0.0) : peakOverlap(s, s.depth, s.rate, gravity.norm());
    if (s.law.exponent != 1) {
      k = s.law.exponent * s.law.stiffness * std::pow(delta, s.law.exponent - 1);
      if (s.law.damping_factor > 0 && delta > 0) {
        const double natural = delta * std::sqrt(k * s.inverse_mass);
        const double closing = std::max(s.touching ? s.law.closing_speed : s.rate, kRestingClosingShare * natural);
        c = s.law.damping_factor * s.law.stiffness * std::pow(delta, s.law.exponent) / closing;
      }
    }
    // The friction law's slope under the force the point carries, but no more than the weight of
    // its effective mass: that bounds the sub-step where friction holds a body at rest or
    // creeping, and there the law is followed exactly. An impact's peak force makes the law a
    // damper far stiffer than anything else here for the instants it lasts; the cap in addForces
    // keeps those instants stable instead.
    const double carried = gravity.norm() > 0 ? std::min(s.normal_force, gravity.norm() / s.inverse_mass) : s.normal_force;
    const double friction = frictionSlope(s.friction) * carried;
    // In an impact (closing from outside, or a damper pushing a tenth of the spring or more) a
    // damper must also be followed accurately, not only stably: explicit steps leave a damped
    // impact's e off by about γ h / 2 (Kelvin-Voigt's e = 0.3 came out 0.286 at γ h = 0.07). At rest
    // the damper only has to be stable.
    const double elastic = s.depth > 0 ? s.law.stiffness * std::pow(s.depth, s.law.exponent) : 0;
    const bool impact = s.depth <= 0 ? s.rate > 0 : std::abs(c * s.rate) >= 0.1 * elastic;
    impact_damping_[&s - springs_.data()] = impact ? c * s.inverse_mass : 0;
    for (int body : {s.a, s.b}) {
      const RigidBody& b = world.bodies[body];
      if (b.is_static) continue;
      const double w = inverseMassAlong(b, s.point, s.normal);
      sum_stiffness_[body] += k * w;
      sum_damping_[body] += c * w;
      sum_friction_[body] += friction * inverseMassTangent(b, s.point);
      if (s.depth > 0) sum_slip_mass_[body] += inverseMassTangent(b, s.point);
    }
  }
  double h = remaining;
  stiffest_ = -1;
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const Spring& s = springs_[i];
    const double omega2 = sum_stiffness_[s.a] + sum_stiffness_[s.b];
    const double gamma = std::max(sum_damping_[s.a] + sum_damping_[s.b], sum_friction_[s.a] + sum_friction_[s.b]);
    double limit = std::numeric_limits<double>::infinity();
    if (omega2 > 0) limit = kSpringStep / std::sqrt(omega2);
    if (gamma > 0) limit = std::min(limit, kDamperStep / gamma);
    if (impact_damping_[i] > 0) limit = std::min(limit, kImpactDamperStep / impact_damping_[i]);
    if (limit < h) {
      h = limit;
      stiffest_ = static_cast<int>(i);
    }
  }
  stable_ = h;
  // A point about to touch: end the sub-step where it touches, with gravity closing the gap at
  // the difference of the two bodies' pulls along the normal (none between two falling bodies).
  // Taken at the closing speed the sub-step would end with, the instant came early: the sub-step
  // ended short of the touch, the cut to the touch was then too short to take (kTouchCut), and
  // the next sub-step crossed it from outside (a dropped cube's Kelvin-Voigt e came out 1 % high).
  const auto falls = [&](int body) { return world.bodies[body].is_static ? 0.0 : 1.0; };
  double cut = h;
  for (const Spring& s : springs_) {
    if (s.depth > 0) continue;
    const double pull = gravity.dot(s.normal) * (falls(s.a) - falls(s.b));
    const double gap = -s.depth, square = s.rate * s.rate + 2 * pull * gap;
    if (!(square >= 0) || !(s.rate + std::sqrt(square) > 0)) continue;   // it never touches
    // Just past the touching instant (the first root of gap = rate t + pull t² / 2), so that the
    // next sub-step starts inside with the law's force at δ = 0+ (Kelvin-Voigt's damper pushes
    // from the first instant: started from outside, its first half-kick would miss D δ' h / 2,
    // and e = 0.3 came out 0.31).
    const double when = 2 * gap / (s.rate + std::sqrt(square)) * (1 + 1e-6);
    if (when < cut && when > kTouchCut * h) cut = when;
  }
  return cut;
}

void PenaltyModel::refuse(const World& world, const StepSettings& settings, double needed) const {
  const Spring& s = springs_[stiffest_];
  char text[600];
  std::snprintf(text, sizeof text,
                "penalty contact model: the contact between \"%s\" and \"%s\" (%s law, stiffness %.4g %s, "
                "effective mass %.4g kg) needs sub-steps of %.3g s, more than max_substeps = %d per step of "
                "%.4g s; the largest stable step for it is %.3g s: lower the stiffness (or Young's modulus), "
                "raise \"max_substeps\" or use a smaller dt_s",
                world.bodies[s.a].name.c_str(), world.bodies[s.b].name.c_str(), nameOf(settings.penalty.law),
                s.law.stiffness, s.law.exponent == 1 ? "N/m" : "N/m^1.5", 1 / s.inverse_mass, needed,
                settings.penalty.max_substeps, settings.dt, needed);
  std::string message = text;
  // Flores et al.'s factor 8(1 - e)/(5e) and Kelvin-Voigt's damping ratio grow without bound as e
  // goes to 0: a nearly plastic pair is an extreme damper, whatever its stiffness.
  const double e = combineRestitution(world.bodies[s.a].restitution, world.bodies[s.b].restitution);
  if ((settings.penalty.law == NormalForceLaw::Flores || settings.penalty.law == NormalForceLaw::KelvinVoigt) && e < 0.1)
    message += "; the pair's restitution " + std::to_string(e).substr(0, 4) + " makes the " +
               nameOf(settings.penalty.law) + " law's damping extreme (it cannot reach e = 0): raise the "
               "restitution or use hunt_crossley";
  throw Error(ExitCode::Software, message);
}

void PenaltyModel::start(const World& world, const StepSettings& /*settings*/, SharedStages& /*shared*/) {
  if (!world.joints.empty())
    throw Error(ExitCode::BadInput, "the penalty contact model does not simulate joints; use \"baraff\" or "
                                    "\"time_stepping\" for a scene with joints");
}

void PenaltyModel::step(World& world, const StepSettings& settings, SharedStages& shared) {
  const double dt = settings.dt;
  if (shared.has_contacts) {
    auto detect = [&] {
      bodyReach(world, shared.body_radius, dt, reach_);
      shared.detector.detect(world, settings.contact, shared.contacts, &shared.pairs, &reach_, false, settings.threads);
    };
    shared.timed(Detect, detect);
    shared.wakeTouched(world, detect);
    shared.timed(Collide, [&] { buildSprings(world, settings, shared); });
  } else {
    springs_.clear();
  }
  if (springs_.empty()) {
    // Nothing can touch within the step: free flight, integrated as the scene asks (RK4 keeps a
    // free spin's energy to 1e-8 where the sub-steps' semi-implicit turn would lose 1e-4).
    shared.timed(Forces, [&] {
      if (shared.apply_gravity)
        applyGravity(world, shared.wrenches);
      else
        for (Wrench& w : shared.wrenches) w = Wrench{};
    });
    shared.timed(Integrate, [&] { integrate(world, shared.wrenches, settings); });
    ++shared.counters.substeps;
    stored_energy_ = 0;
    shared.contacts_fresh = false;
    return;
  }
  // Velocity Verlet (kick, drift, kick) with the forces at both ends of the sub-step: second
  // order, so an elastic bounce keeps its energy to (ω h)² instead of the ω h of symplectic Euler
  // (an elastic ball came back at 0.993 of its speed). The drift turns the bodies with the
  // integrator's rotation (its implicit midpoint rule on the rotation group).
  StepSettings drift = settings;
  drift.integrator = Integrator::SemiImplicitEuler;
  const double smallest = dt / settings.penalty.max_substeps;
  double done = 0;
  long substeps = 0;
  auto forces = [&](double h) {
    shared.timed(Forces, [&] {
      if (shared.apply_gravity)
        applyGravity(world, shared.wrenches);
      else
        for (Wrench& w : shared.wrenches) w = Wrench{};
      addForces(world, shared.wrenches, h);
    });
  };
  auto kick = [&](double h) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      RigidBody& b = world.bodies[i];
      if (b.is_static) continue;
      b.P += shared.wrenches[i].force * h;
      b.L += shared.wrenches[i].torque * h;
    }
  };
  idle_.resize(world.bodies.size());
  while (dt - done > tuning::kStepRemainder * dt) {
    double h = dt - done;
    shared.timed(Resting, [&] {
      evaluate(world);
      h = stableSubstep(world, dt - done, world.gravity);
    });
    // Only the springs' stability can ask too much; a cut at a touching instant is short by choice.
    if (stable_ < smallest && dt - done > smallest) refuse(world, settings, stable_);
    forces(h);
    kick(h / 2);
    drift.dt = h;
    shared.timed(Integrate, [&] { integrate(world, idle_, drift); });
    // The end's dampers see the end's velocity, predicted by a second kick with the start's forces
    // (taken back after): with the half-step velocity instead, a damper is first order in γ h and
    // Kelvin-Voigt's e = 0.3 came out 0.28.
    start_wrenches_ = shared.wrenches;
    kick(h / 2);
    shared.timed(Resting, [&] { evaluate(world); });
    shared.wrenches.swap(start_wrenches_);
    kick(-h / 2);
    shared.wrenches.swap(start_wrenches_);
    forces(h);
    kick(h / 2);
    done += h;
    ++substeps;
  }
  shared.counters.substeps += substeps;
  // The contacts as the step leaves them, for the fault check and overlays.
  evaluate(world);
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    Contact& c = shared.contacts[i];
    c.point = springs_[i].point;
    c.normal = springs_[i].normal;
    c.depth = springs_[i].depth;
  }
  shared.contacts_fresh = false;
}

std::vector<std::string> PenaltyModel::describe(const StepSettings& settings, const SharedStages& shared) const {
  std::vector<std::string> lines;
  const PenaltySettings& p = settings.penalty;
  char line[400];
  if (shared.has_contacts) {
    lines.push_back("detect      sweep and prune over piece AABBs, SAT narrow phase, ground half-space, "
                    "within how far bodies can close in a step");
    std::snprintf(line, sizeof line,
                  "collide     penalty: %s normal force law, stiffness %s; %s friction (ramp speed %g m/s)",
                  nameOf(p.law),
                  p.stiffness > 0 ? (std::to_string(p.stiffness) + (lawIsLinear(p.law) ? " N/m" : " N/m^1.5")).c_str()
                                  : "from Young's modulus and Poisson's ratio",
                  nameOf(p.friction_law), p.ramp_speed_m_s);
    lines.push_back(line);
    if (p.law == NormalForceLaw::Hooke || p.law == NormalForceLaw::Hertz)
      lines.push_back("            (an elastic law: every contact bounces back with e = 1, whatever the bodies' restitution)");
  }
  std::snprintf(line, sizeof line,
                "integrate   velocity Verlet in sub-steps of dt = %g s as short as the stiffest contact needs "
                "(at most %d per step), %s; %d static never integrated",
                settings.dt, p.max_substeps, shared.movingBodies().c_str(), shared.fixed);
  lines.push_back(line);
  if (shared.apply_gravity) lines.push_back("forces      gravity on " + shared.movingBodies() + " in every sub-step");
  if (!shared.has_contacts) lines.push_back("contacts    none needed: nothing in this scene can touch");
  return lines;
}

}  // namespace tumble
