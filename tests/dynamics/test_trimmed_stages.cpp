// Model only what a scene needs: a stage with nothing to do in a scene does not run, its counter
// stays at zero, and leaving it out changes no bit of the motion.
#include <catch2/catch.hpp>

#include <cstring>

#include "dynamics/pipeline.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

BodySpec ground(double friction) {
  BodySpec g;
  g.name = "ground";
  g.shape = ShapeKind::Plane;
  g.is_static = true;
  g.friction = friction;
  return g;
}

BodySpec box(const std::string& name, const Eigen::Vector3d& at, double friction) {
  BodySpec b;
  b.name = name;
  b.box_size_m = {0.2, 0.2, 0.2};
  b.position_m = at;
  b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 0).normalized()));
  b.velocity_m_s = {1, 0, 0};
  b.friction = friction;
  return b;
}

World worldOf(std::vector<BodySpec> bodies, const Eigen::Vector3d& gravity = {0, 0, -9.81}) {
  Scene scene;
  scene.bodies = std::move(bodies);
  scene.simulation.gravity_m_s2 = gravity;
  return buildWorld(scene).world;
}

struct Run {
  World world;
  ContactDetector::Work work;
  PipelineCounters counters;
  double detect_s = 0;
};

Run run(World world, int steps) {
  StepSettings s;
  Pipeline pipeline(world, s);
  for (int k = 1; k <= steps; ++k) {
    pipeline.step(world, s);
    world.time = k * s.dt;
  }
  return {world, pipeline.detectionWork(), pipeline.counters(), pipeline.profile()[Detect].seconds};
}

bool sameState(const RigidBody& a, const RigidBody& b) {
  return std::memcmp(a.x.data(), b.x.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.P.data(), b.P.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.L.data(), b.L.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.q.coeffs().data(), b.q.coeffs().data(), sizeof(double) * 4) == 0;
}

}  // namespace

TEST_CASE("one body on the ground runs no broad phase, and its motion is bit for bit the one with the broad phase running",
          "[trim]") {
  const Run alone = run(worldOf({ground(0.5), box("box", {0, 0, 0.5}, 0.5)}), 240);
  // A static box 100 m away gives the broad phase a pair to sweep every step, and nothing to find.
  const Run swept = run(worldOf({ground(0.5), box("box", {0, 0, 0.5}, 0.5), [] {
                                   BodySpec far = box("far", {100, 0, 0.1}, 0.5);
                                   far.is_static = true;
                                   return far;
                                 }()}),
                        240);
  CHECK(alone.work.broad_phase_runs == 0);
  CHECK(swept.work.broad_phase_runs > 0);
  CHECK(sameState(alone.world.bodies[1], swept.world.bodies[1]));
}

TEST_CASE("every friction coefficient zero: no frictional contact is found, so no friction row is built", "[trim]") {
  const Run frictionless = run(worldOf({ground(0), box("box", {0, 0, 0.5}, 0)}), 240);
  const Run rough = run(worldOf({ground(0.5), box("box", {0, 0, 0.5}, 0.5)}), 240);
  CHECK(frictionless.work.frictional_contacts == 0);
  CHECK(rough.work.frictional_contacts > 0);
}

TEST_CASE("nothing can touch: no detection, no broad phase, no back-step", "[trim]") {
  const Run spin = run(worldOf({box("a", {0, 0, 0}, 0.5)}, Eigen::Vector3d::Zero()), 240);
  CHECK(spin.work.broad_phase_runs == 0);
  CHECK(spin.counters.back_steps == 0);
  CHECK(spin.detect_s == 0);
}

TEST_CASE("static bodies are never integrated: fifty of them add no integration, and change no bit of the motion",
          "[trim]") {
  // One box flying free in no gravity, far from everything: one sub-step per step, one body each.
  const Run alone = run(worldOf({box("box", {0, 0, 0}, 0.5)}, Eigen::Vector3d::Zero()), 240);
  std::vector<BodySpec> crowd{box("box", {0, 0, 0}, 0.5)};
  for (int i = 0; i < 50; ++i) {
    BodySpec wall = box("wall_" + std::to_string(i), {200.0 + i, 50, 0}, 0.5);
    wall.is_static = true;
    crowd.push_back(wall);
  }
  const Run walled = run(worldOf(crowd, Eigen::Vector3d::Zero()), 240);
  CHECK(alone.counters.bodies_integrated == 240);
  CHECK(walled.counters.bodies_integrated == 240);
  CHECK(sameState(alone.world.bodies[0], walled.world.bodies[0]));
}
