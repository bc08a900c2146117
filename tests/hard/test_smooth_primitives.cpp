// Hard cases 20 and 21 (docs/hard-cases.md): exact spheres and capsules (rounded pieces,
// collision/rounded_contact.cpp) against closed forms, with both contact models.
//
// A ball launched sliding (scenes/hard/ball_rolling.json): slides until t* = 2 v0 / (7 mu g), then
// rolls at 5/7 v0. Tolerances: the roll must start within one step of t* (friction acts per step,
// so the slip ends in the step that holds t*); the rolling speed to 1e-9 m/s and the centre's
// height to 1e-9 m (the bound): the stick conserves angular momentum about the contact
// exactly and nothing lifts or presses an exact sphere, so only rounding is left (about 1e-15).
//
// A capsule lying on a box (scenes/hard/capsule_on_box.json): held along its length it must not
// rock. Tolerance 1e-9 rad of turn over 10 s: resting exactly on two points, it turns only by
// rounding.
#include <catch2/catch.hpp>

#include <cmath>

#include "../dynamics/contact_scene_runner.h"

using namespace tumble;

namespace {

constexpr double kG = 9.81, kV0 = 2, kMu = 0.3, kRadius = 0.1, kDt = 1.0 / 240;

struct Rolling {
  double rolls_from = -1;          // s: first step whose contact no longer slips
  double speed_error = 0;          // m/s: |v - 5/7 v0| once rolling
  double height_error = 0;         // m: |z - r| once rolling
  double overlap = 0;
};

Rolling launchBall(ContactModel model) {
  Rolling out;
  auto run = test::runScene(
      "hard/ball_rolling", 1.5,
      [&](const World& w) {
        const RigidBody& ball = w.bodies[1];
        const double slip = ball.velocity().x() - ball.angularVelocity().y() * kRadius;
        if (out.rolls_from < 0 && std::abs(slip) < 1e-9) out.rolls_from = w.time;
        if (out.rolls_from < 0) return;
        out.speed_error = std::max(out.speed_error, std::abs(ball.velocity().norm() - 5.0 / 7.0 * kV0));
        out.height_error = std::max(out.height_error, std::abs(ball.x.z() - kRadius));
      },
      1, [&](Scene& s) { s.simulation.step.model = model; });
  out.overlap = run.max_penetration;
  return out;
}

void checkRolling(const Rolling& r) {
  const double t_star = 2 * kV0 / (7 * kMu * kG);
  INFO("rolls from " << r.rolls_from << " s (t* = " << t_star << " s), speed error " << r.speed_error
                     << " m/s, height error " << r.height_error << " m, overlap " << r.overlap << " m");
  REQUIRE(r.rolls_from > 0);
  CHECK(std::abs(r.rolls_from - t_star) <= kDt);
  CHECK(r.speed_error < 1e-9);
  CHECK(r.height_error < 1e-9);
}

double capsuleTurn(ContactModel model) {
  double turn = 0;
  Eigen::Quaterniond start;
  bool first = true;
  test::runScene(
      "hard/capsule_on_box", 10,
      [&](const World& w) {
        const RigidBody& pill = w.bodies[2];
        if (first) start = pill.q, first = false;
        turn = std::max(turn, pill.q.angularDistance(start));
      },
      1, [&](Scene& s) { s.simulation.step.model = model; });
  return turn;
}

}  // namespace

TEST_CASE("a ball launched sliding rolls from t* at 5/7 v0, its centre level (Baraff)", "[hard][rounded]") {
  checkRolling(launchBall(ContactModel::Baraff));
}

TEST_CASE("a ball launched sliding rolls from t* at 5/7 v0, its centre level (time stepping)",
          "[hard][rounded][time_stepping]") {
  checkRolling(launchBall(ContactModel::TimeStepping));
}

TEST_CASE("a capsule lying on a box stays still for 10 s (Baraff)", "[hard][rounded]") {
  const double turn = capsuleTurn(ContactModel::Baraff);
  INFO("largest turn " << turn << " rad");
  CHECK(turn < 1e-9);
}

TEST_CASE("a capsule lying on a box stays still for 10 s (time stepping)", "[hard][rounded][time_stepping]") {
  const double turn = capsuleTurn(ContactModel::TimeStepping);
  INFO("largest turn " << turn << " rad");
  CHECK(turn < 1e-9);
}
