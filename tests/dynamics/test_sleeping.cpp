// Sleeping (dynamics/sleeping.h): islands at rest freeze, anything awake that touches them wakes
// them, and a body coasting free is never frozen. Both contact models.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact_scene_runner.h"
#include "scene/scene.h"

using namespace tumble;
using tumble::test::runScene;

namespace {

void sleepOn(Scene& s, ContactModel model) {
  s.simulation.step.sleep.enabled = true;
  s.simulation.step.model = model;
}

// scenes/rest.json with a second unit cube, 1 kg, inelastic, dropped from its bottom face 3.5 m
// above the resting cube's top: it lands at sqrt(2 * 3.5 / 9.81) = 0.845 s, after the resting
// cube has slept (0.5 s of quiet from the start).
void dropCubeOnTop(Scene& s) {
  BodySpec top = s.bodies[1];
  top.name = "dropped";
  top.position_m = {0, 0, 1 + 3.5 + 0.5};
  s.bodies.push_back(top);
}

}  // namespace

TEST_CASE("sleeping: a cube at rest on the ground falls asleep, exactly still, where it was", "[contact][sleep]") {
  const ContactModel model = GENERATE(ContactModel::Baraff, ContactModel::TimeStepping);
  INFO((model == ContactModel::Baraff ? "Baraff" : "time stepping"));
  double asleep_at = -1;
  auto run = runScene("rest", 2, [&](const World& w) {
    if (asleep_at < 0 && w.bodies[1].asleep) asleep_at = w.time;
  }, 1, [&](Scene& s) { sleepOn(s, model); });
  // Quiet from the first step, so asleep once after_s (0.5 s) of quiet has been counted.
  CHECK(asleep_at == Approx(0.5).margin(2.0 / 240));
  const BodySample& end = run.trajectory.frames.back()[1];
  CHECK(end.v == Eigen::Vector3d::Zero());
  CHECK(end.w == Eigen::Vector3d::Zero());
  CHECK((end.x - run.trajectory.frames.front()[1].x).norm() < 1e-6);
  CHECK(run.max_penetration < 1e-6);
}

TEST_CASE("sleeping: a cube landing on a sleeping one wakes it, and both sleep once settled", "[contact][sleep]") {
  const ContactModel model = GENERATE(ContactModel::Baraff, ContactModel::TimeStepping);
  INFO((model == ContactModel::Baraff ? "Baraff" : "time stepping"));
  bool bottom_slept_before_landing = false, bottom_woke = false;
  double both_asleep_at = -1, lowest_bottom = 1;
  auto run = runScene("rest", 3, [&](const World& w) {
    const RigidBody& bottom = w.bodies[1];
    const RigidBody& top = w.bodies[2];
    if (w.time < 0.8 && bottom.asleep) bottom_slept_before_landing = true;
    if (w.time > 0.8 && w.time < 1.0 && !bottom.asleep) bottom_woke = true;
    if (both_asleep_at < 0 && bottom.asleep && top.asleep) both_asleep_at = w.time;
    lowest_bottom = std::min(lowest_bottom, bottom.x.z());
  }, 1, [&](Scene& s) {
    sleepOn(s, model);
    dropCubeOnTop(s);
  });
  CHECK(bottom_slept_before_landing);
  CHECK(bottom_woke);   // had it stayed frozen, the landing would have met a static body
  INFO("both asleep at " << both_asleep_at << " s");
  CHECK(both_asleep_at > 0.85);
  CHECK(both_asleep_at < 3);
  // The landing was solved with the bottom cube awake: it was pressed into the ground (by at
  // most the contact tolerance, and the projection lifts it back), not left floating or static.
  CHECK(run.max_penetration < 1e-5);
  const BodySample& top = run.trajectory.frames.back()[2];
  CHECK(top.x.z() == Approx(1.5).margin(1e-5));
  CHECK(top.v == Eigen::Vector3d::Zero());
}

TEST_CASE("sleeping: a body coasting slowly in free space is never frozen", "[contact][sleep]") {
  // Slower than the sleep thresholds for the whole run, but resting on nothing: it is not at rest.
  const ContactModel model = GENERATE(ContactModel::Baraff, ContactModel::TimeStepping);
  bool ever_asleep = false;
  auto run = runScene("rest", 2, [&](const World& w) { ever_asleep |= w.bodies[1].asleep; }, 1, [&](Scene& s) {
    sleepOn(s, model);
    s.simulation.gravity_m_s2.setZero();
    s.bodies[1].position_m = {0, 0, 3};
    s.bodies[1].velocity_m_s = {0.002, 0, 0};
  });
  CHECK_FALSE(ever_asleep);
  CHECK(run.trajectory.frames.back()[1].x.x() == Approx(0.004).margin(1e-12));
}

TEST_CASE("sleeping: off, a resting cube is simulated to the end", "[contact][sleep]") {
  bool ever_asleep = false;
  runScene("rest", 1, [&](const World& w) { ever_asleep |= w.bodies[1].asleep; });
  CHECK_FALSE(ever_asleep);
}

TEST_CASE("sleeping: falling asleep and waking are deterministic (bit-identical trajectories)", "[contact][sleep][determinism]") {
  auto run = [] {
    return runScene("rest", 2, {}, 1000000, [](Scene& s) {
      sleepOn(s, ContactModel::Baraff);
      dropCubeOnTop(s);
    });
  };
  const test::SceneRun one = run(), two = run();
  REQUIRE(one.trajectory.frames.size() == two.trajectory.frames.size());
  for (std::size_t f = 0; f < one.trajectory.frames.size(); ++f)
    for (std::size_t b = 0; b < one.trajectory.frames[f].size(); ++b) {
      REQUIRE(one.trajectory.frames[f][b].x == two.trajectory.frames[f][b].x);
      REQUIRE(one.trajectory.frames[f][b].q.coeffs() == two.trajectory.frames[f][b].q.coeffs());
      REQUIRE(one.trajectory.frames[f][b].v == two.trajectory.frames[f][b].v);
    }
}
