#include "dynamics/sleeping.h"

#include <numeric>

#include "dynamics/contact_detection.h"

namespace tumble {

SleepKeeper::SleepKeeper(const World& world)
    : quiet_s_(world.bodies.size(), 0.0),
      island_(world.bodies.size(), -1),
      inv_mass_(world.bodies.size(), 0.0),
      inv_inertia_(world.bodies.size(), Eigen::Vector3d::Zero()),
      parent_(world.bodies.size()),
      supported_(world.bodies.size()),
      restless_(world.bodies.size()),
      id_of_root_(world.bodies.size()) {}

int SleepKeeper::find(int body) {
  while (parent_[body] != body) body = parent_[body] = parent_[parent_[body]];
  return body;
}

bool SleepKeeper::wakeTouched(World& world, const std::vector<Contact>& contacts, ContactDetector& detector) {
  bool woke = false;
  for (const Contact& c : contacts) {
    for (auto [sleeper, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      if (island_[sleeper] < 0 || world.bodies[other].is_static) continue;
      wake(world, island_[sleeper], detector);
      woke = true;
    }
  }
  return woke;
}

bool SleepKeeper::settle(World& world, const std::vector<Contact>& contacts, const SleepSettings& settings,
                         double dt, ContactDetector& detector) {
  const int n = static_cast<int>(world.bodies.size());
  bool any_quiet = false;
  for (int b = 0; b < n; ++b) {
    const RigidBody& body = world.bodies[b];
    if (body.is_static) continue;
    const bool quiet = body.velocity().norm() < settings.speed_m_s &&
                       body.angularVelocity().norm() < settings.spin_rad_s;
    quiet_s_[b] = quiet ? quiet_s_[b] + dt : 0.0;
    any_quiet |= quiet_s_[b] >= settings.after_s;
  }
  if (!any_quiet) return false;   // the common case while things move: no islands to build

  std::iota(parent_.begin(), parent_.end(), 0);
  std::fill(supported_.begin(), supported_.end(), 0);
  std::fill(restless_.begin(), restless_.end(), 0);
  for (const Contact& c : contacts) {
    const bool fixed_a = world.bodies[c.a].is_static, fixed_b = world.bodies[c.b].is_static;
    if (!fixed_a && !fixed_b) parent_[find(c.a)] = find(c.b);
    else if (fixed_a != fixed_b) supported_[fixed_a ? c.b : c.a] = 1;
  }
  // Joined bodies sleep and wake together (a link frozen under a moving one would hold it to a
  // body that no longer moves), and a joint to the world or a static body supports.
  for (const Joint& j : world.joints) {
    const bool fixed_a = j.a < 0 || world.bodies[j.a].is_static, fixed_b = j.b < 0 || world.bodies[j.b].is_static;
    if (!fixed_a && !fixed_b) parent_[find(j.a)] = find(j.b);
    else if (fixed_a != fixed_b) supported_[fixed_a ? j.b : j.a] = 1;
  }
  // An island sleeps when every body in it has been quiet long enough and one of them rests on
  // something fixed: a body floating free at a crawl keeps its crawl (it is not at rest, it is
  // coasting), and a body that is slow only at the top of a bounce is not quiet for long.
  // Per island, gathered at its root (a root's own flags are its own or already the island's).
  for (int b = 0; b < n; ++b) {
    if (world.bodies[b].is_static) continue;
    const int root = find(b);
    restless_[root] |= quiet_s_[b] < settings.after_s;
    supported_[root] |= supported_[b];
  }
  std::fill(id_of_root_.begin(), id_of_root_.end(), -1);
  bool slept = false;
  for (int b = 0; b < n; ++b) {
    if (world.bodies[b].is_static) continue;
    const int root = find(b);
    if (restless_[root] || !supported_[root]) continue;
    if (id_of_root_[root] < 0) {
      id_of_root_[root] = next_island_++;
      ++counters_.islands_slept;
    }
    freeze(world, b, id_of_root_[root], detector);
    slept = true;
  }
  return slept;
}

void SleepKeeper::freeze(World& world, int b, int island, ContactDetector& detector) {
  RigidBody& body = world.bodies[b];
  inv_mass_[b] = body.inv_mass;
  inv_inertia_[b] = body.inv_inertia_body;
  body.P.setZero();
  body.L.setZero();
  body.inv_mass = 0;
  body.inv_inertia_body.setZero();
  body.is_static = true;
  body.asleep = true;
  island_[b] = island;
  ++counters_.asleep_now;
  detector.setFixed(b, true);
}

void SleepKeeper::wake(World& world, int island, ContactDetector& detector) {
  ++counters_.islands_woken;
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    if (island_[b] != island) continue;
    RigidBody& body = world.bodies[b];
    body.inv_mass = inv_mass_[b];
    body.inv_inertia_body = inv_inertia_[b];
    body.is_static = false;
    body.asleep = false;
    island_[b] = -1;
    quiet_s_[b] = 0;
    --counters_.asleep_now;
    detector.setFixed(static_cast<int>(b), false);
  }
}

}  // namespace tumble
