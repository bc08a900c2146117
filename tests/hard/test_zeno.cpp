// Hard case 1 (docs/hard-cases.md): the bouncing ball comes to rest in finite time (Zeno). An exact
// sphere lands on one point.
#include <catch2/catch.hpp>

#include <cmath>

#include "hard_run.h"

using namespace tumble;

namespace {

constexpr double kG = 9.81, kDrop = 1.0;   // m/s^2, m (lowest point above the ground)

struct ZenoOutcome {
  std::vector<double> apexes;     // m, lowest point, of each bounce's ballistic arc
  double rest_from = -1;          // s: start of the final stretch at rest (resting, |v| < 1e-3)
  double max_speed_after = 0;     // m/s, over the final stretch
  double max_gap_after = 0;       // m, |lowest point| over the final stretch
};

ZenoOutcome runZeno(const std::string& scene_name, double seconds) {
  Scene scene = hard::loadHardScene(scene_name);
  ZenoOutcome out;
  double face = 0;   // centre height when the face touches the ground
  bool in_flight = false, measured = false;
  double prev_vz = 0;
  hard::HardRun run = hard::simulate(scene, seconds, [&](const World& w) {
    const RigidBody& ball = w.bodies[1];
    if (face == 0) {
      // the lowest point's distance below the centre (first step, ball still falling): the lowest
      // vertex, lowered by the piece's rounding (all of it for an exact sphere)
      double lowest = INFINITY;
      for (const Eigen::Vector3d& v : ball.pieces[0].vertices) lowest = std::min(lowest, (ball.rotation() * v).z());
      face = ball.pieces[0].radius_m - lowest;
    }
    double z = ball.x.z() - face, vz = ball.velocity().z();
    // A bounce starts when v_z turns upward; the apex of its arc is z + v_z^2 / 2g, exact for
    // ballistic flight (RK4 integrates constant gravity exactly), measured once per bounce.
    if (vz > 0 && prev_vz <= 0) in_flight = true, measured = false;
    if (in_flight && !measured && vz > 0 && z > 1e-5) {
      out.apexes.push_back(z + vz * vz / (2 * kG));
      measured = true;
    }
    if (vz < 0) in_flight = false;
    prev_vz = vz;
    bool resting = ball.velocity().norm() < 1e-3 && std::abs(z) < 1e-5;
    if (!resting) out.rest_from = -1, out.max_speed_after = 0, out.max_gap_after = 0;
    else {
      if (out.rest_from < 0) out.rest_from = w.time;
      out.max_speed_after = std::max(out.max_speed_after, ball.velocity().norm());
      out.max_gap_after = std::max(out.max_gap_after, std::abs(z));
    }
    return true;
  });
  return out;
}

void checkZeno(const ZenoOutcome& out, double e, double seconds) {
  const double T = std::sqrt(2 * kDrop / kG) * (1 + e) / (1 - e);
  REQUIRE(out.apexes.size() >= 5);
  for (int k = 1; k <= 5; ++k) {
    double expected = std::pow(e, 2 * k) * kDrop;
    INFO("apex " << k << ": " << out.apexes[k - 1] << " m, expected " << expected);
    // Within 1e-6 of the closed form: an exact sphere lands where the contact tolerance takes the
    // landing, so an apex may be off by (1 - e^2) times it; the scenes set it to 1e-9 m, below
    // 1e-6 of the fifth apex at e = 0.5 (0.98 mm). Measured 2026-11-24: at most 7.9e-7 relative
    // (e = 0.5, apex 5) and 2.3e-10 (e = 0.9); 2.1e-4 at e = 0.5 with the default 1e-6 m
    // tolerance, and 0.5 % with the icosphere the ball was before.
    CHECK(std::abs(out.apexes[k - 1] - expected) < 1e-6 * expected);
  }
  for (std::size_t k = 1; k < out.apexes.size(); ++k) CHECK(out.apexes[k] <= out.apexes[k - 1]);
  // At rest by T + 0.1 s and to the end of the run, which is 10 s later.
  INFO("at rest from " << out.rest_from << " s; T = " << T << " s");
  CHECK(out.rest_from >= 0);
  CHECK(out.rest_from <= T + 0.1);
  CHECK(seconds >= T + 10.1);
}

}  // namespace

TEST_CASE("zeno: a ball with e = 0.5 bounces e^2k high and is at rest by T + 0.1 s", "[hard][zeno]") {
  const double e = 0.5, seconds = 1.3546 + 10.1 + 1e-3;
  checkZeno(runZeno("zeno_e05", seconds), e, seconds);
}

TEST_CASE("zeno: a ball with e = 0.9 bounces e^2k high and is at rest by T + 0.1 s", "[hard][zeno]") {
  const double e = 0.9, seconds = 8.5790 + 10.1 + 1e-3;
  checkZeno(runZeno("zeno_e09", seconds), e, seconds);
}
