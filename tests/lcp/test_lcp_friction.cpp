// Boxed LCPs with friction-dependent bounds (ODE's findex; friction cones as in F. Xiang, "Robot
// Control and Physical Simulation", lecture, UC San Diego CSE 291, 2020): a unit cube on
// a 30° incline, modelled as level ground with gravity tilted by 30° about y, so x points down-slope.
// Hand-derived values (weight W = m g):
//   normal:  Σ f_n = W cos θ (no acceleration along the normal)
//   sticks (mu ≥ tan θ = 0.577): Σ f_x = −W sin θ, every contact acceleration 0, |f_t| ≤ mu f_n
//   slides (mu < tan θ): every f_x = −mu f_n (its lower bound), Σ f_x = −mu W cos θ, the body slides
//     without rotating, so every x-row has w = g (sin θ − mu cos θ) ≠ 0 and y-rows w = 0
#include "contact_jacobian.h"
#include "dynamics/lcp/dantzig_solver.h"
#include "dynamics/lcp/pgs_solver.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace tumble::lcp;
using namespace tumble::lcp::test;

namespace {

constexpr double g = 9.81;
const double theta = std::numbers::pi / 6;

ContactSystem cubeOnIncline(double mu) {
  ContactSystem s;
  s.bodies.push_back({});
  s.gravity = g * Eigen::Vector3d(std::sin(theta), 0, -std::cos(theta));
  addNormalContacts(s, 0, -1, rectangleCorners(0, 0, 0.5, 0.5, -0.5));
  addFrictionRows(s, mu);  // rows 4..11: (x, y) for corner 0, then corner 1, ...
  return s;
}

struct Sums {
  double normal = 0, x = 0, y = 0;
};

Sums sums(const Eigen::VectorXd& f) {
  Sums s;
  for (int i = 0; i < 4; ++i) {
    s.normal += f[i];
    s.x += f[4 + 2 * i];
    s.y += f[5 + 2 * i];
  }
  return s;
}

}  // namespace

TEST_CASE("a cube on a 30 degree incline with mu = 0.7 sticks", "[lcp][friction]") {
  const double mu = 0.7;
  const ContactSystem s = cubeOnIncline(mu);
  const LcpResult r = solveDantzig(s.problem());
  INFO("f = " << r.f.transpose() << "\nw = " << r.w.transpose() << "\npasses = " << r.friction_passes
               << ", pivots = " << r.iterations);
  REQUIRE(r.status == LcpStatus::Solved);
  const Sums t = sums(r.f);
  CHECK(t.normal == Approx(g * std::cos(theta)).epsilon(1e-12));
  CHECK(t.x == Approx(-g * std::sin(theta)).epsilon(1e-12));
  CHECK(std::abs(t.y) <= 1e-12 * g);
  CHECK(r.w.lpNorm<Eigen::Infinity>() <= 1e-12 * g);
  CHECK(s.accelerations(r.f).lpNorm<Eigen::Infinity>() <= 1e-12 * g);
  for (int i = 0; i < 4; ++i) {
    CHECK(r.f[i] >= 0);
    CHECK(std::abs(r.f[4 + 2 * i]) <= mu * r.f[i] * (1 + 1e-12) + 1e-15);
    CHECK(std::abs(r.f[5 + 2 * i]) <= mu * r.f[i] * (1 + 1e-12) + 1e-15);
  }
  CHECK(r.residual.bounds <= 1e-12 * g);
}

TEST_CASE("a cube on a 30 degree incline with mu = 0.3 slides: friction at its bounds", "[lcp][friction]") {
  const double mu = 0.3;
  const ContactSystem s = cubeOnIncline(mu);
  const LcpResult r = solveDantzig(s.problem());
  INFO("f = " << r.f.transpose() << "\nw = " << r.w.transpose() << "\npasses = " << r.friction_passes
               << ", pivots = " << r.iterations);
  REQUIRE(r.status == LcpStatus::Solved);
  const Sums t = sums(r.f);
  const double slide = g * (std::sin(theta) - mu * std::cos(theta));
  CHECK(t.normal == Approx(g * std::cos(theta)).epsilon(1e-12));
  CHECK(t.x == Approx(-mu * g * std::cos(theta)).epsilon(1e-12));
  for (int i = 0; i < 4; ++i) {
    CHECK(std::abs(r.w[i]) <= 1e-12 * g);                          // stays on the slope
    CHECK(r.f[4 + 2 * i] == Approx(-mu * r.f[i]).margin(1e-12 * g));  // at its bound
    CHECK(r.w[4 + 2 * i] == Approx(slide).epsilon(1e-9));             // w ≠ 0 there: sliding
    CHECK(std::abs(r.w[5 + 2 * i]) <= 1e-12 * g);
  }
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(6);
  expected[0] = slide;
  CHECK((s.accelerations(r.f) - expected).lpNorm<Eigen::Infinity>() <= 1e-9 * g);
  CHECK(r.residual.complementarity <= 1e-12 * g);
  CHECK(r.residual.bounds <= 1e-12 * g);
}

