// Islands: groups of moving bodies that touch each other, directly or through others. Contacts in
// different islands cannot affect each other within a solve, so each island gets its own LCP: a
// pile of n separate heaps costs n small dense solves instead of one large one. Static bodies
// (the ground, walls) do not join islands: everything resting on the floor is not one island.
#pragma once

#include <span>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// Splits `contacts` into islands, each in the order the contacts came in; islands are ordered by
// their first contact (deterministic).
std::vector<std::vector<const Contact*>> splitIntoIslands(const World& world,
                                                          const std::vector<const Contact*>& contacts);

// The same islands laid end to end in one array, for a step that splits every step and must not
// allocate for it: the buffers are kept from one split to the next.
class ContactIslands {
 public:
  void split(const World& world, std::span<const Contact* const> contacts);
  std::size_t size() const { return begin_.empty() ? 0 : begin_.size() - 1; }
  std::span<const Contact* const> operator[](std::size_t k) const {
    return std::span<const Contact* const>(contacts_).subspan(begin_[k], begin_[k + 1] - begin_[k]);
  }

 private:
  std::vector<const Contact*> contacts_;   // island by island
  std::vector<std::size_t> begin_;         // island k is contacts_[begin_[k], begin_[k + 1])
  std::vector<int> parent_, island_of_root_, island_of_contact_;
};

// Contacts grouped by their pair of bodies: `order` lists contact indices sorted by (a, b), stable
// (within a pair in detection order), and each group is a range [begin, end) of `order`. Both drift
// projections use it to find each pair's deepest point in O(m log m) rather than O(m^2).
struct BodyPairGroups {
  std::vector<std::size_t> order;
  std::vector<std::pair<std::size_t, std::size_t>> groups;
};
BodyPairGroups groupByBodyPair(const std::vector<Contact>& contacts);
// The same into `out`, whose buffers are reused.
void groupByBodyPair(const std::vector<Contact>& contacts, BodyPairGroups& out);

}  // namespace tumble
