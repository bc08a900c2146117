#include "dynamics/impulse_memory.h"

#include <algorithm>

#include "base/pair_order.h"

namespace tumble {
Eigen::Vector3d ImpulseMemory::localPoint(const World& world, const Contact& c) {
  const RigidBody& A = world.bodies[c.a];
  return A.q.conjugate() * (c.point - A.x);
}

const ImpulseRecord* ImpulseMemory::find(const World& world, const Contact& c, double radius) const {
  // Body A's records, then among them the first of the pair: the records of one body are a dozen
  // in a pile, where a binary search over all of them cost 3 % of its step in cache misses.
  if (c.a < 0 || static_cast<std::size_t>(c.a) + 1 >= first_of_a_.size()) return nullptr;
  auto it = records_.begin() + first_of_a_[static_cast<std::size_t>(c.a)];
  const auto a_end = records_.begin() + first_of_a_[static_cast<std::size_t>(c.a) + 1];
  while (it != a_end && it->b < c.b) ++it;
  if (it == a_end || it->b != c.b) return nullptr;
  const Eigen::Vector3d p = localPoint(world, c);
  // Distance across the normal only: a contact's point lies midway between the surfaces, so it
  // moves along the normal by half the gap as a speculative contact closes (9 mm in a step of a
  // 4 m/s landing at 1/240 s), while it stays put across it.
  const Eigen::Vector3d n = world.bodies[c.a].q.conjugate() * c.normal;
  const ImpulseRecord* best = nullptr;
  double nearest = radius * radius;
  for (; it != a_end && it->b == c.b; ++it) {
    Eigen::Vector3d d = it->local - p;
    double d2 = (d - n * n.dot(d)).squaredNorm();
    if (d2 <= nearest) {
      nearest = d2;
      best = &*it;
    }
  }
  return best;
}

void ImpulseMemory::replace(const std::vector<ImpulseRecord>& records) {
  // Sorted by pair, stable within a pair.
  thread_local PairOrderScratch scratch;
  orderByPair(records.size(), [&](std::size_t i) { return records[i].a; }, [&](std::size_t i) { return records[i].b; },
                  order_, scratch);
  spare_.resize(records.size());
  for (std::size_t k = 0; k < order_.size(); ++k) spare_[k] = records[order_[k]];
  records_.swap(spare_);
  // Where each body's records as A begin: first_of_a_[a] .. first_of_a_[a + 1].
  const std::size_t top = records_.empty() ? 0 : static_cast<std::size_t>(records_.back().a) + 1;
  first_of_a_.assign(top + 1, 0);
  for (const ImpulseRecord& r : records_) ++first_of_a_[static_cast<std::size_t>(r.a) + 1];
  for (std::size_t k = 1; k <= top; ++k) first_of_a_[k] += first_of_a_[k - 1];
}

}  // namespace tumble
