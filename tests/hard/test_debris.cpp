// Debris (scenes/hard/debris_wall.json, written by tools/make-debris-wall): a steel ball, radius
// 0.25 m and 7850 kg/m^3, at 120 m/s into a dry-stone wall of 100 convex fragments (2.4 x 0.3 x
// 1.2 m, 2000 kg/m^3, neighbours 0.1 mm apart) standing on the ground, dt = 1 ms, both contact
// models. Many fast first contacts at once, pieces thrown into each other, a pile landing.
//
// Criteria, over 0.4 s:
// - no pair of bodies overlaps by more than 1 mm after any step (the acceptance bound for
//   overlaps), measured exactly (separating-axis depth of every pair whose boxes meet);
// - the run-time fault check stays silent (it stops the run on a deep overlap, a body moved farther
//   than its speeds allow or energy from nowhere, so the run must not throw);
// - over the first 0.1 s the horizontal momentum of all moving bodies stays within 1 % of the
//   ball's, on a frictionless ground. Ground friction is the one horizontal force from outside,
//   and with it the wall's lowest course is not out of play: the impact reaches it through the
//   courses above (it slides at up to 3 m/s with time stepping, 7 m/s with the Baraff model), and
//   friction takes 0.7 % (Baraff) to 1.8 % (time stepping) of the ball's momentum within 0.1 s,
//   against at most mu M g t = 848 N s, 1.4 %, of a whole wall sliding the whole time (the time-
//   stepping model's landings press harder than the weight). That is physics, not an error, and it
//   would hide one, so the momentum is held on a second run with the ground's friction 0, where
//   nothing from outside pushes sideways and the law is exact: there the error is 1e-7 of the
//   ball's momentum or less (measured 2026-11-24). Overlaps and faults are checked on both runs.
// It prints the deepest overlap, the largest energy rise above the running lowest (as a share of
// the energy in play), the momentum error and the wall time per simulated second.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <vector>

#include "../dynamics/contact_scene_runner.h"

using namespace tumble;

namespace {

constexpr double kOverlapBound = 1e-3;     // m, the acceptance bound for overlaps
constexpr double kMomentumShare = 0.01;    // of the ball's momentum, over the first 0.1 s
constexpr double kMomentumWindow = 0.1;    // s
constexpr double kSeconds = 0.4;           // s simulated
constexpr double kLowestCourseTop = 0.24;  // m: fragments whose centre lies below stand on the ground

struct Watched {
  double deepest = 0;          // m: deepest overlap after any step
  double deepest_at = 0;       // s: when
  int steps_over = 0;          // steps that ended with an overlap above the bound
  double largest_rise = 0;     // share of the energy scale: the total energy above its running lowest
  double momentum_error = 0;   // share of the ball's momentum, over the first 0.1 s
  double lowest_course_speed = 0;   // m/s: fastest horizontal speed of a ground-standing fragment, first 0.1 s
  double wall_per_sim = 0;     // s of wall time per simulated s
  bool faulted = false;
};

Eigen::Vector2d horizontalMomentum(const World& world) {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (const RigidBody& b : world.bodies)
    if (!b.is_static) p += b.P.head<2>();
  return p;
}

Watched watch(ContactModel model, bool frictionless_ground) {
  Watched w;
  test::EnergyRise energy;
  Eigen::Vector2d p0 = Eigen::Vector2d::Zero();
  std::vector<char> on_ground;
  auto on_step = [&](const World& world) {
    if (on_ground.empty()) {
      // After the first step the ball is still in free flight (it meets the wall at 6.25 ms), so
      // the momentum is what the scene gave it, and the wall stands as built.
      p0 = horizontalMomentum(world);
      for (const RigidBody& b : world.bodies)
        on_ground.push_back(!b.is_static && b.name != "ball" && b.x.z() < kLowestCourseTop);
    }
    const double depth = test::worldPenetration(world);
    if (depth > w.deepest) w.deepest = depth, w.deepest_at = world.time;
    if (depth > kOverlapBound) ++w.steps_over;
    energy.add(world);
    w.largest_rise = energy.largest();
    if (world.time <= kMomentumWindow + 1e-9) {
      w.momentum_error = std::max(w.momentum_error, (horizontalMomentum(world) - p0).norm() / p0.norm());
      for (std::size_t i = 0; i < world.bodies.size(); ++i)
        if (on_ground[i])
          w.lowest_course_speed = std::max(w.lowest_course_speed, world.bodies[i].P.head<2>().norm() / world.bodies[i].mass);
    }
  };
  const auto start = std::chrono::steady_clock::now();
  try {
    // The overlap is measured in on_step, every step; runScene's own measure only at the end.
    test::runScene("hard/debris_wall", kSeconds, on_step, 1 << 30, [&](Scene& s) {
      s.simulation.step.model = model;
      for (BodySpec& b : s.bodies)
        if (frictionless_ground && b.shape == ShapeKind::Plane) b.friction = 0;
    });
  } catch (const std::exception& e) {
    w.faulted = true;
    UNSCOPED_INFO("run-time fault: " << e.what());
  }
  w.wall_per_sim = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / kSeconds;
  return w;
}

void report(const char* run, const Watched& w) {
  UNSCOPED_INFO(run << ": deepest overlap " << w.deepest << " m at t = " << w.deepest_at << " s, " << w.steps_over
                    << " steps above 1 mm; largest energy rise " << w.largest_rise
                    << " of the scale; horizontal momentum off by " << w.momentum_error
                    << " of the ball's within 0.1 s (lowest course at most " << w.lowest_course_speed
                    << " m/s); " << w.wall_per_sim << " s wall per simulated s (exact overlaps of every "
                    << "step included)");
}

void checkDebris(ContactModel model) {
  const Watched scene = watch(model, false), frictionless = watch(model, true);
  report("as the scene is", scene);
  report("frictionless ground", frictionless);
  for (const Watched* w : {&scene, &frictionless}) {
    CHECK_FALSE(w->faulted);
    CHECK(w->deepest < kOverlapBound);
    CHECK(w->steps_over == 0);
  }
  CHECK(frictionless.momentum_error < kMomentumShare);
}

}  // namespace

TEST_CASE("debris wall, Baraff: a steel ball through 100 fragments, no overlap above 1 mm, no fault, "
          "momentum kept to 1 %",
          "[hard][debris]") {
  checkDebris(ContactModel::Baraff);
}

// The blow sets the two halves of a brick sliding along each other at 8 m/s and turning at
// 60-80 rad/s within one step. The rows hold their points to first order, but the halves' shared
// face turns by 0.06 rad in the step, and the slide closes it by about |w| |v_t| dt^2: up to
// 1.4 mm at a step's end while the drift projection ran at the start of the next step. It runs at
// the end of each step now (time_stepping_model.h), so no step ends that deep.
TEST_CASE("debris wall, time stepping: a steel ball through 100 fragments, no overlap above 1 mm, no fault, "
          "momentum kept to 1 %",
          "[hard][debris][time_stepping]") {
  checkDebris(ContactModel::TimeStepping);
}
