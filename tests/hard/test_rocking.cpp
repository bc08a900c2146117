// Rocking block (scenes/hard/rocking_block.json; G. W. Housner, "The behavior of inverted pendulum
// structures during earthquakes", Bulletin of the Seismological Society of America, 1963). A rigid
// block of half-width b and half-height h, tilted and released, rocks about its bottom edges. Each
// landing is a plastic impact about the landing edge; angular momentum about that edge is kept,
// so the angular speed falls by
//     r = omega+ / omega- = 1 - 1.5 sin^2 alpha,   alpha = atan(b / h),
// the same for every size of block: the law has no length in it, and neither may the simulation.
//
// Measured without timing the impacts: between landings the block turns about one edge without
// slipping, so its energy E = KE + m g (z - h) is constant, and when it passes upright its kinetic
// energy is (1/2) I_edge omega^2. So omega+ / omega- = sqrt(E_after / E_before), with E read on the
// plateaus: at the end of the step before the one in which the block passes upright, and one step
// after it (a step can end exactly at the landing, which the next step resolves; one more step
// for the time-stepping model, which gives a landing's impulse a step late).
//
// Which impacts: the rocking is a Zeno sequence, infinitely many landings in a finite time, and
// the tail below what the step can follow settles (a lift-off that gravity ends within 4 dt is not
// kept: settleRule, baraff/impulse_propagation.h). Every landing whose next swing lasts 8 dt or more by
// the law (twice the rule's bound: the rule estimates the swing to first order) must keep
// Housner's ratio within 1 %. The swing after a landing at omega+ is, for the rocking equation
// linearised in the tilt (theta'' = p^2 (theta - alpha), p^2 = m g R / I_edge = 3 g / 4 R, R the
// half-diagonal), t = (2 / p) artanh(omega+ / (p alpha)).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <vector>

#include "hard_run.h"

using namespace tumble;

namespace {

struct Rocking {
  std::vector<double> energy;   // J: KE + m g (z - h), after every step
  std::vector<double> lean;     // the long axis' lean along x (signed), after every step
  double dt = 0, mass = 0, b = 0, h = 0;
};

// The scene's block scaled to `height_m` (mass with the volume), tilted about its bottom edge at
// x = +b by alpha / 2 and released at rest.
Rocking rock(double height_m, ContactModel model, double seconds) {
  Scene scene = hard::loadHardScene("rocking_block");
  scene.simulation.step.model = model;
  BodySpec& block = scene.bodies[1];
  const double s = height_m / block.box_size_m.z();
  block.box_size_m *= s;
  block.mass_kg = *block.mass_kg * s * s * s;
  Rocking out;
  out.b = block.box_size_m.x() / 2;
  out.h = block.box_size_m.z() / 2;
  out.mass = *block.mass_kg;
  out.dt = scene.simulation.step.dt;
  block.orientation = Eigen::AngleAxisd(std::atan(out.b / out.h) / 2, Eigen::Vector3d::UnitY());
  block.position_m = Eigen::Vector3d(out.b, 0, 0) + block.orientation * Eigen::Vector3d(-out.b, 0, out.h);
  hard::simulate(scene, seconds, [&](const World& w) {
    const RigidBody& body = w.bodies[1];
    out.energy.push_back(body.kineticEnergy() - body.mass * w.gravity.dot(body.x) - body.mass * w.gravity.norm() * out.h);
    int k = 0;   // the long axis: the principal axis of the smallest moment
    for (int i = 1; i < 3; ++i)
      if (body.inertia_body[i] < body.inertia_body[k]) k = i;
    const Eigen::Vector3d axis = body.rotation().col(k);
    out.lean.push_back(axis.z() > 0 ? axis.x() : -axis.x());
    return true;
  });
  return out;
}

struct Impact {
  double time = 0, ratio = 0, swing_s = 0;   // s, -, s (the law's swing after it)
};

std::vector<Impact> impacts(const Rocking& r, int late_steps) {
  const double g = 9.81, alpha = std::atan(r.b / r.h), R = std::hypot(r.b, r.h);
  const double inertia = 4.0 / 3.0 * r.mass * R * R, p = std::sqrt(3 * g / (4 * R));
  const double law = 1 - 1.5 * std::pow(std::sin(alpha), 2);
  std::vector<Impact> out;
  for (std::size_t k = 2; k + 1 + late_steps < r.energy.size(); ++k) {
    if ((r.lean[k] > 0) == (r.lean[k - 1] > 0)) continue;
    const double before = r.energy[k - 1], after = r.energy[k + 1 + late_steps];
    if (!(before > 0)) break;
    const double omega_after = law * std::sqrt(2 * before / inertia);
    const double swing = omega_after < p * alpha ? 2 / p * std::atanh(omega_after / (p * alpha)) : INFINITY;
    out.push_back({static_cast<double>(k) * r.dt, std::sqrt(std::max(0.0, after) / before), swing});
  }
  return out;
}

// The impacts resolvable at the step (law's swing >= 8 dt) and the worst relative error of their
// ratio against Housner's.
struct Verdict {
  int resolvable = 0;
  double worst = 0;
  std::string table;
};

Verdict judge(double height_m, ContactModel model) {
  const Rocking r = rock(height_m, model, 20 * std::sqrt(height_m / 1.5));
  const double law = 1 - 1.5 * std::pow(std::sin(std::atan(r.b / r.h)), 2);
  Verdict v;
  std::ostringstream table;
  for (const Impact& i : impacts(r, model == ContactModel::TimeStepping ? 1 : 0)) {
    if (i.swing_s < 8 * r.dt) break;
    ++v.resolvable;
    v.worst = std::max(v.worst, std::abs(i.ratio / law - 1));
    table << "  t " << i.time << " s: ratio " << i.ratio << " (law " << law << ")\n";
  }
  v.table = table.str();
  return v;
}

void checkHousner(ContactModel model) {
  for (double height : {0.05, 0.15, 0.5, 1.5, 5.0}) {
    const Verdict v = judge(height, model);
    INFO("block " << height << " m tall: " << v.resolvable << " resolvable impacts, worst " << 100 * v.worst
                  << " % off Housner's ratio\n" << v.table);
    CHECK(v.resolvable >= 5);
    CHECK(v.worst < 0.01);
  }
}

}  // namespace

TEST_CASE("rocking block, Baraff: Housner's ratio within 1 % at every resolvable impact, 0.05 m to 5 m",
          "[hard][rocking]") {
  checkHousner(ContactModel::Baraff);
}

// Known failure. The time-stepping model resolves a landing at the end of the step that closes
// it, after gravity has acted over the whole step with the block still turning about the old edge,
// and with one impulse problem for the landing and the lift-off together; the ratios scatter from
// 0.52 to 0.84 (measured 2026-11-24 at dt = 1/240 s: worst 38 % off at 0.05 m, 22 % at 0.15 m,
// 24 % at 0.5 m, 20 % at 1.5 m, 8.2 % at 5 m). A first-order method needs many steps per swing to
// follow a rocking law; use the Baraff model for rocking.
TEST_CASE("rocking block, time stepping: Housner's ratio within 1 % at every resolvable impact, 0.05 m to 5 m "
          "(reached: 38 %)",
          "[hard][rocking][time_stepping][!shouldfail]") {
  checkHousner(ContactModel::TimeStepping);
}
