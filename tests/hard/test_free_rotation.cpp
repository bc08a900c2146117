// Hard case 10 (docs/hard-cases.md): torque-free rotation of a box 1.0 x 0.4 x 0.1 m. About the
// intermediate axis it flips (Dzhanibekov) while energy and |L| stay put; about the major or minor
// axis it stays.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "hard_run.h"

using namespace tumble;

namespace {

// Index of the principal axis with the smallest, middle or largest moment.
int axisOfRank(const RigidBody& b, int rank) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return b.inertia_body[i] < b.inertia_body[j]; });
  return order[rank];
}

struct SpinOutcome {
  double energy_drift = 0, momentum_drift = 0;   // max relative |E/E0 - 1|, ||L|/|L0| - 1|
  double energy_gain = 0;                        // max relative E/E0 - 1 (signed, > 0: gained)
  int flips = 0;                                 // sign changes of the body-frame intermediate rate
  double max_axis_deg = 0;                       // largest angle of the spun axis from L
};

SpinOutcome runSpin(Scene scene, double seconds, int spun_rank, Integrator integrator) {
  scene.simulation.step.integrator = integrator;
  SpinOutcome out;
  double e0 = -1, l0 = 0, prev_rate = 0;
  Eigen::Vector3d axis0;
  hard::simulate(scene, seconds, [&](const World& w) {
    const RigidBody& b = w.bodies[0];
    if (e0 < 0) {
      // the first step's values differ from t = 0 by the integrator's error only, so take t = 0's
      // exactly: E and L of the initial state are those the scene set
      BuiltWorld start = buildWorld(scene);
      const RigidBody& s = start.world.bodies[0];
      e0 = s.kineticEnergy();
      l0 = s.L.norm();
      // The axis a torque-free body spins about is fixed in space along L. The body axis nutates
      // around it on a cone of half-angle ~ I_other w_other / (I_spun w_spun) (0.68 deg for the
      // minor axis here), so measured from its own start it would stray twice that with exact
      // dynamics: "stays within 1 deg of the axis" is measured from L.
      axis0 = s.L.normalized();
      prev_rate = (s.rotation().transpose() * s.angularVelocity())[axisOfRank(s, 1)];
    }
    double e = b.kineticEnergy() / e0 - 1;
    out.energy_drift = std::max(out.energy_drift, std::abs(e));
    out.energy_gain = std::max(out.energy_gain, e);
    out.momentum_drift = std::max(out.momentum_drift, std::abs(b.L.norm() / l0 - 1));
    double rate = (b.rotation().transpose() * b.angularVelocity())[axisOfRank(b, 1)];
    if (rate * prev_rate < 0) ++out.flips;
    prev_rate = rate;
    double c = std::abs(b.rotation().col(axisOfRank(b, spun_rank)).dot(axis0));
    out.max_axis_deg = std::max(out.max_axis_deg, std::acos(std::min(1.0, c)) * 180 / M_PI);
    return true;
  });
  return out;
}

}  // namespace

TEST_CASE("free rotation: about the intermediate axis it flips, and RK4 keeps E and |L| to 1e-6", "[hard][free_rotation]") {
  SpinOutcome out = runSpin(hard::loadHardScene("free_rotation_intermediate"), 10, 1, Integrator::Rk4);
  INFO("flips " << out.flips << ", energy drift " << out.energy_drift << ", |L| drift " << out.momentum_drift);
  CHECK(out.flips >= 2);   // the reference (RK4 on Euler's equations, h = 1e-4 s) flips 3 times
  CHECK(out.energy_drift < 1e-6);
  CHECK(out.momentum_drift < 1e-6);
}

TEST_CASE("free rotation: about the major or the minor axis it stays within 1 deg for 100 s", "[hard][free_rotation]") {
  SpinOutcome major = runSpin(hard::loadHardScene("free_rotation_major"), 100, 2, Integrator::Rk4);
  SpinOutcome minor = runSpin(hard::loadHardScene("free_rotation_minor"), 100, 0, Integrator::Rk4);
  INFO("major axis strays " << major.max_axis_deg << " deg, minor " << minor.max_axis_deg << " deg");
  CHECK(major.max_axis_deg < 1);
  CHECK(minor.max_axis_deg < 1);
}

// The midpoint rotation update alone (integrator.cpp) keeps the energy error bounded but not
// one-sided: +5.5e-6 relative at worst over these 10 s (measured before 862001f, 2026-11-23). The
// turn is therefore projected back onto the energy it had before (L untouched), so it never gains;
// it still flips.
TEST_CASE("free rotation: semi-implicit Euler never gains energy", "[hard][free_rotation]") {
  SpinOutcome out = runSpin(hard::loadHardScene("free_rotation_intermediate"), 10, 1, Integrator::SemiImplicitEuler);
  INFO("largest energy gain " << out.energy_gain << " (relative), flips " << out.flips);
  CHECK(out.flips >= 2);
  CHECK(out.energy_gain <= 1e-12);
  CHECK(out.momentum_drift < 1e-12);   // L is the state: |L| is exact up to rounding
}