TEST_CASE("PGS finds the sliding friction forces of the incline", "[lcp][friction][pgs]") {
  const ContactSystem s = cubeOnIncline(0.3);
  PgsSettings settings;
  settings.max_iterations = 20000;
  const LcpResult r = solvePgs(s.problem(), settings);
  const Sums t = sums(r.f);
  CHECK(t.normal == Approx(g * std::cos(theta)).epsilon(1e-6));
  CHECK(t.x == Approx(-0.3 * g * std::cos(theta)).epsilon(1e-6));
}

TEST_CASE("a stack of cubes with friction stays at rest", "[lcp][friction]") {
  ContactSystem s = cubeStack(5, true, 0.5);
  const LcpResult r = solveDantzig(s.problem());
  INFO("passes = " << r.friction_passes << ", pivots = " << r.iterations);
  REQUIRE(r.status == LcpStatus::Solved);
  CHECK(r.w.lpNorm<Eigen::Infinity>() <= 1e-12 * g);
  CHECK(s.accelerations(r.f).lpNorm<Eigen::Infinity>() <= 1e-12 * g);
}

// One corner of a cube on the ground, pushed sideways: the friction force at the corner tips the
// cube, which changes the normal force, which changes the friction bound. The passes of frozen
// bounds converge at the rate mu x (moment arm ratio): here they took 47 passes, past the contact
// solver's cap of 12 (in the pile, 2806 single-contact solves stopped short in 2 s). The fixed
// point of the active set is solved at once instead (friction_fixed_point.h): 4 passes.
TEST_CASE("a sliding corner's friction bound is found exactly, not by slow passes", "[lcp][friction]") {
  ContactSystem s;
  s.bodies.push_back({});
  s.gravity = Eigen::Vector3d(0.8 * g, 0.3 * g, -g);
  addNormalContacts(s, 0, -1, {Eigen::Vector3d(-0.5, -0.5, -0.5)});
  const double mu = 0.9;
  addFrictionRows(s, mu);
  const LcpProblem p = s.problem();
  const LcpResult r = solveDantzig(p);
  INFO("f = " << r.f.transpose() << "\nw = " << r.w.transpose() << "\npasses = " << r.friction_passes);
  REQUIRE(r.status == LcpStatus::Solved);
  CHECK(r.friction_passes <= 5);
  CHECK(r.f[0] > 0);
  // sliding: at least one friction row at its bound, and the cone holds at the found normal force
  CHECK(std::max(std::abs(r.f[1]), std::abs(r.f[2])) == Approx(mu * r.f[0]).epsilon(1e-12));
  CHECK(r.residual.complementarity <= 1e-12 * g);
  CHECK(r.residual.bounds <= 1e-12 * g);
}

// The passes that find the friction bounds: each after the first starts from the last pass's
// clamped set. The same answer (to the rounding of a solve: the totals statics fixes, since corners
// of a face share their load freely) in fewer pivots than passes driven from zero.
TEST_CASE("a friction pass starts from the last pass's clamped set: the same answer in fewer pivots",
          "[lcp][friction]") {
  std::vector<ContactSystem> systems = {cubeOnIncline(0.3), cubeOnIncline(0.7)};
  for (int n : {3, 6}) {
    ContactSystem stack = cubeStack(n, true, 0.4);
    stack.gravity = g * Eigen::Vector3d(0.45, 0.2, -1).normalized();   // tilted: some corners slide
    systems.push_back(stack);
  }
  int seeded_pivots = 0, cold_pivots = 0;
  for (const ContactSystem& s : systems) {
    const LcpProblem p = s.problem();
    DantzigSettings cold;
    cold.seed_friction_passes = false;
    const LcpResult a = solveDantzig(p), b = solveDantzig(p, cold);
    INFO("seeded: " << a.iterations << " pivots, " << a.friction_passes << " passes; from zero: " << b.iterations
                    << " pivots, " << b.friction_passes << " passes");
    REQUIRE(a.status == LcpStatus::Solved);
    REQUIRE(b.status == LcpStatus::Solved);
    const double scale = p.b.lpNorm<Eigen::Infinity>() + 1;
    CHECK(a.residual.complementarity <= 1e-9 * scale);
    CHECK(a.residual.bounds <= 1e-9 * scale);
    // The net force and moment on every body: J^T f, the same whichever corners carry it.
    CHECK((s.jacobian().transpose() * (a.f - b.f)).lpNorm<Eigen::Infinity>() <= 1e-9 * (b.f.lpNorm<Eigen::Infinity>() + 1));
    seeded_pivots += a.iterations;
    cold_pivots += b.iterations;
  }
  INFO("pivots over the four problems: " << seeded_pivots << " seeded, " << cold_pivots << " from zero");
  CHECK(seeded_pivots < cold_pivots);
}
