// The benchmark scenes (docs/bench/scenes.md) S1-S5 and S7 with the penalty contact model, once
// per normal force law, against closed forms that keep the compliance (docs/penalty.md). The
// stiffness is the benchmark's rule (src/bench/tumble_engine.cpp, penaltyStiffness): the heaviest
// box on its four corners sinks δ0 = kSinkUnderWeight under 9.81 m/s², K = (m g / 4) / δ0^n. A
// corner of a unit cube of mass m has the effective mass m / 4 along the normal (1/m + |r x n|² / I
// = 1/m + (1/2)(6/m) = 4/m), so four corners touching together are each the law's one-dimensional
// contact of mass m / 4 under a quarter of the weight.
//
// - S1: the apex after the first bounce is 0.5 + e² H, e the law's own: its 1-D impact under
//   gravity, m/4 δ'' = -F(δ, δ') + m/4 g, integrated here (penalty_impact.h). The model holds an
//   impact to its law's e within 1 % (damped laws) and 0.5 % (elastic ones), the bounds
//   tests/hard/test_penalty_closed_forms.cpp holds it to, so the rise e² H within twice that
//   share; sampled at the steps, the apex is missed by at most g dt² / 8.
// - S2a: sliding, a corner's friction is μ N once its slip passes the ramp speed v1. Then the
//   normal momentum, ΣN = m (g_n + z''), gives the slide exactly: ½ a T² + μ s(T), a = g_t - μ g_n,
//   s the centre's sink. Before, the ramp leaves out at most μ ∫N dt ≤ μ m g_n t of friction (the
//   cube is still sinking), and the slip passes v1 by t = v1 / a (it gains at least a per second):
//   the slide is longer by at most μ g_n (v1 / a) T.
// - S2b: held, Coulomb's ramp lets the cube creep at v_c = g_t / (μ g_n) v1, where the friction
//   μ N v / v1 carries the weight's slope component g_t. While the weight is still settling into
//   the contacts the friction is saturated, and as in S2a the cube slides at most μ s ahead; s
//   never passes the undamped law's peak δmax = ((n + 1) w / K)^(1/n), w = m g_n / 4 (the weight's
//   work stored in the spring; damping only takes energy out). Once in the ramp, the creep follows
//   the normal force as it settles: at most v_c / ω more, ω = sqrt(n g_n / δs) the contacts'
//   frequency at rest. The end speed is the creep within 1 %, the creep closed form's tolerance.
// - S3, S4, S7: a damped law settles each contact to K δ^n = w, w its corner's share of the load it
//   carries (the ground contact under a stack of ten carries 10 m g), to 1e-6 of the sink (what
//   rounding leaves of a settled equilibrium, as the closed-form test's static sink); the runs are
//   long enough for each law's transient to die out first. An elastic law (hooke, hertz) set down
//   at zero overlap never settles: it keeps the energy the bodies' sinking set free and rings about
//   the static sinks. There the check is the energy's envelope: the most a box can sink (the
//   largest sum of its contacts' overlaps that energy pays for, by Lagrange's condition) and the
//   most it can rise (all of it lifting the box). Velocity Verlet keeps an undamped contact's
//   energy to (ω h)² = 1e-2 (ω h <= 0.1 per sub-step): the slack. Horizontally the columns stand:
//   the top moves less than the benchmark's 1e-4 m.
// - S5: no contact; free flight is integrated by the scene's RK4, held to the default model's
//   bounds (test_free_spin_scene.cpp): energy 1e-4 at dt = 1/240 s, |L| 1e-12.
// - Flores et al.'s damping factor 8(1 - e)/(5e) is infinite at e = 0 (the law cannot model a
//   plastic pair, docs/known-limits.md): on the scenes whose restitution is 0 (S2-S4, S7) the run
//   refuses, exit 70, naming the pair, its stiffness and the sub-step it needs. So does
//   hunt_crossley on S7 (docs/known-limits.md): its contact between the 1 kg and the 1000 kg box
//   needs shorter sub-steps than max_substeps allows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "base/error.h"
#include "contact_scene_runner.h"
#include "dynamics/penalty/force_laws.h"
#include "penalty_impact.h"

using namespace tumble;
using tumble::test::runScene;

