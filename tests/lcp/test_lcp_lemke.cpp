// Lemke's method on the friction LCP (lemke_friction.h): the same answers as the direct solver
// where that settles, and an answer where its friction passes do not.
#include "contact_jacobian.h"
#include "dynamics/lcp/dantzig_solver.h"
#include "dynamics/lcp/lemke_friction.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace tumble::lcp;
using namespace tumble::lcp::test;

namespace {

constexpr double g = 9.81;

// The residuals an exact answer leaves: rounding of the terms that cancel in w = A f + b.
double roundingScale(const LcpProblem& p, const LcpResult& r) {
  return 1e-9 * (p.b.lpNorm<Eigen::Infinity>() + p.A.lpNorm<Eigen::Infinity>() * r.f.lpNorm<Eigen::Infinity>());
}

Eigen::Vector3d unitVector(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Eigen::Vector3d v(n(rng), n(rng), n(rng));
  return v.normalized();
}

// A velocity-level contact problem of `bodies` bodies (masses over four decades, flattened
// inertias) with `contacts` contacts at random points and normals between random pairs or the
// ground, each with two friction rows: b = J v for random velocities, plus a gap on the normals.
// It has an answer (Anitescu and Potra 1997); whether the direct solver's passes settle depends.
LcpProblem randomImpactProblem(int bodies, int contacts, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  ContactSystem s;
  for (int i = 0; i < bodies; ++i) {
    Body body;
    body.mass = std::pow(10.0, -2 + 4 * u(rng));
    const Eigen::Vector3d axes(0.02 + u(rng), 0.02 + u(rng), 0.02 + 0.1 * u(rng));
    body.inertia = (body.mass / 12 * Eigen::Vector3d(axes.y() * axes.y() + axes.z() * axes.z(),
                                                     axes.x() * axes.x() + axes.z() * axes.z(),
                                                     axes.x() * axes.x() + axes.y() * axes.y()))
                       .asDiagonal();
    body.com = Eigen::Vector3d(u(rng), u(rng), u(rng));
    s.bodies.push_back(body);
  }
  std::vector<double> mu;
  for (int c = 0; c < contacts; ++c) {
    const int a = static_cast<int>(u(rng) * bodies);
    int b = static_cast<int>(u(rng) * (bodies + 1)) - 1;   // -1: the ground
    if (b == a) b = -1;
    const Eigen::Vector3d point = s.bodies[a].com + 0.3 * unitVector(rng);
    s.rows.push_back({a, b, point, unitVector(rng), -1, 0});
    mu.push_back(0.2 + u(rng));
  }
  for (int c = 0; c < contacts; ++c) {
    const Eigen::Vector3d n = s.rows[c].dir;
    const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    for (const Eigen::Vector3d& t : {t1, t2}) {
      ContactRow row = s.rows[c];
      row.dir = t;
      row.friction_of = c;
      row.mu = mu[c];
      s.rows.push_back(row);
    }
  }
  LcpProblem p = s.problem();
  Eigen::VectorXd v(6 * bodies);
  for (int i = 0; i < v.size(); ++i) v[i] = 4 * u(rng) - 2;
  p.b = s.jacobian() * v;
  for (int c = 0; c < contacts; ++c) p.b[c] += 0.1 * u(rng);   // a gap the step may close
  return p;
}

}  // namespace

TEST_CASE("Lemke's method finds the sticking and the sliding cube on an incline", "[lcp][lemke]") {
  for (const double mu : {0.7, 0.3}) {
    ContactSystem s;
    s.bodies.push_back({});
    const double theta = std::numbers::pi / 6;
    s.gravity = g * Eigen::Vector3d(std::sin(theta), 0, -std::cos(theta));
    addNormalContacts(s, 0, -1, rectangleCorners(0, 0, 0.5, 0.5, -0.5));
    addFrictionRows(s, mu);
    const LcpProblem p = s.problem();
    LcpResult r;
    solveLemkeFriction(p, LemkeSettings{}, r);
    INFO("mu " << mu << " f = " << r.f.transpose() << "\nw = " << r.w.transpose());
    REQUIRE(r.status == LcpStatus::Solved);
    double normal = 0, x = 0;
    for (int i = 0; i < 4; ++i) normal += r.f[i], x += r.f[4 + 2 * i];
    // Statics along the normal; along the slope the weight's component (sticking, mu >= tan 30)
    // or the full friction mu N (sliding): to rounding of a few pivots on unit-sized terms.
    CHECK(normal == Approx(g * std::cos(theta)).epsilon(1e-12));
    CHECK(x == Approx(mu > std::tan(theta) ? -g * std::sin(theta) : -mu * g * std::cos(theta)).epsilon(1e-12));
    CHECK(r.residual.complementarity <= 1e-12 * g);
    CHECK(r.residual.bounds <= 1e-12 * g);
  }
}

