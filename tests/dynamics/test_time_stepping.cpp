// The time-stepping contact model (simulation.step.model = "time_stepping") on the benchmark
// scenes, against closed forms. It is first order in dt, so its bounds are looser than the Baraff
// model's where the step shows; each says where it came from. Small islands are solved exactly
// by pivoting (rest, stacks, the mass ratio stay exact); the pile uses Gauss-Seidel.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact_scene_runner.h"
#include "dynamics/gravity.h"
#include "dynamics/impulse_memory.h"
#include "dynamics/time_stepping/contact_impulses.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;
using tumble::test::runScene;

namespace {

void timeStepping(Scene& scene) { scene.simulation.step.model = ContactModel::TimeStepping; }

// A contact of scenes/rest.json's cube (body 1) with the ground (body 0), `below` m under its
// centre, e = 0.5.
Contact groundContactUnder(const RigidBody& cube, double below) {
  Contact c;
  c.a = 0;
  c.b = 1;
  c.normal = Eigen::Vector3d::UnitZ();
  c.point = cube.x - Eigen::Vector3d(0, 0, below);
  c.restitution = 0.5;
  return c;
}

const BodySample& last(const test::SceneRun& run, int body) { return run.trajectory.frames.back()[body]; }
const BodySample& first(const test::SceneRun& run, int body) { return run.trajectory.frames.front()[body]; }

}  // namespace

// The apex of the dropped cube's first bounce (closed form 0.75 m) with `steps_per_frame` steps
// in each of the scene's 1/30 s frames, and the largest spin on the way.
struct Bounce {
  double apex = 0, max_w = 0;
};
Bounce dropCube(int steps_per_frame) {
  Bounce out;
  bool rising = false, done = false;
  runScene("cube_drop", 2, [&](const World& w) {
    const RigidBody& cube = w.bodies[1];
    out.max_w = std::max(out.max_w, cube.angularVelocity().norm());
    if (cube.velocity().z() > 0.05) rising = true;
    if (rising && !done) out.apex = std::max(out.apex, cube.x.z());
    if (rising && cube.velocity().z() <= 0) done = true;
  }, 1, [&](Scene& s) {
    timeStepping(s);
    s.simulation.steps_per_frame = steps_per_frame;
    s.simulation.step.dt = 1.0 / (30 * steps_per_frame);   // the scene's 30 frames a second
  });
  return out;
}

TEST_CASE("time stepping: the dropped cube bounces to 0.75 m, first order in dt, and never spins", "[contact][time_stepping]") {
  // The bounce e u is given one step after the landing the speculative margin closed, from the
  // approach speed before it, and the impact is solved before that step's gravity (impacts first:
  // contact_impulses.h): the cube leaves the ground a step late, at e u, and symplectic Euler's
  // rise from there is about e u dt / 2 short of (e u)^2 / 2g; the landing speed is about g dt / 2
  // short too. Both are first order in dt. Measured (2026-11-29): 10.8 mm low at 1/240 s (1.44 %
  // of the apex) and 4.0 mm at 1/480 s. Asserted: within 1.6 % of the apex at 1/240 s (the figure
  // with a tenth to spare) and within half that at 1/480 s. Solved in one problem with the step's
  // gravity, the bounce left at e u at the end of its step and the two lags nearly cancelled
  // (1.7 mm at 1/240 s, 0.6 mm at 1/480 s), at the price of the ground's load acting within every
  // impact's solve (hard case 34, a ball rolling into a wall: 3.1 % to 30 % off).
  const Bounce at_dt = dropCube(8), at_half = dropCube(16);
  const double error = std::abs(at_dt.apex - 0.75), half_error = std::abs(at_half.apex - 0.75);
  INFO("apex " << at_dt.apex << " m at 1/240 s, " << at_half.apex << " m at 1/480 s");
  CHECK(error < 0.016 * 0.75);
  CHECK(half_error < 0.008 * 0.75);
  // The four corners are one island, solved by Gauss-Seidel to 1e-12 of its largest velocity
  // term or else pivoted exactly: the corners' impulses agree to that accuracy, and the spin it can
  // leave is ~1e-9 rad/s (1.0e-9 measured at 1/240 s, 6.2e-8 at 1/480 s; Bullet spins at 3.3 rad/s here).
  CHECK(at_dt.max_w < 1e-8);
  CHECK(at_half.max_w < 1e-7);
}

