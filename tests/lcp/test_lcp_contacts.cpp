// Redundant resting contacts from real contact Jacobians (four contact points sharing one contact
// normal make one of them redundant; D. Baraff, "Fast contact force computation for
// nonpenetrating rigid bodies", SIGGRAPH 1994): A is singular, the solver must still return forces
// that hold the body exactly.
#include "contact_jacobian.h"
#include "dynamics/lcp/dantzig_solver.h"
#include "dynamics/lcp/pgs_solver.h"

#include <catch2/catch.hpp>

#include <random>

using namespace tumble::lcp;
using namespace tumble::lcp::test;

namespace {

constexpr double g = 9.81;

// The body (or bodies) must be held: total normal force = weight, accelerations (the LCP's w and
// the bodies' generalised accelerations) below accelTol·g, no single force above maxForce.
void checkHeld(const ContactSystem& s, const LcpResult& r, double sumTol, double accelTol, double maxForce) {
  double weight = 0;
  for (const auto& body : s.bodies) weight += body.mass * g;
  REQUIRE(r.status == LcpStatus::Solved);
  REQUIRE(r.f.allFinite());
  double groundForce = 0;
  for (size_t i = 0; i < s.rows.size(); ++i)
    if (s.rows[i].b < 0 && s.rows[i].friction_of < 0) groundForce += r.f[i];
  CHECK(std::abs(groundForce - weight) <= sumTol * weight);
  CHECK(r.w.lpNorm<Eigen::Infinity>() <= accelTol * g);
  CHECK(s.accelerations(r.f).lpNorm<Eigen::Infinity>() <= accelTol * g);
  CHECK(r.f.maxCoeff() <= maxForce);
  CHECK(r.f.minCoeff() >= 0);
}

ContactSystem unitCube(int copies) {
  ContactSystem s;
  s.bodies.push_back({});
  for (int c = 0; c < copies; ++c) addNormalContacts(s, 0, -1, rectangleCorners(0, 0, 0.5, 0.5, -0.5));
  return s;
}

// A 200 kg plate 3 × 1.2 × 0.1 m resting on four supports placed off-centre and not in a rectangle.
ContactSystem slabOnLegs(double jitter, unsigned seed) {
  ContactSystem s;
  Body plate;
  plate.mass = 200;
  const double a = 3.0, c = 1.2, h = 0.1;
  plate.inertia = plate.mass / 12 * Eigen::Vector3d(c * c + h * h, a * a + h * h, a * a + c * c).asDiagonal();
  s.bodies.push_back(plate);
  std::vector<Eigen::Vector3d> legs = {{-1.3, -0.5, -h / 2}, {1.1, -0.55, -h / 2}, {1.4, 0.45, -h / 2},
                                       {-0.9, 0.52, -h / 2}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (auto& p : legs) p += Eigen::Vector3d(u(rng), u(rng), u(rng));
  addNormalContacts(s, 0, -1, legs);
  return s;
}

}  // namespace

TEST_CASE("a cube on four coplanar corner contacts is held exactly", "[lcp][redundant]") {
  const ContactSystem s = unitCube(1);
  const LcpResult r = solveDantzig(s.problem());
  INFO("f = " << r.f.transpose() << ", pivots = " << r.iterations);
  checkHeld(s, r, 1e-12, 1e-12, 9.81 * (1 + 1e-12));
  CHECK(r.iterations <= 2 * 4);
}

TEST_CASE("a cube on eight contacts (every corner twice) is held exactly", "[lcp][redundant]") {
  const ContactSystem s = unitCube(2);
  const LcpResult r = solveDantzig(s.problem());
  INFO("f = " << r.f.transpose() << ", pivots = " << r.iterations);
  checkHeld(s, r, 1e-12, 1e-12, 9.81 * (1 + 1e-12));
  CHECK(r.iterations <= 2 * 8);
}

TEST_CASE("a slab on four legs is held, also with the legs moved by 1e-9 m", "[lcp][redundant]") {
  for (double jitter : {0.0, 1e-9})
    for (unsigned seed = 0; seed < 20; ++seed) {
      const ContactSystem s = slabOnLegs(jitter, seed);
      const LcpResult r = solveDantzig(s.problem());
      INFO("jitter = " << jitter << ", seed = " << seed << ", f = " << r.f.transpose());
      checkHeld(s, r, 1e-9, 1e-9, 10 * 200 * g);
    }
}

TEST_CASE("a cube with corners perturbed by 1e-9 m is held", "[lcp][redundant]") {
  for (unsigned seed = 0; seed < 50; ++seed) {
    ContactSystem s = unitCube(2);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1e-9, 1e-9);
    for (auto& row : s.rows) row.point += Eigen::Vector3d(u(rng), u(rng), u(rng));
    const LcpResult r = solveDantzig(s.problem());
    INFO("seed = " << seed << ", f = " << r.f.transpose());
    checkHeld(s, r, 1e-9, 1e-9, 10 * g);
  }
}

TEST_CASE("a stack of ten cubes is held exactly", "[lcp][redundant]") {
  const ContactSystem s = cubeStack(10, false);
  const LcpResult r = solveDantzig(s.problem());
  INFO("pivots = " << r.iterations);
  checkHeld(s, r, 1e-12, 1e-12, 10 * 10 * g);
}

TEST_CASE("a 1000:1 mass ratio stack is held exactly", "[lcp][redundant]") {
  for (bool heavyOnTop : {true, false}) {
    ContactSystem s = cubeStack(3, false);
    const int heavy = heavyOnTop ? 2 : 0;
    s.bodies[heavy].mass = 1000;
    s.bodies[heavy].inertia *= 1000;
    const LcpResult r = solveDantzig(s.problem());
    INFO("heavy on top = " << heavyOnTop << ", f = " << r.f.transpose());
    // the rounding floor of w is eps times the terms that cancel, A·f ~ (1000 g)·(1/1 kg) here
    checkHeld(s, r, 1e-12, 1e-12 * 1000, 1002 * g);
  }
}

TEST_CASE("PGS holds the cube on four corners to its tolerance", "[lcp][pgs]") {
  const ContactSystem s = unitCube(1);
  PgsSettings settings;
  settings.max_iterations = 10000;
  const LcpResult r = solvePgs(s.problem(), settings);
  CHECK(r.status == LcpStatus::Solved);
  CHECK(std::abs(r.f.sum() - g) <= 1e-8 * g);
  CHECK(r.w.lpNorm<Eigen::Infinity>() <= 1e-8 * g);
}
