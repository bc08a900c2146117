// The matrix-free Gauss-Seidel solve of resting forces (row_gauss_seidel.h), which piles use
// instead of pivoting: it must carry the weight, keep friction inside its bounds, and never let a
// sliding contact's friction reverse the slide.
#include <catch2/catch.hpp>

#include "dynamics/contact_detection.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/baraff/resting_forces.h"
#include "dynamics/row_gauss_seidel.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

// The unit box of scenes/rest.json on the ground, with the contacts the pipeline finds.
struct Resting {
  World world;
  std::vector<Contact> contacts;
  int box = -1;
};

Resting restingBox() {
  Resting out;
  out.world = buildWorld(loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/rest.json")).world;
  ContactDetector detector(out.world);
  detector.detect(out.world, ContactSettings{}, out.contacts);
  for (std::size_t i = 0; i < out.world.bodies.size(); ++i)
    if (!out.world.bodies[i].is_static) out.box = static_cast<int>(i);
  return out;
}

// Rows for every contact: normal, then either two static-friction tangents or one row against
// the slide, with the free acceleration gravity gives each row.
struct Rows {
  std::vector<ContactRow> rows;
  std::vector<RowLimit> limits;
  Eigen::VectorXd b;
};

Rows rowsOf(const World& world, const std::vector<Contact>& contacts, double mu, const Eigen::Vector3d* slide,
            double target) {
  Rows out;
  for (const Contact& c : contacts) {
    int normal = static_cast<int>(out.rows.size());
    out.rows.push_back(rowAlong(world, c, c.normal));
    out.limits.push_back({});
    if (slide) {
      out.rows.push_back(rowAlong(world, c, -*slide));
      out.limits.push_back({RowLimit::Sliding, normal, mu, target});
    } else {
      Eigen::Vector3d t1, t2;
      tangentsOf(c.normal, t1, t2);
      for (const Eigen::Vector3d& t : {t1, t2}) {
        out.rows.push_back(rowAlong(world, c, t));
        out.limits.push_back({RowLimit::Static, normal, mu, 0});
      }
    }
  }
  out.b.resize(out.rows.size());
  for (std::size_t r = 0; r < out.rows.size(); ++r) {
    const ContactRow& row = out.rows[r];
    Eigen::Vector3d ga = world.bodies[row.a].is_static ? Eigen::Vector3d::Zero() : world.gravity;
    Eigen::Vector3d gb = world.bodies[row.b].is_static ? Eigen::Vector3d::Zero() : world.gravity;
    out.b[r] = row.dir.dot(gb - ga);
  }
  return out;
}

}  // namespace

TEST_CASE("Gauss-Seidel rows carry a resting box's weight on its four redundant corners", "[contact][gauss_seidel]") {
  Resting r = restingBox();
  REQUIRE(r.contacts.size() == 4);
  Rows rows = rowsOf(r.world, r.contacts, 0.5, nullptr, 0);
  RowGaussSeidelResult out = solveRowsGaussSeidel(r.world, rows.rows, rows.b, rows.limits);
  const RigidBody& box = r.world.bodies[r.box];
  double mg = box.mass * r.world.gravity.norm(), sum = 0;
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    if (rows.limits[i].kind == RowLimit::Normal) {
      CHECK(out.f[i] >= 0);
      sum += out.f[i];
    } else {
      // No tangential load: friction stays (numerically) zero, inside its bound.
      CHECK(std::abs(out.f[i]) <= 0.5 * out.f[rows.limits[i].normal] + 1e-12);
    }
  }
  CHECK(out.converged);
  // The stopping rule leaves at most 1e-7 g of residual acceleration per row; four rows share it.
  CHECK(std::abs(sum - mg) / mg < 1e-6);
}

TEST_CASE("Gauss-Seidel sliding friction is mu f_n, or what stops the slide without reversing it", "[contact][gauss_seidel]") {
  Resting r = restingBox();
  const RigidBody& box = r.world.bodies[r.box];
  const double mu = 0.4, mg = box.mass * r.world.gravity.norm();
  const Eigen::Vector3d slide = Eigen::Vector3d::UnitX();
  auto friction_total = [&](double target) {
    Rows rows = rowsOf(r.world, r.contacts, mu, &slide, target);
    RowGaussSeidelResult out = solveRowsGaussSeidel(r.world, rows.rows, rows.b, rows.limits);
    CHECK(out.converged);
    double fn = 0, ft = 0;
    for (std::size_t i = 0; i < rows.rows.size(); ++i)
      (rows.limits[i].kind == RowLimit::Normal ? fn : ft) += out.f[i];
    CHECK(std::abs(fn - mg) / mg < 1e-5);   // friction at the base tips the load, not its sum
    return ft;
  };
  // A fast slide (3 m/s, stopping within one 1/240 s step would need 720 m/s^2): exactly mu m g.
  CHECK(friction_total(3.0 * 240) == Approx(mu * mg).epsilon(1e-5));
  // A slide of 1 mm/s stops within the step with 0.24 m/s^2: m a, well below mu m g.
  CHECK(friction_total(1e-3 * 240) == Approx(box.mass * 0.24).epsilon(1e-4));
}

