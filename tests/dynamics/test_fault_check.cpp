// Numerical faults at run time are caught the step they happen, named (bodies, time, stages) and
// stop the run with exit code 70, unless the run keeps going; healthy runs raise nothing.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "base/error.h"
#include "dynamics/body_extent.h"
#include "dynamics/motion_check.h"
#include "dynamics/simulator.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

// A 1 m box named "crate" resting 1 m above the ground, another ("lid") wherever asked.
BuiltWorld twoBoxes(const std::string& lid_position) {
  Scene scene = parseScene(R"({"schema_version": 1, "bodies": [
    {"name": "ground", "shape": "plane"},
    {"name": "crate", "shape": "box", "position_m": [0, 0, 1.5]},
    {"name": "lid", "shape": "box", "position_m": )" + lid_position + R"(}]})",
                           "scenes/faults.json");
  return buildWorld(scene);
}

std::string faultOf(Simulator& sim) {
  try {
    sim.run();
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::Software);
    return e.what();
  }
  return "";
}

// The fault found is of `kind`, names `body` alone, and says `text`.
void checkFault(const std::optional<Fault>& fault, Fault::Kind kind, const std::string& body, const std::string& text) {
  REQUIRE(fault);
  CHECK(fault->kind == kind);
  CHECK(fault->bodies == std::vector<std::string>{body});
  CHECK_THAT(fault->describe(), Catch::Contains(text));
}

}  // namespace

TEST_CASE("a NaN in a body's state stops the run that step, naming the body and time", "[faults]") {
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  built.world.bodies[2].P.x() = std::numeric_limits<double>::quiet_NaN();
  Simulator sim(std::move(built.world), {built.step, 8, 30});
  std::string message = faultOf(sim);
  CHECK_THAT(message, Catch::Contains("numerical failure at t = 0.00416667 s (step 1; stages run: ") &&
                          Catch::Contains("body \"lid\" has a non-finite") &&
                          Catch::Contains("--keep-going"));
  CHECK(sim.faults().first()->bodies == std::vector<std::string>{"lid"});
}

TEST_CASE("bodies sunk into each other are a deep penetration fault", "[faults]") {
  // The crate is put inside a 3 m block, centre on centre: 2 m deep, far beyond half the thinner
  // box (0.5 m), and beyond what the position correction may move a body in one step (also half
  // its thinnest piece: drift_correction.h), which repairs a shallower sinking. A scene cannot
  // start that way (buildWorld refuses it, start_overlap.h), so the test moves the crate in after
  // building, as a failing contact solve would.
  Scene scene = parseScene(R"({"schema_version": 1, "bodies": [
    {"name": "ground", "shape": "plane"},
    {"name": "crate", "shape": "box", "position_m": [0, 0, 5]},
    {"name": "block", "shape": "box", "size_m": [3, 3, 3], "position_m": [10, 0, 1.5]}]})",
                           "scenes/faults.json");
  BuiltWorld built = buildWorld(scene);
  built.world.bodies[1].x = built.world.bodies[2].x;
  Simulator sim(std::move(built.world), {built.step, 8, 30});
  std::string message = faultOf(sim);
  CHECK_THAT(message, Catch::Contains("step 1;") && Catch::Contains("bodies \"crate\" and \"block\" overlap by") &&
                          Catch::Contains("half the thinner piece"));
}

TEST_CASE("energy that grows without a source is a runaway energy fault", "[faults]") {
  // The contact stages never add energy; a kick from outside stands in for a solver that would.
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  FaultCheck check(built.world);
  Pipeline pipeline(built.world, built.step);
  CHECK_FALSE(check.afterStep(built.world, pipeline, 1));
  RigidBody& crate = built.world.bodies[1];
  crate.P = crate.mass * Eigen::Vector3d(0, 0, 50);   // 1.25 MJ; the limit is ~4 kJ
  std::optional<Fault> fault = check.afterStep(built.world, pipeline, 2);
  checkFault(fault, Fault::Kind::RunawayEnergy, "crate",
             "(step 2): runaway energy: the total rose from 0 J to 1.25e+06 J");
  CHECK_THAT(fault->describe(), Catch::Contains("body \"crate\" gained the most"));
}

TEST_CASE("with keep_going a fault is counted and summarised, and the run finishes", "[faults]") {
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  built.world.bodies[1].L.z() = std::numeric_limits<double>::infinity();
  SimulationPlan plan{built.step, 8, 10};
  plan.keep_going = true;
  Simulator sim(std::move(built.world), plan);
  Trajectory t = sim.run();
  CHECK(t.frames.size() == 10);
  CHECK(sim.faults().count(Fault::Kind::NonFinite) == 72);   // every step of 9 frames x 8
  CHECK_THAT(sim.faults().summary(), Catch::StartsWith("72 steps with numerical faults: 72 non-finite state;") &&
                                         Catch::Contains("\"crate\""));
}

