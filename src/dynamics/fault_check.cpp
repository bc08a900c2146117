#include "dynamics/fault_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "dynamics/joints/joint.h"
#include "dynamics/time_stepping/contact_impulses.h"

namespace tumble {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string inQuotes(const std::string& name) { return "\"" + name + "\""; }

// Which part of a body's state is not finite, for the message.
std::string brokenParts(const RigidBody& b) {
  std::string parts;
  auto add = [&](bool ok, const char* what) {
    if (!ok) parts += (parts.empty() ? "" : ", ") + std::string(what);
  };
  add(b.x.allFinite(), "position");
  add(b.q.coeffs().allFinite(), "orientation");
  add(b.P.allFinite(), "linear momentum");
  add(b.L.allFinite(), "angular momentum");
  return parts;
}

const char* kKindNames[] = {"non-finite state", "runaway energy", "deep penetration", "unexplained motion",
                            "energy gain"};
static_assert(sizeof kKindNames / sizeof kKindNames[0] == static_cast<int>(Fault::Kind::Count));

}  // namespace

FaultSettings FaultSettings::forModel(ContactModel model) {
  FaultSettings s;
  s.energy_repaid_within = model == ContactModel::TimeStepping ? kOwedBounceCarries + 1 : 0;
  return s;
}

std::string Fault::describe() const {
  return "numerical failure at t = " + number(time) + " s (step " + std::to_string(step) +
         (stages.empty() ? "" : "; stages run: " + stages) + "): " + detail;
}

FaultCheck::FaultCheck(const World& world, FaultSettings settings)
    : settings_(settings),
      gravity_(world.gravity),
      extents_(extentsOf(world)),
      motion_(world, extents_, settings.depth_share),
      energy_(world, settings.energy_gain_share, settings.energy_drift_m, settings.energy_repaid_within),
      last_time_(world.time) {
  double scale = 0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    start_x_.push_back(b.x);
    start_energy_.push_back(b.is_static ? 0 : b.kineticEnergy());
    start_total_ += start_energy_.back();
    if (!b.is_static) scale += b.kineticEnergy() + b.mass * gravity_.norm() * extents_[i].radius;
  }
  // The last term only keeps the limit above rounding when nothing moves and nothing falls.
  energy_limit_ = settings_.energy_growth * scale + 1e-9 * (1 + scale);
  extremes_.energy_start_j = extremes_.energy_end_j = start_total_;
  extremes_.scale_j = scale;
}

void FaultCheck::measure(const World& world, double stored, const std::vector<Contact>& contacts) {
  double total = stored;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) total += energyOf(world.bodies[i], int(i));
  extremes_.energy_end_j = total;
  extremes_.highest_rise_j = std::max(extremes_.highest_rise_j, total - start_total_);
  for (const Contact& c : contacts)
    if (c.depth > extremes_.deepest_m) {
      extremes_.deepest_m = c.depth;
      extremes_.deepest_time = world.time;
    }
}

double FaultCheck::energyOf(const RigidBody& body, int index) const {
  if (body.is_static) return 0;
  // Potential energy -m g.(x - x0): zero at the start, so each body's energy starts at its KE.
  return body.kineticEnergy() - body.mass * gravity_.dot(body.x - start_x_[index]);
}

std::optional<Fault> FaultCheck::nonFinite(const World& world) const {
  Fault f;
  for (const RigidBody& b : world.bodies) {
    std::string parts = brokenParts(b);
    if (parts.empty()) continue;
    if (f.bodies.empty()) f.detail = "body " + inQuotes(b.name) + " has a non-finite " + parts;
    f.bodies.push_back(b.name);
  }
  if (f.bodies.empty()) return std::nullopt;
  // A NaN spreads through contacts within a step: name a few of the others too.
  for (std::size_t i = 1; i < f.bodies.size() && i <= 3; ++i)
    f.detail += (i == 1 ? " (also " : ", ") + inQuotes(f.bodies[i]);
  if (f.bodies.size() > 4) f.detail += " and " + std::to_string(f.bodies.size() - 4) + " more";
  if (f.bodies.size() > 1) f.detail += ")";
  f.kind = Fault::Kind::NonFinite;
  f.detail += "; try a smaller dt_s";
  return f;
}

std::optional<Fault> FaultCheck::runawayEnergy(const World& world, double stored) const {
  double total = stored, largest_gain = -kInf;
  int gainer = -1;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    double e = energyOf(world.bodies[i], int(i));
    total += e;
    if (e - start_energy_[i] > largest_gain) {
      largest_gain = e - start_energy_[i];
      gainer = int(i);
    }
  }
  if (total - start_total_ <= energy_limit_) return std::nullopt;
  Fault f;
  f.kind = Fault::Kind::RunawayEnergy;
  f.bodies.push_back(world.bodies[gainer].name);
  f.detail = "runaway energy: the total rose from " + number(start_total_) + " J to " + number(total) +
             " J (limit " + number(start_total_ + energy_limit_) + " J); body " +
             inQuotes(world.bodies[gainer].name) + " gained the most (" + number(largest_gain) +
             " J); try a smaller dt_s or lower restitution";
  return f;
}

