// Hard case 3 (docs/hard-cases.md): redundant contacts. Four coplanar corners with one normal make
// Baraff's matrix A singular (D. Baraff, "Fast contact force computation for nonpenetrating rigid
// bodies", SIGGRAPH 1994); eight duplicated corners and a slab's sixteen leg corners more so.
// The resting-force solve must still terminate, carry the weight exactly, and not put the weight
// on one contact with large opposing forces on others.
#include <catch2/catch.hpp>

#include <random>

#include "dynamics/contact_detection.h"
#include "dynamics/contact_rows.h"
#include "dynamics/baraff/resting_forces.h"
#include "hard_run.h"

using namespace tumble;

namespace {

// The contacts of a scene's bodies resting on the ground, as the pipeline finds them.
std::vector<Contact> restingContacts(const World& world) {
  ContactDetector detector(world);
  std::vector<Contact> contacts;
  detector.detect(world, ContactSettings{}, contacts);
  return contacts;
}

struct RestOutcome {
  double weight_error = 0;       // |sum f_n - m g| / m g, from the LCP's forces
  double largest_share = 0;      // largest single normal force / m g
  double acceleration = 0;       // |a| + |alpha| size of the body under gravity + contact forces, / g
  int pivots = 0, variables = 0, passes = 1;   // passes: of the friction-bound fixed point
  bool solved = false, finite = false;
};

RestOutcome solveRest(const World& world, const std::vector<Contact>& contacts) {
  const RigidBody& body = world.bodies[1];
  const double mg = body.mass * world.gravity.norm();
  RestOutcome out;
  std::vector<const Contact*> set;
  for (const Contact& c : contacts) set.push_back(&c);
  // The LCP alone: its individual forces and its pivots.
  ContactLcp lcp = buildContactLcp(world, set, std::vector<char>(set.size(), 1));
  for (std::size_t r = 0; r < lcp.rows.size(); ++r) {
    const ContactRow& row = lcp.rows[r];
    // free relative acceleration of B against A along the row: gravity on the moving body only
    Eigen::Vector3d ga = world.bodies[row.a].is_static ? Eigen::Vector3d::Zero() : world.gravity;
    Eigen::Vector3d gb = world.bodies[row.b].is_static ? Eigen::Vector3d::Zero() : world.gravity;
    lcp.problem.b[r] = row.dir.dot(gb - ga);
  }
  ContactSolveStats stats;
  lcp::LcpResult r = solveContactLcp(lcp.problem, stats);
  out.solved = r.status == lcp::LcpStatus::Solved;
  out.finite = r.f.allFinite();
  out.pivots = r.iterations;
  out.passes = std::max(1, r.friction_passes);
  out.variables = lcp.problem.size();
  double sum = 0;
  for (int row : lcp.normal_row) {
    sum += r.f[row];
    out.largest_share = std::max(out.largest_share, r.f[row] / mg);
  }
  out.weight_error = std::abs(sum - mg) / mg;
  // The pipeline's stage: gravity plus the resting forces it adds must leave the body at rest.
  std::vector<Wrench> wrenches(world.bodies.size());
  wrenches[1].force = body.mass * world.gravity;
  const ContactSettings settings;
  addRestingForces(contacts, {world, settings, 0, nullptr, wrenches, stats});
  double size = 0;
  for (const Eigen::Vector3d& v : body.pieces[0].vertices) size = std::max(size, v.norm());
  Eigen::Vector3d a = wrenches[1].force * body.inv_mass;
  Eigen::Vector3d alpha = body.rotation() * body.inv_inertia_body.cwiseProduct(body.rotation().transpose() * wrenches[1].torque);
  out.acceleration = (a.norm() + alpha.norm() * size) / world.gravity.norm();
  return out;
}

void checkRest(const RestOutcome& out) {
  INFO("weight error " << out.weight_error << ", largest share " << out.largest_share << " mg, |a| "
                       << out.acceleration << " g, pivots " << out.pivots << " for " << out.variables << " variables");
  CHECK(out.finite);
  CHECK(out.solved);
  CHECK(out.weight_error < 1e-9);
  CHECK(out.acceleration < 1e-9);
  CHECK(out.largest_share <= 10);
}

std::vector<Contact> moved(std::vector<Contact> contacts, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1e-9, 1e-9);
  for (Contact& c : contacts) c.point += Eigen::Vector3d(u(rng), u(rng), u(rng));
  return contacts;
}

}  // namespace

TEST_CASE("redundant contacts: a box on 4 and on 8 (duplicated) corners carries its weight", "[hard][redundant]") {
  BuiltWorld built = buildWorld(hard::loadHardScene("redundant_box"));
  std::vector<Contact> four = restingContacts(built.world);
  REQUIRE(four.size() == 4);
  std::vector<Contact> eight = four;
  eight.insert(eight.end(), four.begin(), four.end());
  for (const std::vector<Contact>* set : {&four, &eight}) {
    INFO(set->size() << " contacts");
    RestOutcome out = solveRest(built.world, *set);
    checkRest(out);
    // At most 2n pivots; with friction the solver repeats its pass per update of the friction
    // bounds, so at most 2n per pass.
    CHECK(out.pivots <= 2 * out.variables * out.passes);
    RestOutcome nudged = solveRest(built.world, moved(*set, 7));
    checkRest(nudged);
  }
}

TEST_CASE("redundant contacts: a slab on four legs (16 coplanar corners) carries its weight", "[hard][redundant]") {
  BuiltWorld built = buildWorld(hard::loadHardScene("slab_on_legs"));
  std::vector<Contact> sixteen = restingContacts(built.world);
  REQUIRE(sixteen.size() == 16);
  for (const std::vector<Contact>& set : {sixteen, moved(sixteen, 11)}) {
    RestOutcome out = solveRest(built.world, set);
    checkRest(out);
    CHECK(out.pivots <= 2 * out.variables * out.passes);
  }
}

TEST_CASE("redundant contacts: the box and the slab stand still through the whole pipeline", "[hard][redundant]") {
  for (const char* name : {"redundant_box", "slab_on_legs"}) {
    Scene scene = hard::loadHardScene(name);
    BuiltWorld start = buildWorld(scene);
    double max_speed = 0;
    hard::HardRun run = hard::simulate(scene, 2, [&](const World& w) {
      max_speed = std::max(max_speed, w.bodies[1].velocity().norm() + w.bodies[1].angularVelocity().norm());
      return true;
    });
    INFO(name << ": largest speed " << max_speed << ", moved " << (run.world.bodies[1].x - start.world.bodies[1].x).norm());
    CHECK(max_speed < 1e-9);
    CHECK((run.world.bodies[1].x - start.world.bodies[1].x).norm() < 1e-9);
    CHECK(run.counters.contacts.failures == 0);
  }
}
