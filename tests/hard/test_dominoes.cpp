// Hard case 12 (docs/hard-cases.md): a chain of 30 dominoes, the first tipped past its critical
// angle: all fall, in order, and the speed of the wave agrees within 1 % between dt and dt/2.
// Horizon 3.5 s (the wave reaches the last domino at about 2.35 s); two runs, about 5 minutes of
// wall time together on the 2-core machine (about 13 sub-steps per step, 91 % in the resting solve).
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

#include "hard_run.h"

using namespace tumble;

namespace {

constexpr int kDominoes = 30;
constexpr double kSpacing = 0.1, kFallenDeg = 30;

// The time each domino's tilt passes 30 deg, interpolated linearly within the step (-1: never).
std::vector<double> fallTimes(int dt_divisor) {
  Scene scene = hard::loadHardScene("dominoes");
  scene.simulation.step.dt /= dt_divisor;
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

// Each run at most once per process, and only when a case asks for it: index 0 at dt, 1 at dt/2.
// Lazy, so that one run can be checked alone (a sanitizer build runs the two in two processes,
// side by side: together they take hours there).
const std::vector<double>& runAt(int divisor) {
  static std::optional<std::vector<double>> runs[2];
  if (!runs[divisor - 1]) runs[divisor - 1] = fallTimes(divisor);
  return *runs[divisor - 1];
}

void checkAllFallInOrder(int divisor) {
  const std::vector<double>& fell = runAt(divisor);
  for (int i = 0; i < kDominoes; ++i) {
    INFO("dt/" << divisor << ": domino " << i + 1 << " fell at " << fell[i] << " s");
    CHECK(fell[i] > 0);
    if (i > 0) CHECK(fell[i] > fell[i - 1]);
  }
}

}  // namespace

// The three cases read the same two simulations; CTest runs them in one process
// (tests/hard/CMakeLists.txt), so each simulation runs once.
TEST_CASE("dominoes: all 30 fall, in order, at dt", "[hard][dominoes]") { checkAllFallInOrder(1); }

TEST_CASE("dominoes: all 30 fall, in order, at dt/2", "[hard][dominoes]") { checkAllFallInOrder(2); }

// The least-squares speed over dominoes 5-30, fall times interpolated within the step. A known
// failure, and a fragile figure: 1.19 % at d1ee62c (2026-11-23), 0.75 % at 0a8f771 (2026-11-23),
// 1.56 % at f3ae70d (2026-11-23, the drift projection), 1.96 % at def6d4b (2026-11-24: 1.49024
// against 1.46165 m/s), where only islands too large to pivot go to the velocity-level solve, and
// 2.67 % at 570eaf9 (2026-11-24: 1.50088 against 1.46191 m/s), where the drift correction refuses
// displacements out of proportion to the lift.
// Also sending pivoting solves that stop short there gave 0.35 %, then 1.37 % after a change at
// rounding level only (5be4f35, 2026-11-24), then 7.5 % with dynamic-friction failures left to
// boxed friction: the chain amplifies small differences in its resting solves to percents of its
// wave speed.
// It passes since the resting solve's normal rows stop the drift of a pivot's normal speed
// (baraff/resting_forces.cpp, stopNormalDrift) and a lift-off settles only when the step cannot
// follow it (settleRule): 0.12 % (2026-11-24: 1.49683 against 1.49865 m/s); 0.070 % (1.4987 against
// 1.49766 m/s) with the arches' subspace steps (active_set_step.h); 0.13 % (1.49693 against
// 1.49883 m/s) with the debris wall's back-stepping. A domino tipping on
// its edge is a rocking block; its pivot's drift was a step-size error of first order.
TEST_CASE("dominoes: the wave speed agrees within 1 % between dt and dt/2",
          "[hard][dominoes]") {
  double coarse = waveSpeed(runAt(1)), fine = waveSpeed(runAt(2));
  INFO("wave speed " << coarse << " m/s at dt, " << fine << " m/s at dt/2: " << 100 * (coarse / fine - 1) << " %");
  CHECK(std::abs(coarse / fine - 1) < 0.01);
}
