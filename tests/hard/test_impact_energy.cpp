// Hard case 9 (docs/hard-cases.md): kinetic energy never grows at an impact. 10 000 seeded random
// frictional impacts, straight on the impulse stage (resolveCollisions): boxes and random convex
// hulls, on the ground or on each other, random poses, velocities and spins, e and mu in [0, 1],
// under each restitution law. Newton's law with friction can create energy (Kane's paradox), and
// so can Poisson's; the solver must not.
#include <catch2/catch.hpp>

#include <random>

#include "collision/narrow_phase.h"
#include "dynamics/contact_detection.h"
#include "dynamics/baraff/collisions.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "hard_run.h"

using namespace tumble;

namespace {

using Rng = std::mt19937;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

Eigen::Vector3d uniformVector(Rng& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

ConvexPiece randomShape(Rng& rng) {
  if (uniform(rng, 0, 1) < 0.5) return makeBox(uniformVector(rng, 0.05, 0.5));
  for (;;) {
    std::vector<Eigen::Vector3d> points;
    int n = 6 + static_cast<int>(uniform(rng, 0, 14));
    Eigen::Vector3d scale = uniformVector(rng, 0.05, 0.5);
    for (int i = 0; i < n; ++i) points.push_back(uniformVector(rng, -1, 1).cwiseProduct(scale));
    if (std::optional<ConvexPiece> hull = convexHull(points, nullptr)) return *hull;
  }
}

// A moving body of the shape (density 1000) in its principal frame, at rest at the origin.
RigidBody makeBody(const ConvexPiece& shape, double e, double mu) {
  RigidBody body;
  MassProperties mp = massProperties(shape, 1000);
  PrincipalFrame frame = principalFrame(mp.inertia);
  ConvexPiece piece = shape;
  piece.transform(frame.rotation.transpose(), -frame.rotation.transpose() * mp.center);
  body.pieces = {piece};
  body.mass = mp.mass;
  body.inv_mass = 1 / mp.mass;
  body.inertia_body = frame.moments;
  body.inv_inertia_body = frame.moments.cwiseInverse();
  body.restitution = e;
  body.friction = mu;
  return body;
}

double lowestZ(const RigidBody& b) {
  double z = INFINITY;
  for (const Eigen::Vector3d& v : b.pieces[0].vertices) z = std::min(z, (b.x + b.rotation() * v).z());
  return z;
}
double highestZ(const RigidBody& b) {
  double z = -INFINITY;
  for (const Eigen::Vector3d& v : b.pieces[0].vertices) z = std::max(z, (b.x + b.rotation() * v).z());
  return z;
}

void randomMotion(Rng& rng, RigidBody& b) {
  b.q = Eigen::Quaterniond(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)).normalized();
  b.P = b.mass * uniformVector(rng, -3, 3);
  Eigen::Vector3d w = uniformVector(rng, -10, 10);
  Eigen::Matrix3d R = b.rotation();
  b.L = R * b.inertia_body.cwiseProduct(R.transpose() * w);
}

// Lowers `upper` along -z until it touches `lower`: the SAT separation s along the separating axis
// n is at most the gap along z, and moving down by s closes it by s |n_z| <= s, so the steps never
// overshoot and shrink geometrically.
void lowerOnto(const RigidBody& lower, RigidBody& upper) {
  CollisionHull hl = makeCollisionHull(lower.pieces[0]), hu = makeCollisionHull(upper.pieces[0]);
  for (int i = 0; i < 200; ++i) {
    SatCache cache;
    double gap = separation(hl, poseOf(lower), hu, poseOf(upper), cache);
    if (gap < 1e-9) return;
    upper.x.z() -= gap;
  }
}

// A world of the ground and one body touching it, or of two bodies, the upper one lowered onto
// the lower one from just above it.
World randomImpact(Rng& rng) {
  World world;
  world.gravity = Eigen::Vector3d(0, 0, -9.81);
  RigidBody ground;
  ground.name = "ground";
  ground.shape = ShapeKind::Plane;
  ground.is_static = true;
  world.bodies.push_back(ground);
  const double e = uniform(rng, 0, 1), mu = uniform(rng, 0, 1);
  RigidBody lower = makeBody(randomShape(rng), e, mu);
  randomMotion(rng, lower);
  lower.x.z() -= lowestZ(lower);
  world.bodies.push_back(lower);
  if (uniform(rng, 0, 1) < 0.5) {
    RigidBody upper = makeBody(randomShape(rng), e, mu);
    randomMotion(rng, upper);
    upper.P.z() -= upper.mass * 3;   // mostly falling onto the lower body
    upper.x.head<2>() = world.bodies[1].x.head<2>() + uniformVector(rng, -0.1, 0.1).head<2>();
    upper.x.z() += highestZ(world.bodies[1]) - lowestZ(upper) + 0.01;
    lowerOnto(world.bodies[1], upper);
    world.bodies.push_back(upper);
  }
  return world;
}

// 10 000 seeded impacts under `law`: none adds kinetic energy; at least half are impacts, and at
// least 2000 of those between two moving bodies.
void checkImpactEnergy(RestitutionLaw law) {
  Rng rng(20261123);
  ContactSettings settings;
  settings.restitution_law = law;
  int impacts = 0, body_pairs = 0;
  double worst = -INFINITY;   // largest relative energy change (> 0: gained)
  for (int trial = 0; trial < 10000; ++trial) {
    World world = randomImpact(rng);
    ContactDetector detector(world);
    std::vector<Contact> contacts;
    detector.detect(world, settings, contacts);
    double before = hard::kineticEnergy(world);
    ContactSolveStats stats;
    if (!resolveCollisions(world, contacts, settings, BounceThreshold{settings.resting_speed_m_s}, 1.0 / 240, stats)) continue;
    ++impacts;
    bool pair = false;
    for (const Contact& c : contacts) pair |= !world.bodies[c.b].is_static;
    body_pairs += pair;
    double after = hard::kineticEnergy(world);
    worst = std::max(worst, (after - before) / before);
    INFO("trial " << trial << ": energy " << before << " -> " << after << " J");
    REQUIRE(after <= before * (1 + 1e-9));
  }
  INFO(impacts << " impacts (" << body_pairs << " with two bodies), worst relative change " << worst);
  CHECK(impacts >= 5000);
  CHECK(body_pairs >= 2000);
}

}  // namespace

TEST_CASE("impact energy: 10 000 random frictional impacts never add kinetic energy", "[hard][energy]") {
  checkImpactEnergy(RestitutionLaw::Newton);
}

// The same impacts under the other laws (baraff/restitution_laws.h): Poisson's law can add energy
// where friction stops or turns the slip, and the two-phase impacts of several points are not
// the laws' own definition; the energy rule must hold for both.
TEST_CASE("impact energy: the same random impacts never add kinetic energy under Poisson's law", "[hard][energy]") {
  checkImpactEnergy(RestitutionLaw::Poisson);
}

TEST_CASE("impact energy: the same random impacts never add kinetic energy under Stronge's law", "[hard][energy]") {
  checkImpactEnergy(RestitutionLaw::Stronge);
}
