// An unconverged impulse answer may not do worse than no impulses (passive_impulses.h): its merit
// is the change of kinetic energy where no row has a target, and an answer above merit 0 is scaled
// to the least merit along it, which takes energy and stays inside every friction pyramid.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/contact_detection.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/passive_impulses.h"
#include "scene/scene_loader.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

// The unit cube of 1 kg of scenes/rest.json on the ground (four corner contacts), moving at `v`
// and turning at `omega`, with a normal and two friction rows per corner (mu = 0.5) and b = J v:
// the rows' velocities without impulses, no targets.
struct CubeRows {
  World world;
  int cube = -1;
  std::vector<ContactRow> rows;
  std::vector<RowLimit> limits;
  Eigen::VectorXd b;
};

CubeRows cubeOnGround(const Eigen::Vector3d& v, const Eigen::Vector3d& omega) {
  CubeRows out;
  out.world = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/rest.json")).world;
  for (std::size_t i = 0; i < out.world.bodies.size(); ++i)
    if (!out.world.bodies[i].is_static) out.cube = static_cast<int>(i);
  RigidBody& cube = out.world.bodies[out.cube];
  cube.P = cube.mass * v;
  cube.L = cube.rotation() * cube.inertia_body.cwiseProduct(cube.rotation().transpose() * omega);
  std::vector<Contact> contacts;
  ContactDetector detector(out.world);
  detector.detect(out.world, ContactSettings{}, contacts);
  REQUIRE(contacts.size() == 4);
  for (const Contact& c : contacts) {
    const int normal = static_cast<int>(out.rows.size());
    out.rows.push_back(rowAlong(out.world, c, c.normal));
    out.limits.push_back({});
    Eigen::Vector3d t1, t2;
    tangentsOf(c.normal, t1, t2);
    for (const Eigen::Vector3d& t : {t1, t2}) {
      out.rows.push_back(rowAlong(out.world, c, t));
      out.limits.push_back({RowLimit::Static, normal, 0.5, 0});
    }
  }
  out.b.resize(out.rows.size());
  for (std::size_t r = 0; r < out.rows.size(); ++r) out.b[r] = rowVelocity(out.world, out.rows[r]);
  return out;
}

// The kinetic energy the impulses p add to the cube (J), by applying them to a copy of the world.
double kineticEnergyAdded(const CubeRows& c, const Eigen::VectorXd& p) {
  World after = c.world;
  applyAlongRows(after, c.rows, p);
  return after.bodies[c.cube].kineticEnergy() - c.world.bodies[c.cube].kineticEnergy();
}

// Impulses on the cube of `each` N s along every corner's normal row and `friction` (N s, world,
// horizontal) along its tangent rows.
Eigen::VectorXd cornerImpulses(const CubeRows& c, double each, const Eigen::Vector3d& friction = Eigen::Vector3d::Zero()) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(c.rows.size()));
  for (std::size_t r = 0; r < c.rows.size(); r += 3) {
    const double side = c.rows[r].b == c.cube ? 1 : -1;   // rows push B along +dir, A along -dir
    p[r] = each;
    p[r + 1] = side * friction.dot(c.rows[r + 1].dir);
    p[r + 2] = side * friction.dot(c.rows[r + 2].dir);
  }
  return p;
}

}  // namespace

TEST_CASE("the merit of impulses with no targets is the kinetic energy they add", "[contact][passive]") {
  const CubeRows c = cubeOnGround({0.3, -0.2, -0.5}, {0.4, 0.1, -0.7});
  const Eigen::VectorXd p = cornerImpulses(c, 0.2, {0.05, 0.02, 0});
  const ImpulseMerit m = impulseMerit(c.world, c.rows, c.b, c.limits, p);
  // Rounding of sums of terms of about 0.1 J.
  CHECK(m.value() == Approx(kineticEnergyAdded(c, p)).margin(1e-13));
}

TEST_CASE("impulses that would add kinetic energy are scaled to the least energy along them", "[contact][passive]") {
  // The cube lands at 0.5 m/s; four corner impulses three times those that stop it throw it up at
  // 1 m/s, adding 0.375 J. Along them the least energy is at a third: the cube stopped.
  CubeRows c = cubeOnGround({0, 0, -0.5}, Eigen::Vector3d::Zero());
  const double stop = c.world.bodies[c.cube].mass * 0.5 / 4;
  Eigen::VectorXd p = cornerImpulses(c, 3 * stop);
  REQUIRE(kineticEnergyAdded(c, p) == Approx(0.375).epsilon(1e-12));
  const double alpha = keepPassive(c.world, c.rows, c.b, c.limits, p);
  CHECK(alpha == Approx(1.0 / 3).epsilon(1e-12));
  CHECK(kineticEnergyAdded(c, p) == Approx(-0.125).epsilon(1e-12));   // all of 1/2 m v^2 taken
  World after = c.world;
  applyAlongRows(after, c.rows, p);
  CHECK(after.bodies[c.cube].velocity().norm() < 1e-14);
}