TEST_CASE("time stepping: a cube on the ground does not move or sink", "[contact][time_stepping]") {
  auto run = runScene("rest", 10, {}, 1, timeStepping);
  // Exact pivoting holds the velocity at zero: the bounds are the Baraff model's (rounding).
  CHECK(run.max_penetration < 1e-6);
  CHECK((last(run, 1).x - first(run, 1).x).norm() < 1e-6);
  CHECK(last(run, 1).v.norm() < 1e-9);
}

TEST_CASE("time stepping: sliding down the incline follows symplectic Euler's closed form", "[contact][time_stepping]") {
  auto run = runScene("incline_slide", 2, {}, 1, timeStepping);
  // Constant acceleration a under symplectic Euler gives x_n = a dt^2 n (n + 1) / 2 exactly,
  // i.e. a t^2 / 2 + a dt t / 2; Coulomb friction is exact along the pyramid's axes. 1e-9 m is
  // rounding over 480 steps.
  const double a = 9.81 * (0.5 - 0.3 * std::cos(M_PI / 6)), t = 2, dt = 1.0 / 240;
  CHECK(std::abs(-last(run, 1).x.x() - (0.5 * a * t * t + 0.5 * a * dt * t)) < 1e-9);
  CHECK(last(run, 1).w.norm() < 1e-9);
}

TEST_CASE("time stepping: the cube sticks on the incline when mu > tan 30", "[contact][time_stepping]") {
  auto run = runScene("incline_stick", 2, {}, 1, timeStepping);
  CHECK((last(run, 1).x - first(run, 1).x).norm() < 1e-9);
}

TEST_CASE("time stepping: 1000:1 mass ratio stays stacked without penetrating", "[contact][time_stepping]") {
  auto run = runScene("mass_ratio", 5, {}, 1, timeStepping);
  // The two-box island is pivoted exactly, so the Baraff model's bounds (test_contact_scenes.cpp)
  // hold (Gauss-Seidel alone lets the heavy box crush the light one: 0.5 m, as Bullet's 0.14 m).
  CHECK(run.max_penetration < 1e-5);
  CHECK(std::abs(last(run, 2).x.z() - 1.5) < 1e-5);
  CHECK(last(run, 2).x.head<2>().norm() < 1e-5);
}

TEST_CASE("time stepping: a stack of 10 stands at 1/60 s", "[contact][time_stepping]") {
  auto run = runScene("stack10", 10, {}, 1, [](Scene& s) {
    timeStepping(s);
    s.simulation.steps_per_frame = 1;   // 30 fps: dt = 1/30 s would be too coarse; 1/60 s below
    s.render.fps = 60;
    s.simulation.step.dt = 1.0 / 60;
  });
  const int top = static_cast<int>(run.trajectory.body_names.size()) - 1;
  // Pivoted exactly (120 rows): nothing moves beyond rounding, at a step where Gauss-Seidel
  // (30 sweeps) lets it fall.
  CHECK(run.max_penetration < 1e-6);
  CHECK((last(run, top).x - first(run, top).x).norm() < 1e-6);
}

TEST_CASE("time stepping: no cube passes through a 1 cm wall at 100 m/s", "[contact][time_stepping]") {
  auto run = runScene("tunnel", 0.2, {}, 1, timeStepping);
  for (std::size_t j = 1; j < run.trajectory.body_names.size(); ++j) {
    INFO(run.trajectory.body_names[j]);
    CHECK(last(run, static_cast<int>(j)).x.x() < 5.0);
  }
}