TEST_CASE("Lemke's method answers the contact problems whose friction passes do not settle", "[lcp][lemke]") {
  std::mt19937 rng(20261129);
  DantzigSettings capped;   // the contact solver's settings (contact_rows.cpp)
  capped.friction_tolerance = 1e-9;
  capped.max_friction_passes = 12;
  int unsettled = 0, problems = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int bodies = 2 + trial % 5, contacts = 2 + trial % 13;
    const LcpProblem p = randomImpactProblem(bodies, contacts, rng);
    const LcpResult direct = solveDantzig(p, capped);
    LcpResult r;
    solveLemkeFriction(p, LemkeSettings{}, r);
    ++problems;
    if (direct.status != LcpStatus::Solved) ++unsettled;
    INFO("trial " << trial << ": " << bodies << " bodies, " << contacts << " contacts; pivots " << r.iterations
                  << ", complementarity " << r.residual.complementarity << ", bounds " << r.residual.bounds
                  << " against rounding " << roundingScale(p, r));
    CHECK(r.status == LcpStatus::Solved);
    CHECK(r.residual.complementarity <= roundingScale(p, r));
    CHECK(r.residual.bounds <= roundingScale(p, r));
    // No contact approaches: the normal rows' w (the velocity along the normal plus its gap term).
    for (int c = 0; c < contacts; ++c) CHECK(r.w[c] >= -roundingScale(p, r));
  }
  // The draw is made to include problems the passes leave unsettled, which this test is about.
  INFO(unsettled << " of " << problems << " left unsettled by the direct solver's friction passes");
  CHECK(unsettled >= 5);
}

// Towers of crossed blocks (0.6 x 0.3 x 0.25 m, 45 kg, each course turned a quarter turn on the
// one below: four coplanar corners on each 0.3 m square of contact, A singular many times over),
// each block given a random velocity: the velocity-level problem of a tower rocking. These the
// plain path answers exactly; the islands of a toppling tower (hard case 26) where rounding
// defeated it are answered by the regularised path, within what a usable pivoting answer must
// reach (kUsableComplementarity, 1e-6 of the problem's scale), the bound checked here too.
TEST_CASE("Lemke's method answers rocking towers of crossed blocks", "[lcp][lemke]") {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1, 1);
  int exact = 0, regularised = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const int blocks = 3 + trial % 6;
    ContactSystem s;
    const double m = 45, a = 0.6, b = 0.3, h = 0.25;
    for (int i = 0; i < blocks; ++i) {
      Body body;
      body.mass = m;
      const bool along_x = i % 2 == 0;
      const double lx = along_x ? a : b, ly = along_x ? b : a;
      body.inertia = (m / 12 * Eigen::Vector3d(ly * ly + h * h, lx * lx + h * h, lx * lx + ly * ly)).asDiagonal();
      body.com = {0, 0, h * (i + 0.5)};
      s.bodies.push_back(body);
      // On the ground the block's own face; on the block below, the square where the two cross.
      addNormalContacts(s, i, i - 1, i == 0 ? rectangleCorners(0, 0, lx / 2, ly / 2, 0) : rectangleCorners(0, 0, b / 2, b / 2, h * i));
    }
    addFrictionRows(s, 0.6);
    LcpProblem p = s.problem();
    Eigen::VectorXd v(6 * blocks);
    for (int i = 0; i < v.size(); ++i) v[i] = 0.3 * u(rng);
    p.b = s.jacobian() * v;
    LcpResult r;
    solveLemkeFriction(p, LemkeSettings{}, r);
    INFO("trial " << trial << ": " << blocks << " blocks, pivots " << r.iterations << ", status "
                  << toString(r.status) << ", complementarity " << r.residual.complementarity);
    REQUIRE(r.status != LcpStatus::Failed);
    (r.status == LcpStatus::Solved ? exact : regularised) += 1;
    CHECK(r.residual.complementarity <= 1e-6 * (p.b.lpNorm<Eigen::Infinity>() + 1));
    CHECK(r.residual.bounds <= 1e-6 * (p.b.lpNorm<Eigen::Infinity>() + 1));
  }
  INFO(exact << " exact, " << regularised << " regularised");
  CHECK(exact > 0);
}