TEST_CASE("resting islands above the pivoting limit are solved by Gauss-Seidel and carry the weight", "[contact][gauss_seidel]") {
  Resting r = restingBox();
  const RigidBody& box = r.world.bodies[r.box];
  double mg = box.mass * r.world.gravity.norm();
  for (int limit : {256, 0}) {
    ContactSettings settings;
    settings.max_direct_rows = limit;
    std::vector<Wrench> wrenches(r.world.bodies.size());
    wrenches[r.box].force = box.mass * r.world.gravity;
    ContactSolveStats stats;
    addRestingForces(r.contacts, {r.world, settings, 1.0 / 240, nullptr, wrenches, stats});
    INFO("pivoting limit " << limit << " rows");
    CHECK(stats.iterative_islands == (limit == 0 ? 1 : 0));
    CHECK(wrenches[r.box].force.norm() / mg < 1e-6);
  }
}

// The pipeline passes a memory: islands past the pivoting limit are then solved at the velocity
// level over the step and warm-started from the last call's impulses (baraff/resting_forces.cpp). A box
// at rest carries its weight, and the second call starts at the first's answer: converged at once.
TEST_CASE("with a memory, islands above the pivoting limit start from the last call's impulses", "[contact][gauss_seidel]") {
  Resting r = restingBox();
  const RigidBody& box = r.world.bodies[r.box];
  const double mg = box.mass * r.world.gravity.norm();
  ContactSettings settings;
  settings.max_direct_rows = 0;
  RestingMemory memory;
  long first_sweeps = 0;
  for (int call = 0; call < 2; ++call) {
    std::vector<Wrench> wrenches(r.world.bodies.size());
    wrenches[r.box].force = box.mass * r.world.gravity;
    ContactSolveStats stats;
    addRestingForces(r.contacts, {r.world, settings, 1.0 / 240, &memory, wrenches, stats});
    INFO("call " << call << ": " << stats.sweeps << " sweeps");
    CHECK(stats.iterative_islands == 1);
    CHECK(stats.unconverged_sweeps == 0);
    CHECK(wrenches[r.box].force.norm() / mg < 1e-6);
    if (call == 0) first_sweeps = stats.sweeps;
    else CHECK(stats.sweeps < first_sweeps);
    if (call == 1) CHECK(stats.sweeps <= 2);
  }
  CHECK(memory.last.size() == r.contacts.size());
}

// A box resting on one bottom edge, the opposite edge 20 um above the ground (within the detection
// margin, beyond the contact tolerance): gravity turns it about the resting edge. Solved at the
// velocity level, the lifted corners are near contacts whose gap may close within the step but
// not be overshot, so the box lands on them within the step instead of falling freely for it
// (20 um in 1/240 s is 4.8 mm/s; gravity's turn alone would reach about 3 g dt / 4 = 3 cm/s).
TEST_CASE("at the velocity level, near contacts keep a lifted edge from being overshot in the step", "[contact][gauss_seidel]") {
  Resting r = restingBox();
  RigidBody& box = r.world.bodies[r.box];
  const double gap = 20e-6, dt = 1.0 / 240;
  // Turn about the bottom edge at x = -0.5 so that the edge at x = +0.5 rises by `gap`.
  const double angle = std::asin(gap / 1.0);
  const Eigen::Vector3d pivot(-0.5, 0, 0);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitY()));
  box.q = turn * box.q;
  box.x = pivot + turn * (box.x - pivot);
  ContactDetector detector(r.world);
  detector.detect(r.world, ContactSettings{}, r.contacts);
  REQUIRE(r.contacts.size() == 4);
  ContactSettings settings;
  settings.max_direct_rows = 0;   // this island at the velocity level
  RestingMemory memory;
  std::vector<Wrench> wrenches(r.world.bodies.size());
  wrenches[r.box].force = box.mass * r.world.gravity;
  ContactSolveStats stats;
  addRestingForces(r.contacts, {r.world, settings, dt, &memory, wrenches, stats});
  REQUIRE(stats.iterative_islands == 1);
  // Velocities after the step under these forces (the box starts at rest).
  const Eigen::Vector3d v = wrenches[r.box].force * box.inv_mass * dt;
  const Eigen::Vector3d w = inverseInertiaWorld(box) * wrenches[r.box].torque * dt;
  for (const Contact& c : r.contacts) {
    const double vn = c.normal.dot(-(v + w.cross(c.point - box.x)));   // ground is body b: + apart
    INFO("corner at x = " << c.point.x() << ", gap " << -c.depth << " m, normal velocity " << vn << " m/s");
    // Gauss-Seidel stops at 1e-6 of the largest velocity term (g dt = 0.04 m/s): 4e-8 m/s of slack.
    CHECK(vn >= -std::max(0.0, -c.depth) / dt - 1e-7);
  }
  // Both bodies of the near rows are in the island, so the memory holds all four corners.
  CHECK(memory.last.size() == 4);
}