// The pile (scenes/pile.json) with the time-stepping model comes to rest inside the bin within
// 5 s. Reached (2026-11-28): every piece below 1.6e-9 m/s and 5.4e-9 rad/s at 5 s; the deepest
// overlap in the last half second 9.8e-7 m (the Baraff model rests it too, since 2026-11-28:
// test_pile_scene.cpp). Gauss-Seidel stops at its 200 sweeps on a jammed piece, and which
// path jams is chance: on one path a piece resting on an edge, leaning on a third and carrying a
// fourth crept at 1.2e-3 m/s at 5 s (with 250 sweeps or more it rested).
TEST_CASE("time stepping: the pile by Gauss-Seidel rests in the bin after 5 s, under 1e-4 m deep", "[contact][time_stepping]") {
  double deepest_late = 0;
  auto run = runScene("pile", 5, [&](const World& w) {
    // the last half second, every 30 steps (worldPenetration tests every pair by SAT: costly)
    if (w.time > 4.5 && std::lround(w.time * 240) % 30 == 0)
      deepest_late = std::max(deepest_late, test::worldPenetration(w));
  }, 1000000, [](Scene& s) {
    timeStepping(s);
    s.simulation.step.contact.max_direct_rows = 0;   // every island by Gauss-Seidel: the fast setting for piles
  });
  // The pile's acceptance bound is 1e-3 m (test_pile_scene.cpp); this is a tenth of it, so that it
  // also catches a return to a single projection pass per step (5.5e-4 m here). While the pieces
  // land (0.3-0.7 s) pairs overlap by up to 2.2 cm for a step or two (a corner rotating in that
  // the start-of-step contacts did not hold).
  INFO("deepest overlap in the last 0.5 s " << deepest_late << " m, at the end " << run.max_penetration << " m");
  CHECK(deepest_late < 1e-4);
  CHECK(run.max_penetration < 1e-4);
  World start = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/pile.json")).world;
  const std::vector<BodySample>& end = run.trajectory.frames.back();
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (start.bodies[i].is_static) continue;
    INFO(run.trajectory.body_names[i]);
    CHECK(std::abs(end[i].x.x()) < 2.4);   // the bin's inside: walls 0.2 m thick centred at +-2.5 m
    CHECK(std::abs(end[i].x.y()) < 2.4);
    CHECK(end[i].x.z() > 0);
    // At rest: below the resting-contact speed (1e-3 m/s), as the Baraff pile test asks.
    CHECK(end[i].v.norm() < 1e-3);
    CHECK(end[i].w.norm() < 1e-2);
  }
}

TEST_CASE("time stepping: the same scene gives bit-identical trajectories", "[contact][time_stepping]") {
  auto edit = [](Scene& s) {
    timeStepping(s);
    s.simulation.step.contact.max_direct_rows = 0;
  };
  auto one = runScene("pile", 0.5, {}, 1000000, edit);
  auto two = runScene("pile", 0.5, {}, 1000000, edit);
  REQUIRE(one.trajectory.frames.size() == two.trajectory.frames.size());
  for (std::size_t f = 0; f < one.trajectory.frames.size(); ++f)
    for (std::size_t b = 0; b < one.trajectory.frames[f].size(); ++b) {
      CHECK(one.trajectory.frames[f][b].x == two.trajectory.frames[f][b].x);
      CHECK(one.trajectory.frames[f][b].q.coeffs() == two.trajectory.frames[f][b].q.coeffs());
    }
}

TEST_CASE("impulse memory: a contact is found again across its normal, not beyond the radius", "[contact][time_stepping]") {
  World world;
  world.bodies.resize(2);
  world.bodies[0].x = {1, 2, 3};
  world.bodies[0].q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  Contact c;
  c.a = 0;
  c.b = 1;
  c.point = {1.5, 2, 3};
  c.normal = Eigen::Vector3d::UnitX();
  ImpulseRecord rec;
  rec.a = 0;
  rec.b = 1;
  rec.local = ImpulseMemory::localPoint(world, c);
  rec.impulse = {7, 0, 0};
  ImpulseMemory memory;
  memory.replace({rec});
  Contact moved = c;
  moved.point += Eigen::Vector3d(0.05, 0.001, 0);   // 5 cm along the normal, 1 mm across
  REQUIRE(memory.find(world, moved, 2e-3) != nullptr);
  CHECK(memory.find(world, moved, 2e-3)->impulse.x() == 7);
  moved.point.y() += 0.002;                         // now 3 mm across
  CHECK(memory.find(world, moved, 2e-3) == nullptr);
  Contact other = c;
  other.b = 0;                                      // another pair of bodies
  CHECK(memory.find(world, other, 1) == nullptr);
}