TEST_CASE("friction that pushes a sliding cube along its slide is dropped, normal impulse with it", "[contact][passive]") {
  // Sliding at 1 m/s along x and resting (no normal speed): friction along +x only adds energy,
  // and the normal impulse that carries its bound lifts the cube, so the least merit along the
  // answer is at zero. Scaling keeps every friction impulse inside its pyramid (|p_t| <= mu p_n).
  CubeRows c = cubeOnGround({1, 0, 0}, Eigen::Vector3d::Zero());
  Eigen::VectorXd p = cornerImpulses(c, 0.1, {0.05, 0, 0});
  REQUIRE(kineticEnergyAdded(c, p) > 0);
  CHECK(keepPassive(c.world, c.rows, c.b, c.limits, p) == 0.0);
  CHECK(p.isZero(0));
}

TEST_CASE("an answer that takes energy is kept bit for bit", "[contact][passive]") {
  // Half the impulses that stop a landing cube, with friction against a sideways slide: merit < 0.
  CubeRows c = cubeOnGround({0.2, 0, -0.5}, Eigen::Vector3d::Zero());
  const double stop = c.world.bodies[c.cube].mass * 0.5 / 4;
  const Eigen::VectorXd before = cornerImpulses(c, 0.5 * stop, {-0.01, 0, 0});
  Eigen::VectorXd p = before;
  REQUIRE(impulseMerit(c.world, c.rows, c.b, c.limits, p).value() < 0);
  CHECK(keepPassive(c.world, c.rows, c.b, c.limits, p) == 1.0);
  CHECK(p == before);
}

namespace {

// The rise of the cube's total energy over a time step of `dt` that starts at rest: gravity's
// impulse is in the velocity the rows read (v = g dt), the impulses p are applied, and the step
// moves the cube by its new velocity (x + v dt, as the time-stepping model integrates). Against
// its start, at rest where it stands: the kinetic energy plus -m g . (v dt).
double stepEnergyRise(const CubeRows& c, const Eigen::VectorXd& p, double dt) {
  World after = c.world;
  applyAlongRows(after, c.rows, p);
  const RigidBody& cube = after.bodies[c.cube];
  return cube.kineticEnergy() - cube.mass * after.gravity.dot(cube.velocity() * dt);
}

}  // namespace

TEST_CASE("a time step's exact answer for a resting cube is kept bit for bit", "[contact][passive]") {
  // At rest on the ground with gravity's impulse over the step in its velocity: a quarter of
  // m |g| dt at each corner stops it, and the step ends where it started, with the energy it
  // started with: on the bound itself, which rounding may not push it over.
  const double dt = 1.0 / 240;
  const Eigen::Vector3d g(0, 0, -9.81);
  CubeRows c = cubeOnGround(g * dt, Eigen::Vector3d::Zero());
  REQUIRE(c.world.gravity == g);
  const Eigen::VectorXd before = cornerImpulses(c, c.world.bodies[c.cube].mass * 9.81 * dt / 4);
  Eigen::VectorXd p = before;
  REQUIRE(std::abs(stepEnergyRise(c, p, dt)) < 1e-15);
  CHECK(keepPassive(c.world, c.rows, c.b, c.limits, p, dt) == 1.0);
  CHECK(p == before);
}

TEST_CASE("impulses that would lift a resting cube are scaled until the step ends with the energy it began with",
          "[contact][passive]") {
  // Twice the impulses that hold the cube throw it up at |g| dt: no kinetic energy added (it moved
  // down at that speed before them), so the merit keeps them, but the step would lift the cube by
  // |g| dt^2 with nothing to pay for it (an unconverged answer on the 101-stone arch lifted its
  // ring this way, 180 J a step). Scaled by a half: the impulses that hold it, the energy kept.
  const double dt = 1.0 / 240;
  CubeRows c = cubeOnGround(Eigen::Vector3d(0, 0, -9.81 * dt), Eigen::Vector3d::Zero());
  const double hold = c.world.bodies[c.cube].mass * 9.81 * dt / 4;
  Eigen::VectorXd p = cornerImpulses(c, 2 * hold);
  REQUIRE(impulseMerit(c.world, c.rows, c.b, c.limits, p).value() == Approx(0).margin(1e-15));
  REQUIRE(stepEnergyRise(c, p, dt) > 1e-4);
  CHECK(keepPassive(c.world, c.rows, c.b, c.limits, p) == 1.0);   // without the step: kept
  CHECK(keepPassive(c.world, c.rows, c.b, c.limits, p, dt) == Approx(0.5).epsilon(1e-9));
  CHECK(stepEnergyRise(c, p, dt) == Approx(0).margin(1e-12));
  World after = c.world;
  applyAlongRows(after, c.rows, p);
  CHECK(after.bodies[c.cube].velocity().norm() < 1e-14);
}