TEST_CASE("a healthy drop onto the ground raises no fault", "[faults]") {
  BuiltWorld built = twoBoxes("[3, 0, 4]");
  Simulator sim(std::move(built.world), {built.step, 8, 120});
  sim.run();
  CHECK(sim.faults().total() == 0);
}

TEST_CASE("a body moved in a step farther than its velocities allow is an unexplained-motion fault", "[faults]") {
  // A teleport: the lid, at rest, is found 1 m away one step later. Its speeds allow g dt^2 and
  // the position correction half its thinnest piece (0.5 m).
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  FaultCheck check(built.world);
  Pipeline pipeline(built.world, built.step);
  built.world.time += built.step.dt;
  CHECK_FALSE(check.afterStep(built.world, pipeline, 1));
  built.world.time += built.step.dt;
  built.world.bodies[2].x.x() += 1.0;
  checkFault(check.afterStep(built.world, pipeline, 2), Fault::Kind::UnexplainedMotion, "lid",
             "unexplained motion: body \"lid\" moved by up to 1 m in one step");
}

TEST_CASE("motion at a speed the body had within the step, between two impacts, is explained", "[faults]") {
  // The Baraff model's sub-steps: struck, a body may move fast and be stopped again within one step,
  // at rest at both of its ends. The lid moves 0.6 m (0.1 m more than the correction allows a body
  // at rest) at the speed its model reports it moved at within the step.
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  const double dt = built.step.dt;
  MotionCheck check(built.world, extentsOf(built.world), FaultSettings{}.depth_share);
  built.world.bodies[2].x.x() += 0.6;
  MotionCheck without = check;
  std::vector<double> peak_speed(built.world.bodies.size(), 0.0), peak_spin(built.world.bodies.size(), 0.0);
  peak_speed[2] = 0.1 / dt;
  CHECK_FALSE(check.afterStep(built.world, dt, peak_speed, peak_spin));
  const std::optional<UnexplainedMotion> m = without.afterStep(built.world, dt);
  REQUIRE(m);
  CHECK(m->body == 2);
}

TEST_CASE("a turn no spin explains is an unexplained-motion fault too", "[faults]") {
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  FaultCheck check(built.world);
  Pipeline pipeline(built.world, built.step);
  built.world.time += built.step.dt;
  // 90 degrees about z: the lid's corners (0.87 m from its centre) move by 1.2 m.
  built.world.bodies[2].q = Eigen::Quaterniond(Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitZ()));
  checkFault(check.afterStep(built.world, pipeline, 1), Fault::Kind::UnexplainedMotion, "lid", "moved by up to 1.2");
}

TEST_CASE("energy risen above the lowest it reached in a passive scene is an energy-gain fault", "[faults]") {
  // 100 J of kinetic energy from nowhere: far below the runaway limit (~8.5 kJ), far above the
  // tolerance (1e-3 of the 100 J in play plus 2000 kg g 1e-4 m = 2 J).
  BuiltWorld built = twoBoxes("[5, 0, 0.5]");
  FaultCheck check(built.world);
  Pipeline pipeline(built.world, built.step);
  CHECK_FALSE(check.afterStep(built.world, pipeline, 1));
  RigidBody& crate = built.world.bodies[1];
  crate.P = crate.mass * Eigen::Vector3d(0, 0, std::sqrt(2 * 100 / crate.mass));
  checkFault(check.afterStep(built.world, pipeline, 2), Fault::Kind::EnergyGain, "crate",
             "energy gain: the total rose 100 J above the lowest it reached");
}

TEST_CASE("energy paid back within the model's delay is no gain, later it is", "[faults]") {
  // The crate moving at 1 m/s (500 J) loses its speed for one step and gets it back, as a bounce
  // of the time-stepping model does (one step late).
  for (int repaid_within : {1, 0}) {
    BuiltWorld built = twoBoxes("[5, 0, 0.5]");
    RigidBody& crate = built.world.bodies[1];
    const Eigen::Vector3d moving = crate.mass * Eigen::Vector3d(1, 0, 0);
    crate.P = moving;
    EnergyCheck check(built.world, 1e-3, 1e-4, repaid_within);
    CHECK_FALSE(check.afterStep(built.world));
    crate.P.setZero();
    CHECK_FALSE(check.afterStep(built.world));
    crate.P = moving;
    INFO("repaid within " << repaid_within << " steps");
    CHECK(check.afterStep(built.world).has_value() == (repaid_within == 0));
  }
}

TEST_CASE("a healthy drop and a knock-down raise no unexplained motion or energy gain", "[faults]") {
  for (ContactModel model : {ContactModel::Baraff, ContactModel::TimeStepping}) {
    Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/knockdown.json");
    scene.simulation.step.model = model;
    BuiltWorld built = buildWorld(scene);
    Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, 90});
    sim.run();
    CHECK(sim.faults().total() == 0);
  }
}