TEST_CASE("impulse memory: each contact finds its own pair's record among many pairs", "[contact][time_stepping]") {
  // Records of several pairs, given out of order; every lookup must land in its own pair, and a
  // pair (or a body A) with no record finds none.
  World world;
  world.bodies.resize(8);
  const std::vector<std::pair<int, int>> pairs = {{2, 5}, {0, 1}, {4, 6}, {0, 2}, {2, 3}, {1, 2}};
  std::vector<ImpulseRecord> records;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ImpulseRecord rec;
    rec.a = pairs[k].first;
    rec.b = pairs[k].second;
    rec.local = Eigen::Vector3d::Zero();
    rec.impulse = {static_cast<double>(k), 0, 0};
    records.push_back(rec);
  }
  ImpulseMemory memory;
  memory.replace(records);
  Contact c;
  c.normal = Eigen::Vector3d::UnitZ();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    c.a = pairs[k].first;
    c.b = pairs[k].second;
    const ImpulseRecord* found = memory.find(world, c, 1e-3);
    REQUIRE(found != nullptr);
    CHECK(found->impulse.x() == static_cast<double>(k));
  }
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{0, 3}, {1, 0}, {3, 4}, {2, 4}, {4, 7}, {6, 7}, {7, 1}}) {
    c.a = a;
    c.b = b;
    CHECK(memory.find(world, c, 1e-3) == nullptr);
  }
  memory.replace({});
  c.a = 0;
  c.b = 1;
  CHECK(memory.find(world, c, 1e-3) == nullptr);
}


TEST_CASE("time stepping: an impact is solved before the step's load, and recorded beside it, no warm start",
          "[contact][time_stepping]") {
  // A cube touching the ground at one point, falling at 2 m/s, e = 0.5, no friction. The impact
  // phase reverses it to 1 m/s before gravity's impulse (N s = m (1 + e) u = 3 on a 1 kg cube);
  // gravity's impulse then leaves it rising at 1 - g dt, so the load's solve has nothing to do.
  BuiltWorld built = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/rest.json"));
  World& world = built.world;
  StepSettings settings = built.step;
  RigidBody& cube = world.bodies[1];
  Contact c = groundContactUnder(cube, 0.5);   // under the centre: no turning
  c.depth = 0;
  cube.P = cube.mass * Eigen::Vector3d(0, 0, -2);
  const std::vector<Contact> contacts{c};
  const std::vector<double> approach{2};
  ContactImpulses impulses;
  ContactSolveStats stats;
  impulses.prepare(world, contacts, approach, settings, minBounceSpeed(world, settings.contact, settings.dt));
  REQUIRE(impulses.applyImpacts(world, contacts, settings, stats));
  CHECK(cube.velocity().z() == Approx(1).epsilon(1e-12));
  applyGravityImpulse(world, settings.dt);
  impulses.apply(world, contacts, approach, settings, false, stats);
  impulses.remember();
  CHECK(cube.velocity().z() == Approx(1 - 9.81 * settings.dt).epsilon(1e-12));
  const ImpulseRecord* record = impulses.memory().find(world, c, ImpulseMemory::kMatchRadius);
  REQUIRE(record);
  CHECK(record->impact.z() == Approx(3 * cube.mass).epsilon(1e-12));   // drawn with the contact's force
  CHECK(record->impulse.norm() < 1e-12);                               // the next step's warm start: none
}

