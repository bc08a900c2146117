#include "dynamics/time_stepping/outrun_contacts.h"

#include <algorithm>

#include "dynamics/body_extent.h"
#include "dynamics/time_stepping/speculative_contacts.h"

namespace tumble {

bool outrunsReach(const World& world, const std::vector<BodyExtent>& extents, const std::vector<double>& reach,
                  double dt, double margin) {
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.is_static || i >= reach.size()) continue;
    const double sweep = (b.velocity().norm() + b.angularVelocity().norm() * extents[i].radius) * dt;
    if (sweep > reach[i] + std::max(margin, kOutrunShare * extents[i].thinnest)) return true;
  }
  return false;
}

long OutrunContacts::add(const World& world, ContactDetector& detector, const StepSettings& settings,
                         const std::vector<double>& body_radius, bool gravity, std::vector<double>& reach,
                         std::vector<Contact>& contacts) {
  const double dt = settings.dt;
  const ContactSettings& cs = settings.contact;
  bodySpins(world, spin_);
  bodyReach(world, body_radius, dt, reach_now_, &spin_);
  for (std::size_t i = 0; i < reach.size() && i < reach_now_.size(); ++i) reach[i] = std::max(reach[i], reach_now_[i]);
  // Not reusing kept manifolds: the poses are those the step's contacts were found at.
  detector.detect(world, cs, found_, &pairs_, &reach, false, settings.threads);
  keepReachableContacts(world, detector, found_, pairs_, dt, gravity, cs.tolerance_m);
  addSweptContacts(world, detector, found_, pairs_, spin_, dt, gravity, cs.margin_m, cs.tolerance_m, settings.threads);
  // The step's contacts by body pair, to find a found contact's neighbours among them.
  const std::size_t had = contacts.size();
  auto key = [](const Contact& c) { return (static_cast<long long>(c.a) << 32) | static_cast<unsigned>(c.b); };
  known_.clear();
  for (std::size_t k = 0; k < had; ++k) known_.emplace_back(key(contacts[k]), k);
  std::sort(known_.begin(), known_.end());
  for (const Contact& c : found_) {
    auto it = std::lower_bound(known_.begin(), known_.end(), std::pair<long long, std::size_t>(key(c), 0));
    bool near = false;
    for (; it != known_.end() && it->first == key(c) && !near; ++it)
      near = (contacts[it->second].point - c.point).norm() <= cs.margin_m;
    if (!near) contacts.push_back(c);
  }
  return static_cast<long>(contacts.size() - had);
}

}  // namespace tumble
