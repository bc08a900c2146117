// Islands: groups of moving bodies that touch each other, directly or through others. Contacts in
// different islands cannot affect each other within a solve, so each island gets its own LCP: a
// pile of n separate heaps costs n small dense solves instead of one large one. Static bodies
// (the ground, walls) do not join islands: everything resting on the floor is not one island.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// Splits `contacts` into islands, each in the order the contacts came in; islands are ordered by
// their first contact (deterministic).
std::vector<std::vector<const Contact*>> splitIntoIslands(const World& world,
                                                          const std::vector<const Contact*>& contacts);

// Contacts grouped by their pair of bodies: `order` lists contact indices sorted by (a, b), stable
// (within a pair in detection order), and each group is a range [begin, end) of `order`. Both drift
// projections use it to find each pair's deepest point in O(m log m) rather than O(m^2).
struct BodyPairGroups {
  std::vector<std::size_t> order;
  std::vector<std::pair<std::size_t, std::size_t>> groups;
};
BodyPairGroups groupByBodyPair(const std::vector<Contact>& contacts);

}  // namespace tumble