TEST_CASE("time stepping: a landing's bounce lapses when the contact stays short of touching past one step",
          "[contact][time_stepping]") {
  // A cube lands at 10 m/s on the ground through the speculative margin, then rides a few
  // micrometres above it, pressed by gravity, for three steps, then touches. The bounce it was
  // owed (e u = 5 m/s) is for a landing the next step touches: given three steps late it would
  // throw a body that had long stopped (a steel ball riding a block gained 65 J that way).
  BuiltWorld built = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/rest.json"));
  World& world = built.world;
  StepSettings settings = built.step;
  RigidBody& cube = world.bodies[1];
  Contact c = groundContactUnder(cube, 0.25);
  ContactImpulses impulses;
  ContactSolveStats stats;
  const double g_dt = 9.81 * settings.dt;
  const BounceThreshold min_bounce = minBounceSpeed(world, settings.contact, settings.dt);   // 2 g dt here
  auto stepWith = [&](double depth, double vz, double approach) {
    cube.P = cube.mass * Eigen::Vector3d(0, 0, vz);
    cube.L.setZero();
    c.depth = depth;
    const std::vector<Contact> contacts{c};
    const std::vector<double> approaches{approach};
    impulses.prepare(world, contacts, approaches, settings, min_bounce);
    impulses.apply(world, contacts, approaches, settings, true, stats);   // one solve, bounces and load together
    impulses.remember();
    return cube.velocity().z();
  };
  stepWith(-1e-3, -10, 10);                       // the landing, closed by the margin
  for (int k = 0; k < 3; ++k) stepWith(-3e-6, -g_dt, 0);   // riding 3 um above, pressed by gravity
  CHECK(std::abs(stepWith(0, -g_dt, 0)) < 1e-9);  // touching at last: no bounce, it rests

  SECTION("one step short of touching still bounces: rounding may leave a landing a hair apart") {
    ContactImpulses fresh;
    impulses = fresh;
    stepWith(-1e-3, -10, 10);
    stepWith(-3e-6, -g_dt, 0);
    CHECK(stepWith(0, -g_dt, 0) == Approx(5).epsilon(1e-9));
  }
}

// The ten-link chain of scenes/demos/chain.json (dt 1/480 s) under time stepping, 4 s: the total
// energy may never rise above the lowest it has reached by more than 1e-3 of the energy in play
// (test::EnergyRise: the largest kinetic energy plus the potential's range, about 15 J here), the
// run-time fault check's share (energy_check.h), since nothing in the scene adds energy: the
// joints' impulses and projections only remove it, and what touches is inelastic.
// Known failure (measured 2026-11-25): it rises 0.046 J, 3.0e-3 of the energy in play, by 0.87 s,
// and the fault check trips at 0.54 s (`tumble simulate scenes/demos/chain.json --contact-model
// time_stepping`). Not the contacts: with the links thinned to 5 mm (no link meets another) the rise
// is the same, 3.0e-3. Not first-order error shrinking with the step either: 2.6e-2 at 1/960 s and
// 6.1e-2 at 1/1920 s. The Baraff model keeps the same chain within 3.4e-4 (next test). Where it
// comes from (measured 2026-11-27, each stage's change of the total energy): not the position
// projection (it removes up to 1e-7 J a step; its gains sum to 3e-12 J over 4 s) nor the joints'
// forces in the free motion (their change of kinetic energy sums to -1e-5 J over 0.6 s). It is the
// split of the step: gravity is given as an impulse before the impulse problem and the positions
// then move with the joints' forces alone, so during the whip each step's kick (+4e-2 J)
// outweighs the potential energy its motion gives back (-4e-2 J) by 6e-4 to 1.4e-3 J, of which
// the joints' impulses remove 3.4e-4 J. The Baraff model integrates gravity with the joints'
// forces at every RK4 stage.
TEST_CASE("a chain under time stepping gains no energy above 1e-3 of the energy in play over 4 s (reached: 3.0e-3)",
          "[time_stepping][joints][!shouldfail]") {
  test::EnergyRise energy;
  test::SceneRun run = test::runScene(
      "demos/chain", 4, [&](const World& world) { energy.add(world); }, 1000000,
      [](Scene& s) { s.simulation.step.model = ContactModel::TimeStepping; }, true);
  INFO("largest rise " << energy.largest() << " of the energy in play; " << run.faults << " steps at fault");
  CHECK(energy.largest() < 1e-3);
}