std::optional<Fault> FaultCheck::deepPenetration(const World& world,
                                                 const std::vector<Contact>& contacts) const {
  const Contact* worst = nullptr;
  double worst_share = settings_.depth_share, limit = 0;
  for (const Contact& c : contacts) {
    double thinner = std::min(extents_[c.a].thinnest, extents_[c.b].thinnest);
    if (!std::isfinite(thinner) || c.depth <= 0) continue;
    if (c.depth / thinner > worst_share) {
      worst = &c;
      worst_share = c.depth / thinner;
      limit = settings_.depth_share * thinner;
    }
  }
  if (!worst) return std::nullopt;
  Fault f;
  f.kind = Fault::Kind::DeepPenetration;
  f.bodies = {world.bodies[worst->a].name, world.bodies[worst->b].name};
  f.detail = "bodies " + inQuotes(f.bodies[0]) + " and " + inQuotes(f.bodies[1]) + " overlap by " +
             number(worst->depth) + " m (limit " + number(limit) +
             " m, half the thinner piece); try a smaller dt_s";
  return f;
}

std::optional<Fault> FaultCheck::unexplainedMotion(const World& world, const Pipeline& pipeline) {
  const double dt = world.time - last_time_;
  last_time_ = world.time;
  std::optional<UnexplainedMotion> m = motion_.afterStep(world, dt, pipeline.peakSpeeds(), pipeline.peakSpins());
  if (!m) return std::nullopt;
  Fault f;
  f.kind = Fault::Kind::UnexplainedMotion;
  f.bodies.push_back(world.bodies[m->body].name);
  f.detail = "unexplained motion: body " + inQuotes(f.bodies[0]) + " moved by up to " + number(m->moved) +
             " m in one step, where its speeds and the position correction allow " + number(m->allowed) +
             " m; try a smaller dt_s";
  return f;
}

std::optional<Fault> FaultCheck::energyGain(const World& world, double stored) {
  std::optional<EnergyGain> g = energy_.afterStep(world, stored);
  if (!g) return std::nullopt;
  Fault f;
  f.kind = Fault::Kind::EnergyGain;
  f.detail = "energy gain: the total rose " + number(g->total - g->lowest) +
             " J above the lowest it reached (tolerance " + number(g->tolerance) + " J) in a scene with " +
             "nothing that adds energy";
  if (g->body >= 0) {
    f.bodies.push_back(world.bodies[g->body].name);
    f.detail += "; body " + inQuotes(f.bodies[0]) + " gained the most";
  }
  f.detail += "; try a smaller dt_s";
  return f;
}

// A stage ran in the last step when its timer moved. The pipeline checks nothing between its
// stages, so this is as close as a fault can be pinned without a hook inside the step.
std::string FaultCheck::stagesRun(const std::vector<StageTime>& profile) {
  stage_seconds_.resize(profile.size(), 0);
  std::string ran;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    if (profile[i].seconds != stage_seconds_[i]) ran += (ran.empty() ? "" : ", ") + profile[i].name;
    stage_seconds_[i] = profile[i].seconds;
  }
  return ran;
}

std::optional<Fault> FaultCheck::afterStep(const World& world, const Pipeline& pipeline, long step) {
  std::string stages = stagesRun(pipeline.profile());
  // Every check runs every step (each keeps its running state); the first fault found is reported.
  std::optional<Fault> f = nonFinite(world);
  if (f) return record(*f, world, step, stages);
  const double stored = pipeline.storedEnergy();
  measure(world, stored, pipeline.contacts());
  std::optional<Fault> checks[] = {unexplainedMotion(world, pipeline), runawayEnergy(world, stored),
                                   deepPenetration(world, pipeline.contacts()), energyGain(world, stored)};
  // A joint's motor does work (a PD motor lifts an arm, a velocity motor spins a wheel): a scene
  // with one is not passive, and its energy may rise.
  if (hasMotors(world.joints)) checks[1] = checks[3] = std::nullopt;
  for (std::optional<Fault>& c : checks)
    if (c) return record(*c, world, step, stages);
  return std::nullopt;
}

std::optional<Fault> FaultCheck::record(Fault fault, const World& world, long step, const std::string& stages) {
  std::optional<Fault> f = std::move(fault);
  f->time = world.time;
  f->step = step;
  f->stages = stages;
  ++counts_[static_cast<int>(f->kind)];
  if (!first_) first_ = f;
  return f;
}

long FaultCheck::total() const {
  long n = 0;
  for (long c : counts_) n += c;
  return n;
}

std::string FaultCheck::summary() const {
  if (total() == 0) return "";
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on a chain of string + string.
  std::string out = std::to_string(total());
  out.append(total() == 1 ? " step" : " steps").append(" with numerical faults:");
  for (int k = 0; k < static_cast<int>(Fault::Kind::Count); ++k)
    if (counts_[k] > 0) out.append(" ").append(std::to_string(counts_[k])).append(" ").append(kKindNames[k]).append(",");
  out.back() = ';';
  return out.append(" the first: ").append(first_->describe());
}

}  // namespace tumble