namespace {

constexpr double kSinkUnderWeight = 1e-4;   // m: the benchmark's static overlap
constexpr double kG = 9.81;                 // m/s²: every scene here but S5's
constexpr double kDt = 1.0 / 240;           // s: the scenes' step (30 fps, 8 steps a frame)
constexpr double kVerletEnergy = 1e-2;      // (ω h)²: an undamped contact's energy over a run

// The benchmark's stiffness for a scene whose heaviest box weighs `heaviest_kg`.
double stiffnessFor(NormalForceLaw law, double heaviest_kg) {
  return heaviest_kg * kG / 4 / std::pow(kSinkUnderWeight, lawExponent(law));
}

// K δ^n = w: a corner's overlap under its load w (N).
double staticOverlap(NormalForceLaw law, double K, double w) { return std::pow(w / K, 1 / lawExponent(law)); }

std::function<void(Scene&)> penaltyWith(NormalForceLaw law, double K) {
  return [=](Scene& scene) {
    scene.simulation.step.model = ContactModel::Penalty;
    scene.simulation.step.penalty.law = law;
    scene.simulation.step.penalty.stiffness = K;
  };
}

// The run refuses with exit 70, naming the pair, the stiffness and the sub-step it needs.
void checkRefusal(const std::string& scene, const test::NamedLaw& l, double K, double seconds, const std::string& pair) {
  char stiffness[64];
  std::snprintf(stiffness, sizeof stiffness, "stiffness %.4g %s", K, lawExponent(l.law) == 1 ? "N/m" : "N/m^1.5");
  try {
    runScene(scene, seconds, {}, 1000000, penaltyWith(l.law, K));
    FAIL_CHECK("the run went through");
  } catch (const Error& e) {
    const std::string what = e.what();
    std::printf("penalty scenes: %-13s %-20s refused: %s\n", scene.c_str(), l.name, what.c_str());
    CHECK(e.code() == ExitCode::Software);
    CHECK(what.find(pair) != std::string::npos);
    CHECK(what.find(stiffness) != std::string::npos);
    CHECK(what.find("needs sub-steps of") != std::string::npos);
    if (l.law == NormalForceLaw::Flores) CHECK(what.find("the pair's restitution 0.00") != std::string::npos);
  }
}

// A column of unit cubes on the ground, each contact four corners: corner_loads[j] (N) is what
// each corner of contact j (0: the ground's) carries. The sinks below are of box i's centre, the
// sum of the overlaps of the contacts under it.
struct Column {
  NormalForceLaw law;
  double K;
  std::vector<double> corner_loads;