TEST_CASE("the same chain under the Baraff model gains no energy above 1e-3 of the energy in play over 4 s (reached: 3.4e-4)",
          "[joints]") {
  test::EnergyRise energy;
  test::runScene("demos/chain", 4, [&](const World& world) { energy.add(world); }, 1000000);
  INFO("largest rise " << energy.largest() << " of the energy in play");
  CHECK(energy.largest() < 1e-3);
}

// The same chain with semi-implicit Euler, whose joint forces are held over the step at the
// velocity level (joints/joint_integrator.h): no energy above the lowest reached, no fault, over
// 4 s at the scene's step. Held at the acceleration level they fed the whip energy at every step
// under both models, and by 1 s the state was not finite (2026-11-28). What the velocity level
// costs instead is dissipation: 7.5 J of the 14.7 J the fall releases are gone by 4 s (Baraff).
TEST_CASE("the chain with semi-implicit Euler gains no energy over 4 s (Baraff model)", "[joints]") {
  test::EnergyRise energy;
  test::SceneRun run = test::runScene(
      "demos/chain", 4, [&](const World& world) { energy.add(world); }, 1000000,
      [](Scene& s) { s.simulation.step.integrator = Integrator::SemiImplicitEuler; }, true);
  INFO("largest rise " << energy.largest() << " of the energy in play; " << run.faults << " steps at fault; the first: "
                       << run.first_fault);
  CHECK(run.faults == 0);
  CHECK(energy.largest() < 1e-3);
}

// Under time stepping the same run gained nothing until 3.37 s, where one step (links 8 and 9
// lying folded onto each other, a link beside them touching both) turned both at 146 rad/s and
// added 10 J before the next step took it back (a known failure until 2026-11-29): the bounce
// target of a contact the joints nearly held already (the problem's smallest eigenvalue 5.5e-5 of
// its largest's 76) was met exactly by impulses of 347 N s. An answer whose bounces add kinetic
// energy is now solved again without them (time_stepping/contact_impulses.cpp).
TEST_CASE("the chain with semi-implicit Euler gains no energy over 4 s under time stepping", "[time_stepping][joints]") {
  test::EnergyRise energy;
  test::SceneRun run = test::runScene(
      "demos/chain", 4, [&](const World& world) { energy.add(world); }, 1000000,
      [](Scene& s) {
        s.simulation.step.model = ContactModel::TimeStepping;
        s.simulation.step.integrator = Integrator::SemiImplicitEuler;
      },
      true);
  INFO("largest rise " << energy.largest() << " of the energy in play; " << run.faults << " steps at fault; the first: "
                       << run.first_fault);
  CHECK(run.faults == 0);
  CHECK(energy.largest() < 1e-3);
}

// The model detects and corrects at the end of each step (time_stepping_model.h), and its
// projection goes on past its eight passes over the pairs still deeper than 100 times the
// contact tolerance (tuning::kProjectionDeepFactor), until none is: so no step of the 100-piece
// pile's landing ends deeper than that, 1e-4 m (9.6e-5 m measured 2026-11-28). Corrected at the
// start of the next step, the states seen were 12 mm deep; at the end with eight passes only,
// 1.7 mm.
TEST_CASE("time stepping: every step of a landing pile ends with its overlaps corrected", "[contact][time_stepping]") {
  double deepest = 0;
  runScene("pile", 1, [&](const World& w) { deepest = std::max(deepest, test::worldPenetration(w)); }, 1,
           timeStepping);
  INFO("deepest overlap at a step's end " << deepest << " m");
  CHECK(deepest < tuning::kProjectionDeepFactor * 1e-6);   // the pile's tolerance: the default
}
