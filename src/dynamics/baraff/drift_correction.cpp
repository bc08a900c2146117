#include "dynamics/baraff/drift_correction.h"

#include <algorithm>
#include <cstdint>

#include "dynamics/contact_islands.h"
#include "dynamics/position_projection.h"

namespace tumble {

int correctPenetration(World& world, const std::vector<Contact>& contacts, double tol) {
  // Once per pair of bodies, all its points together: the four corners of a face resting too deep
  // share one depth and are lifted together, and a landing edge is lifted by turning about the
  // resting one rather than by lifting both.
  const BodyPairGroups grouped = groupByBodyPair(contacts);
  struct Push {
    std::size_t first_seen, group;
  };
  std::vector<Push> pushes;
  for (std::size_t g = 0; g < grouped.groups.size(); ++g) {
    const auto& [begin, end] = grouped.groups[g];
    std::size_t first = SIZE_MAX;
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = grouped.order[k];
      if (contacts[i].depth > tol) first = std::min(first, i);
    }
    if (first != SIZE_MAX) pushes.push_back({first, g});
  }
  // Pairs are projected in the order their first too-deep point was detected (deterministic).
  std::sort(pushes.begin(), pushes.end(), [](const Push& x, const Push& y) { return x.first_seen < y.first_seen; });
  std::vector<const Contact*> points;
  int moved = 0;
  for (const Push& p : pushes) {
    const auto& [begin, end] = grouped.groups[p.group];
    points.clear();
    for (std::size_t k = begin; k < end; ++k) points.push_back(&contacts[grouped.order[k]]);
    if (projectPair(world, points, tol)) ++moved;
  }
  return moved;
}

}  // namespace tumble