  double n() const { return lawExponent(law); }
  // The energy of contact j at overlap δ, less the work of its load: 4 (K δ^(n+1)/(n+1) - w δ).
  double energy(std::size_t j, double delta) const {
    return 4 * (K * std::pow(delta, n() + 1) / (n() + 1) - corner_loads[j] * delta);
  }
  double staticSink(std::size_t box) const {
    double s = 0;
    for (std::size_t j = 0; j <= box; ++j) s += staticOverlap(law, K, corner_loads[j]);
    return s;
  }
  // The energy set free when every contact sinks from 0 to its static overlap, at most what an
  // undamped column started at zero overlap has to move with.
  double freeEnergy() const {
    double e = 0;
    for (std::size_t j = 0; j < corner_loads.size(); ++j) e -= energy(j, staticOverlap(law, K, corner_loads[j]));
    return e;
  }
  // The most box i can sink: the largest sum of the overlaps under it for which the contacts'
  // energies (those above at their least) add up to no more than at the start, 0, give or take
  // Verlet's slack. Lagrange: every overlap in the sum has the same slope 4 (K δ^n - w) = 4c,
  // δ = ((w + c) / K)^(1/n); c by bisection, the energy growing with it.
  double mostSink(std::size_t box) const {
    auto overlap = [&](std::size_t j, double c) { return std::pow((corner_loads[j] + c) / K, 1 / n()); };
    auto used = [&](double c) {
      double e = 0;
      for (std::size_t j = 0; j < corner_loads.size(); ++j)
        e += energy(j, j <= box ? overlap(j, c) : staticOverlap(law, K, corner_loads[j]));
      return e - kVerletEnergy * freeEnergy();
    };
    double lo = 0, hi = corner_loads.back();
    while (used(hi) < 0) hi *= 2;
    for (int i = 0; i < 200; ++i) (used(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
    double s = 0;
    for (std::size_t j = 0; j <= box; ++j) s += overlap(j, hi);
    return s;
  }
  // The most box i can rise: a gap under it of g costs 4 w g of energy, w the lightest load below.
  double mostRise(std::size_t box) const {
    double lightest = corner_loads[0];
    for (std::size_t j = 0; j <= box; ++j) lightest = std::min(lightest, corner_loads[j]);
    return (1 + kVerletEnergy) * freeEnergy() / (4 * lightest);
  }
};

// A column's boxes (world bodies 1..boxes) against the law's statics or energy envelope.
struct ColumnWatch {
  std::vector<double> rest_height, least_sink, most_sink;
  explicit ColumnWatch(std::size_t boxes) : least_sink(boxes, INFINITY), most_sink(boxes, -INFINITY) {
    for (std::size_t i = 0; i < boxes; ++i) rest_height.push_back(0.5 + static_cast<double>(i));
  }
  void add(const World& w) {
    for (std::size_t i = 0; i < rest_height.size(); ++i) {
      const double sink = rest_height[i] - w.bodies[i + 1].x.z();
      least_sink[i] = std::min(least_sink[i], sink);
      most_sink[i] = std::max(most_sink[i], sink);
    }
  }
};

void checkColumn(const char* scene, const test::NamedLaw& l, const Column& column, const test::SceneRun& run,
                 const ColumnWatch& watch) {
  const std::size_t boxes = column.corner_loads.size();
  for (std::size_t i = 0; i < boxes; ++i) {
    INFO("box " << i);
    const double closed = column.staticSink(i);
    if (test::isElastic(l.law)) {
      if (i == boxes - 1)
        std::printf("penalty scenes: %-13s %-20s top sinks %.6g..%.6g m, envelope %.6g..%.6g m (static %.6g m)\n", scene,
                    l.name, watch.least_sink[i], watch.most_sink[i], -column.mostRise(i), column.mostSink(i), closed);
      CHECK(watch.most_sink[i] <= column.mostSink(i));
      CHECK(watch.least_sink[i] >= -column.mostRise(i));
    } else {
      const double sink = watch.rest_height[i] - run.trajectory.frames.back()[i + 1].x.z();
      if (i == boxes - 1)
        std::printf("penalty scenes: %-13s %-20s top sink %.9g m, closed form %.9g m (%+.2g of it)\n", scene, l.name, sink,
                    closed, (sink - closed) / closed);
      CHECK(std::abs(sink - closed) <= 1e-6 * closed);
    }
  }
  const BodySample& top = run.trajectory.frames.back()[boxes];
  CHECK(top.x.head<2>().norm() < 1e-4);
}

// Runs a column scene and checks it (checkColumn); `on_step` sees every step too.
void checkColumnScene(const char* scene, const test::NamedLaw& l, const Column& column, double seconds,
                      const std::function<void(const World&)>& on_step = {}) {
  ColumnWatch watch(column.corner_loads.size());
  auto run = runScene(scene, seconds, [&](const World& w) {
    watch.add(w);
    if (on_step) on_step(w);
  }, 1000000, penaltyWith(l.law, column.K));
  checkColumn(scene, l, column, run, watch);
}

}  // namespace

TEST_CASE("penalty scenes: S1 cube drop bounces to the apex of each law's own impact, without spin", "[penalty]") {
  const double mass = 1, drop = 1.0, e = 0.5;   // scene: 1 kg unit cube, bottom 1 m up, pair's e 0.5
  const double v0 = std::sqrt(2 * kG * drop);
  for (const test::NamedLaw& l : test::kNormalLaws) {
    DYNAMIC_SECTION(l.name) {
      const double K = stiffnessFor(l.law, mass);
      NormalLawState law;
      law.stiffness = K;
      law.exponent = lawExponent(l.law);
      if (l.law == NormalForceLaw::KelvinVoigt) law.damping = 2 * kelvinVoigtDampingRatio(e) * std::sqrt(K * mass / 4);
      law.damping_factor = hertzDampingFactor(l.law, e);
      law.closing_speed = v0;
      const double e_law = test::oneDimensionalRestitution(law, mass / 4, v0, kG);
      const double closed = 0.5 + e_law * e_law * drop;
      double apex = 0, max_w = 0;
      bool rising = false, done = false;
      runScene("cube_drop", 1.0, [&](const World& w) {   // the elastic laws' apex is at 0.90 s
        const RigidBody& cube = w.bodies[1];
        max_w = std::max(max_w, cube.angularVelocity().norm());
        if (cube.velocity().z() > 0.05) rising = true;
        if (rising && !done) apex = std::max(apex, cube.x.z());
        if (rising && cube.velocity().z() <= 0) done = true;
      }, 1000000, penaltyWith(l.law, K));
      const double tolerance = 2 * (test::isElastic(l.law) ? 5e-3 : 1e-2) * e_law * e_law * drop + kG * kDt * kDt / 8;
      std::printf("penalty scenes: cube_drop     %-20s apex %.6f m, its own impact (e %.5f) %.6f m, tolerance %.2g m; "
                  "spin %.2g rad/s\n", l.name, apex, e_law, closed, tolerance, max_w);
      CHECK(std::abs(apex - closed) <= tolerance);
      CHECK(max_w < 1e-9);
    }
  }
}

namespace {

// S2a for one law: the slide against its closed form (header).
void checkSlide(const test::NamedLaw& l) {
  const double mu = 0.3, seconds = 2, v1 = PenaltySettings{}.ramp_speed_m_s;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  auto run = runScene("incline_slide", seconds, [&](const World& w) { gravity = w.gravity; }, 1000000,
                      penaltyWith(l.law, stiffnessFor(l.law, 1)));
  const double g_t = -gravity.x(), g_n = -gravity.z(), a = g_t - mu * g_n;   // down the slope is -x
  const BodySample &start = run.trajectory.frames.front()[1], &end = run.trajectory.frames.back()[1];
  const double slide = start.x.x() - end.x.x(), sink = start.x.z() - end.x.z();
  const double closed = 0.5 * a * seconds * seconds + mu * sink;
  const double tolerance = mu * g_n * v1 / a * seconds;
  std::printf("penalty scenes: incline_slide %-20s slide %.7f m, closed form %.7f m (sink %.3g m), tolerance %.2g m\n",
              l.name, slide, closed, sink, tolerance);
  CHECK(std::abs(slide - closed) <= tolerance);
}

// S2b for one law: the creep and the displacement bound (header).
void checkStick(const test::NamedLaw& l) {
  const double mu = 0.7, seconds = 2, v1 = PenaltySettings{}.ramp_speed_m_s;
  const double K = stiffnessFor(l.law, 1);
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  auto run = runScene("incline_stick", seconds, [&](const World& w) { gravity = w.gravity; }, 1000000,
                      penaltyWith(l.law, K));
  const double g_t = -gravity.x(), g_n = -gravity.z(), n = lawExponent(l.law);
  const double creep = g_t / (mu * g_n) * v1;
  const double w = g_n / 4, rest = staticOverlap(l.law, K, w), peak = std::pow((n + 1) * w / K, 1 / n);
  const double omega = std::sqrt(n * g_n / rest);
  const BodySample &start = run.trajectory.frames.front()[1], &end = run.trajectory.frames.back()[1];
  const double slide = start.x.x() - end.x.x(), speed = -end.v.x();
  const double bound = creep * seconds + mu * peak + creep / omega;
  std::printf("penalty scenes: incline_stick %-20s slide %.6g m, bound %.6g m (creep %.6g m/s x %g s); "
              "end speed %.6g m/s\n", l.name, slide, bound, creep, seconds, speed);
  CHECK(slide >= 0);
  CHECK(slide <= bound);
  CHECK(std::abs(speed - creep) <= 0.01 * creep);   // the creep closed form's tolerance
  CHECK(std::abs(end.x.y() - start.x.y()) <= 1e-9);
}

}  // namespace

TEST_CASE("penalty scenes: S2a the cube slides 0.5 g (sin 30 - mu cos 30) t^2 and mu times its sink", "[penalty]") {
  for (const test::NamedLaw& l : test::kNormalLaws) {
    DYNAMIC_SECTION(l.name) {
      if (l.law == NormalForceLaw::Flores)
        checkRefusal("incline_slide", l, stiffnessFor(l.law, 1), 2, "\"cube\" and \"ground\"");
      else
        checkSlide(l);
    }
  }
}

TEST_CASE("penalty scenes: S2b the cube held by friction only creeps at its ramp's speed (damped laws)", "[penalty]") {
  for (const test::NamedLaw& l : test::kNormalLaws) {
    if (test::isElastic(l.law)) continue;   // next test
    DYNAMIC_SECTION(l.name) {
      if (l.law == NormalForceLaw::Flores)
        checkRefusal("incline_stick", l, stiffnessFor(l.law, 1), 2, "\"cube\" and \"ground\"");
      else
        checkStick(l);
    }
  }
}

// Known failure (2026-11-25): set down at zero overlap, an undamped contact rings about its sink
// for ever; each time it unloads the friction lets go, and the slips feed a rocking that grows
// until the cube hops down the slope: 1.29 m (hooke) and 1.28 m (hertz) in 2 s, against the
// bound of 1.8e-3 m. Not the sub-steps': a quarter of the sub-step hops as far (1.28 m and
// 1.22 m). docs/known-limits.md.
TEST_CASE("penalty scenes: S2b the cube held by friction only creeps at its ramp's speed (elastic laws)",
          "[penalty][!mayfail]") {
  for (const test::NamedLaw& l : test::kNormalLaws) {
    if (!test::isElastic(l.law)) continue;
    DYNAMIC_SECTION(l.name) { checkStick(l); }
  }
}

TEST_CASE("penalty scenes: S3 a resting cube sinks to K delta^n = m g / 4 per corner, without drift or spin", "[penalty]") {
  const double seconds = 1;
  for (const test::NamedLaw& l : test::kNormalLaws) {
    DYNAMIC_SECTION(l.name) {
      const Column column{l.law, stiffnessFor(l.law, 1), {kG / 4}};
      double drift = 0, spin = 0;
      if (l.law == NormalForceLaw::Flores)
        checkRefusal("rest", l, column.K, seconds, "\"cube\" and \"ground\"");
      else
        checkColumnScene("rest", l, column, seconds, [&](const World& w) {
          drift = std::max(drift, w.bodies[1].x.head<2>().norm());
          spin = std::max(spin, w.bodies[1].angularVelocity().norm());
        });
      CHECK(drift <= 1e-9);   // four equal corners: nothing but rounding turns or pushes it
      CHECK(spin <= 1e-9);
    }
  }
}

TEST_CASE("penalty scenes: S4 a stack of ten sinks by each contact's load and stands", "[penalty]") {
  const double seconds = 1;
  for (const test::NamedLaw& l : test::kNormalLaws) {
    DYNAMIC_SECTION(l.name) {
      Column column{l.law, stiffnessFor(l.law, 1), {}};
      for (int above = 10; above >= 1; --above) column.corner_loads.push_back(above * kG / 4);
      if (l.law == NormalForceLaw::Flores)
        checkRefusal("stack10", l, column.K, seconds, "\"cube_0\" and \"cube_1\"");
      else
        checkColumnScene("stack10", l, column, seconds);
    }
  }
}

TEST_CASE("penalty scenes: S5 free spin touches nothing and keeps its energy and angular momentum", "[penalty]") {
  for (const test::NamedLaw& l : test::kNormalLaws) {
    DYNAMIC_SECTION(l.name) {
      double E0 = 0, L0 = 0, dE = 0, dL = 0;
      long steps = 0;
      auto run = runScene("free_spin", 10, [&](const World& w) {
        const RigidBody& plate = w.bodies[1];
        if (steps++ == 0) E0 = plate.kineticEnergy(), L0 = plate.L.norm();
        dE = std::max(dE, std::abs(plate.kineticEnergy() / E0 - 1));
        dL = std::max(dL, std::abs(plate.L.norm() / L0 - 1));
      }, 1000000, penaltyWith(l.law, stiffnessFor(l.law, 1)));
      std::printf("penalty scenes: free_spin     %-20s energy %.2g, |L| %.2g, %ld sub-steps in %ld steps\n", l.name, dE, dL,
                  run.counters.substeps, steps);
      CHECK(dE < 1e-4);
      CHECK(dL < 1e-12);
      CHECK(run.counters.substeps == steps);   // free flight: one integration per step
    }
  }
}

TEST_CASE("penalty scenes: S7 a 1000 kg box on a 1 kg box sinks by each contact's load, or the run refuses", "[penalty]") {
  const double seconds = 1.5;
  for (const test::NamedLaw& l : test::kNormalLaws) {
    DYNAMIC_SECTION(l.name) {
      // The stiffness carries the heavy box; the light one's ground contact carries both, 1001 g.
      const Column column{l.law, stiffnessFor(l.law, 1000), {1001 * kG / 4, 1000 * kG / 4}};
      if (l.law == NormalForceLaw::Flores || l.law == NormalForceLaw::HuntCrossley)
        checkRefusal("mass_ratio", l, column.K, seconds, "\"light\" and \"heavy\"");
      else
        checkColumnScene("mass_ratio", l, column, seconds);
    }
  }
}
