#include "dynamics/baraff/back_step.h"

#include <algorithm>
#include <limits>

#include "dynamics/baraff/bracket_record.h"
#include "dynamics/baraff/time_of_impact.h"
#include "dynamics/contact_rows.h"

namespace tumble {
namespace {

// How far a too-deep point may be from a touching point of the same pair at the sub-step's start
// and still be that point (moved by the sub-step's sliding or turning) rather than a landing: a
// tenth of the smaller body's radius.
double landingRadius(const Contact& c, const std::vector<double>& body_radius) {
  double r = std::numeric_limits<double>::infinity();
  for (int body : {c.a, c.b})
    if (body_radius[body] > 0) r = std::min(r, body_radius[body]);
  return 0.1 * r;
}

}  // namespace

double BackStepper::firstContact(World& world, const StepSettings& settings, double h, const TrialSubstep& trial,
                                 SharedStages& shared) {
  PipelineCounters& counters = shared.counters;
  const std::vector<Contact>& start = shared.contacts;
  const std::vector<PiecePair>& start_pairs = shared.pairs;
  ++counters.back_steps;
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
  for (std::size_t i = 0; i < trial.end.size(); ++i) {
    const Contact& end = trial.end[i];
    if (end.depth <= tol) continue;
    double before = -std::numeric_limits<double>::infinity();
    bool touched_here = false;
    const double near = landingRadius(end, shared.body_radius);
    for (std::size_t j = 0; j < start.size(); ++j) {
      if (!(start_pairs[j] == trial.end_pairs[i])) continue;
      const Contact& s = start[j];
      before = std::max(before, s.depth);
      touched_here |= s.depth >= -tol && !trial.lifting[j] && (s.point - end.point).squaredNorm() <= near * near;
    }
    // Every landing that approaches (faster than the resting speed) is timed, however slow: a
    // block's rocking is the same law at every size, and a 5 cm block's corners land at a few
    // cm/s. Not timing landings below a fixed 0.08 m/s saved a third of the sub-steps in a pile,
    // and cut a 15 cm block's rocking to half of Housner's ratio at its third landing.
    if (before >= -tol && (touched_here || -normalVelocity(world, end) <= settings.contact.resting_speed_m_s)) continue;
    if (!offending.empty() && offending.back().pair == trial.end_pairs[i]) continue;
    Watch w{trial.end_pairs[i], before >= -tol, near, {}, end.a, end.b, end.point};
    if (w.landing)
      for (std::size_t j = 0; j < start.size(); ++j)
        if (start_pairs[j] == w.pair && start[j].depth >= -tol && !trial.lifting[j])
          w.resting.push_back(start[j].point);
    offending.push_back(std::move(w));
  }
  if (offending.empty()) return h;
  // The bracket needs every pair within the tolerance at the start. The manifold (which said the
  // pair was apart) and the separation bisection measures can disagree on a pair the narrow phase
  // missed at the start; such a pair is not a first contact to find but a penetration to project,
  // and bisecting on it would return t = 0 and stall the step. It is dropped and counted.
  trial.start_state.restore(world);
  watched_.clear();
  for (Watch& w : offending)
    if (watchedDepth(world, w, settings, shared.detector) <= tol) watched_.push_back(std::move(w));
    else ++counters.inconsistent_pairs;
  StepSettings sub = settings;
  auto depth_at = [&](double t) {
    trial.start_state.restore(world);
    sub.dt = t;
    shared.counters.bodies_integrated += integrate(world, shared.wrenches, sub);
    double worst = -std::numeric_limits<double>::infinity();
    for (const Watch& w : watched_) worst = std::max(worst, watchedDepth(world, w, settings, shared.detector));
    return worst;
  };
  if (watched_.empty()) {
    depth_at(h);
    return h;
  }
  // The overlay's record of the search (inert without a log): each trial's poses, as tried.
  BracketRecord record(shared.back_step_log, world.time, h);
  for (const Watch& w : watched_) record.watch(world, w.a, w.b, w.point);
  auto tried = [&](double t) {
    const double depth = depth_at(t);
    record.trial(world, t, depth > tol);
    return depth;
  };
  int evaluations = 0;
  const double at_once = tuning::kImmediateContact * h;
  for (;;) {
    const double deepest = tried(h);
    ++counters.bisection_evaluations;
    if (deepest <= tol) return h;   // only the manifold saw it too deep: nothing to go back for
    ImpactSearch found = findFirstContact(tried, h, deepest, tol, settings.contact.max_bisections,
                                          settings.contact.regula_falsi);
    counters.bisection_evaluations += found.evaluations;
    evaluations += found.evaluations;
    if (found.time >= at_once) {
      depth_at(found.time);
      record.found(found.time, evaluations);
      return found.time;
    }
    // A pair too deep at once: a landing found again at the start after its impulse (a point the
    // impulse could not stop, or whose manifold moved). Cutting here would stall the step in
    // sub-steps of nothing; the next sub-step's impulse and the projection take it. But only it:
    // the other pairs are timed again without it. Given up on all together, a brick pressed 1e-6 m
    // deep at 4 m/s in a wall a steel ball had just struck hid the ball's first contact with the
    // next brick, and the sub-step took the ball 6 cm into it (scenes/hard/debris_wall.json).
    // Left out are the pairs too deep by `at_once`, or if none is yet, the one nearest to it (the
    // search stopped just before it crossed): each round leaves out at least one.
    depth_at(at_once);
    depths_.clear();
    for (const Watch& w : watched_) depths_.push_back(watchedDepth(world, w, settings, shared.detector));
    const double nearest = *std::max_element(depths_.begin(), depths_.end());
    std::size_t kept = 0;
    for (std::size_t k = 0; k < watched_.size(); ++k)
      if (depths_[k] <= tol && depths_[k] < nearest) watched_[kept++] = std::move(watched_[k]);
    watched_.resize(kept);
    if (watched_.empty()) {
      depth_at(h);
      return h;
    }
  }
}

// The depth back-stepping times a watched pair by: its separation for a first contact; for a
// landing, the deepest of its contact points away from every point it rested on at the start.
double BackStepper::watchedDepth(const World& world, const Watch& w, const StepSettings& settings,
                                 ContactDetector& detector) {
  if (!w.landing) return detector.maxDepth(world, {w.pair});
  landing_points_.clear();
  detector.pairContacts(world, w.pair, settings.contact.margin_m, landing_points_);
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Contact& c : landing_points_) {
    bool resting = false;
    for (const Eigen::Vector3d& p : w.resting) resting |= (p - c.point).squaredNorm() <= w.near * w.near;
    if (!resting) deepest = std::max(deepest, c.depth);
  }
  return deepest;
}

}  // namespace tumble
