// Free flight against closed forms: ballistic motion, and torque-free rotation conserving kinetic
// energy and angular momentum, for both integrators.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/simulator.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

// The free-spin benchmark body (docs/bench/scenes.md, S5): a 1.0 x 0.4 x 0.1 m box of 1 kg
// spinning at 5 rad/s about its intermediate (y) axis plus 0.01 rad/s about x, no gravity.
World freeSpinWorld() {
  Scene s = parseScene(R"({"schema_version": 1, "simulation": {"gravity_m_s2": [0, 0, 0]},
    "bodies": [{"shape": "box", "size_m": [1.0, 0.4, 0.1], "mass_kg": 1,
                "position_m": [0, 0, 1], "angular_velocity_rad_s": [0.01, 5.0, 0]}]})", "spin.json");
  return buildWorld(s).world;
}

struct Drift {
  double energy = 0, momentum = 0;   // max relative deviation over the run
  int flips = 0;                     // sign changes of the body-frame spin about y
};

Drift spin(Integrator integrator, double dt, double seconds) {
  World world = freeSpinWorld();
  const RigidBody& b0 = world.bodies[0];
  double E0 = b0.kineticEnergy(), L0 = b0.L.norm();
  StepSettings step;
  step.dt = dt;
  step.integrator = integrator;
  std::vector<Wrench> none(1);
  Drift d;
  double last_wy = 1;
  long steps = std::lround(seconds / dt);
  for (long i = 0; i < steps; ++i) {
    integrate(world, none, step);
    const RigidBody& b = world.bodies[0];
    d.energy = std::max(d.energy, std::abs(b.kineticEnergy() / E0 - 1));
    d.momentum = std::max(d.momentum, std::abs(b.L.norm() / L0 - 1));
    // The box's y axis is principal; which column of R it is depends on the principal sort.
    Eigen::Vector3d w_body = b.rotation().transpose() * b.angularVelocity();
    double wy = w_body[1];
    if (wy * last_wy < 0) ++d.flips;
    last_wy = wy;
  }
  return d;
}

}  // namespace

TEST_CASE("free fall matches the closed form", "[dynamics]") {
  Scene s = parseScene(R"({"schema_version": 1, "render": {"fps": 30, "frames": 61},
    "bodies": [{"shape": "box", "position_m": [0, 0, 10], "velocity_m_s": [1, 0, 5]}]})", "fall.json");
  double t = 2.0;   // frame 61 at 30 fps
  double g = 9.81;
  SECTION("RK4 is exact for a constant force (to rounding)") {
    BuiltWorld built = buildWorld(s);
    Simulator sim(std::move(built.world), {built.step, s.simulation.steps_per_frame, 61});
    Trajectory tr = sim.run();
    Eigen::Vector3d x = tr.frames.back()[0].x;
    CHECK(tr.times.back() == Approx(t).epsilon(1e-15));
    // 1e-9 m: 480 steps of rounding on values of order 10 m leave ~1e-12; far below any visible error.
    CHECK(std::abs(x.x() - (0 + 1 * t)) < 1e-9);
    CHECK(std::abs(x.z() - (10 + 5 * t - 0.5 * g * t * t)) < 1e-9);
  }
  SECTION("semi-implicit Euler has its known first-order offset 1/2 g t dt") {
    s.simulation.step.integrator = Integrator::SemiImplicitEuler;
    BuiltWorld built = buildWorld(s);
    Simulator sim(std::move(built.world), {built.step, s.simulation.steps_per_frame, 61});
    Trajectory tr = sim.run();
    double dt = s.simulation.step.dt;
    // v_{n+1} = v_n - g dt, x_{n+1} = x_n + v_{n+1} dt  =>  x_n = x0 + v0 t - g dt^2 n(n+1)/2.
    double expected = 10 + 5 * t - 0.5 * g * t * t - 0.5 * g * t * dt;
    CHECK(std::abs(tr.frames.back()[0].x.z() - expected) < 1e-9);
  }
}

TEST_CASE("torque-free rotation conserves energy and angular momentum (RK4)", "[dynamics]") {
  // Tolerances are the ones the free-spin scene is held to (test_free_spin_scene.cpp): 1e-6 at
  // dt = 1/600, 1e-4 at dt = 1/240, over 10 s through three intermediate-axis flips.
  Drift fine = spin(Integrator::Rk4, 1.0 / 600, 10);
  CHECK(fine.energy < 1e-6);
  CHECK(fine.momentum < 1e-12);   // L is the state and no torque acts: exact to rounding
  Drift coarse = spin(Integrator::Rk4, 1.0 / 240, 10);
  CHECK(coarse.energy < 1e-4);
  // The Dzhanibekov effect: the reference solution (docs/bench/scenes.md, S5) flips 3 times in 10 s.
  CHECK(fine.flips == 3);
}

TEST_CASE("semi-implicit Euler keeps |L| exactly and energy bounded", "[dynamics]") {
  Drift d = spin(Integrator::SemiImplicitEuler, 1.0 / 240, 10);
  CHECK(d.momentum < 1e-12);
  // First order: the energy error is O(w dt) = 5/240 ~ 2 % at worst; 5 % is its bound here.
  CHECK(d.energy < 0.05);
}

TEST_CASE("the same scene gives bit-identical trajectories", "[dynamics][determinism]") {
  auto run = [] {
    World w = freeSpinWorld();
    StepSettings step;
    step.dt = 1.0 / 240;
    Simulator sim(std::move(w), {step, 8, 90});
    return sim.run();
  };
  Trajectory a = run(), b = run();
  for (std::size_t k = 0; k < a.frames.size(); ++k) {
    REQUIRE(a.frames[k][0].x == b.frames[k][0].x);
    REQUIRE(a.frames[k][0].q.coeffs() == b.frames[k][0].q.coeffs());
    REQUIRE(a.frames[k][0].w == b.frames[k][0].w);
  }
}
