// Hard case 12 (issue 6): a chain of 30 dominoes, the first tipped past its critical angle: all
// fall, in order, and the speed of the wave agrees within 1 % between dt and dt/2.
// Horizon 3.5 s (the wave reaches the last domino at about 2.35 s); two runs, about 20 s of wall
// time together on the 2-core machine.
#include <catch2/catch.hpp>

#include <cmath>

#include "hard_run.h"

using namespace tumble;

namespace {

constexpr int kDominoes = 30;
constexpr double kSpacing = 0.1, kFallenDeg = 30;

// The time each domino's tilt passes 30 deg, interpolated linearly within the step (-1: never).
std::vector<double> fallTimes(int dt_divisor) {
  Scene scene = hard::loadHardScene("dominoes");
  scene.simulation.dt_s /= dt_divisor;
  scene.simulation.steps_per_frame *= dt_divisor;
  BuiltWorld start = buildWorld(scene);
  std::vector<double> fell(kDominoes, -1), previous(kDominoes, 0);
  double previous_time = 0;
  hard::simulate(scene, 3.5, [&](const World& w) {
    for (int i = 0; i < kDominoes; ++i) {
      double tilt = Eigen::AngleAxisd(start.world.bodies[i + 1].q.inverse() * w.bodies[i + 1].q).angle() * 180 / M_PI;
      if (fell[i] < 0 && tilt > kFallenDeg)
        fell[i] = previous_time + (kFallenDeg - previous[i]) / (tilt - previous[i]) * (w.time - previous_time);
      previous[i] = tilt;
    }
    previous_time = w.time;
    return true;
  });
  return fell;
}

// Least-squares speed (m/s) of the wave over dominoes 5..30, past the start-up of the first few.
double waveSpeed(const std::vector<double>& fell) {
  double n = 0, sx = 0, st = 0, sxx = 0, sxt = 0;
  for (int i = 4; i < kDominoes; ++i) {
    double x = kSpacing * i;
    n += 1, sx += x, st += fell[i], sxx += x * x, sxt += x * fell[i];
  }
  double slope = (n * sxt - sx * st) / (n * sxx - sx * sx);   // s per m
  return 1 / slope;
}

// The two runs, once per test run (both test cases read them): index 0 at dt, 1 at dt/2.
const std::vector<double>& runAt(int divisor) {
  static const std::vector<double> runs[2] = {fallTimes(1), fallTimes(2)};
  return runs[divisor - 1];
}

}  // namespace

TEST_CASE("dominoes: all 30 fall, in order, at dt and dt/2", "[hard][dominoes]") {
  for (int divisor : {1, 2}) {
    const std::vector<double>& fell = runAt(divisor);
    for (int i = 0; i < kDominoes; ++i) {
      INFO("dt/" << divisor << ": domino " << i + 1 << " fell at " << fell[i] << " s");
      CHECK(fell[i] > 0);
      if (i > 0) CHECK(fell[i] > fell[i - 1]);
    }
  }
}

// Was a known failure at 1.19 % (1.48079 m/s at dt = 1/240 against 1.46334 m/s at 1/480) until
// back-stepping stopped bisecting on impacts the narrow phase had missed at the start of a step
// (pipeline.cpp, "too deep to go back for") and failed pivoting solves stopped being used as they
// were (contact_solver.cpp): 1.45227 against 1.44150 m/s, 0.75 %. The least-squares speed over
// dominoes 5-30, fall times interpolated within the step.
//
// Known failure again since session 5: 1.48456 against 1.46180 m/s, 1.56 %. The projection that
// turns a landing pair about its resting points and holds them at half the tolerance (it fixed
// the rocking box, the 10000:1 stack and the pile's overlaps: position_projection.h) moves the
// leaning dominoes differently at the two steps. With the resting points left where they were
// the wave agreed (0.75 %) but the 1000:1 stack blew up at dt = 1/60 and the pile overlapped by
// 3.5 mm; that trade was judged the worse one.
TEST_CASE("dominoes: the wave speed agrees within 1 % between dt and dt/2 (reached: 1.56 %)",
          "[hard][dominoes][!shouldfail]") {
  double coarse = waveSpeed(runAt(1)), fine = waveSpeed(runAt(2));
  INFO("wave speed " << coarse << " m/s at dt, " << fine << " m/s at dt/2: " << 100 * (coarse / fine - 1) << " %");
  CHECK(std::abs(coarse / fine - 1) < 0.01);
}
