// The edge axes of two boxes. Two boxes' edges run along three directions each, so the axes the
// edge pairs can give are the nine cross products of their axes (the fifteen-axis test of
// S. Gottschalk, M. Lin and D. Manocha, "OBBTree", 1996). Along an axis n turned from A towards B,
// the gap is n . (c_B - c_A) less each box's support radius, sum_k half_k |n . axis_k|, and the
// edges that meet there are A's edge along its axis at the corner n points to and B's at the
// corner -n points to: the pair the Gauss-map test of the general query (sat.cpp) finds crossing
// for this axis, with the same separation up to rounding. Nine axes instead of 144 edge pairs.
#include <cmath>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

AxisQuery queryBoxEdges(const HullView& a, const BoxShape& box_a, const HullView& b, const BoxShape& box_b,
                        double stop_above) {
  Eigen::Vector3d axis_a[3], axis_b[3];
  for (int k = 0; k < 3; ++k) {
    axis_a[k] = a.normals[box_a.plus_face[k]];
    axis_b[k] = b.normals[box_b.plus_face[k]];
  }
  const Eigen::Vector3d between = b.centroid - a.centroid;
  AxisQuery best;
  for (int i = 0; i < 3; ++i) {
    const auto [a1, a2] = otherAxes(i);
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d n = axis_a[i].cross(axis_b[j]);
      const double len2 = n.squaredNorm();
      if (!(len2 > kParallelSine * kParallelSine)) continue;   // parallel (or NaN), as in sat.cpp
      const auto [b1, b2] = otherAxes(j);
      // An axis that is certainly worse than the best so far is not normalised (three divisions):
      // its separation times |n|, from the unnormalised axis, is below the best's times |n| by
      // far more than the roundings that tell the two apart (a few units in the last place of
      // the terms' sizes), so the exact one could be neither better nor equal.
      const double len = std::sqrt(len2);
      if (best.separation > -INFINITY) {
        const double along = std::abs(n.dot(between));
        const double reach = box_a.half[a1] * std::abs(n.dot(axis_a[a1])) + box_a.half[a2] * std::abs(n.dot(axis_a[a2])) +
                             box_b.half[b1] * std::abs(n.dot(axis_b[b1])) + box_b.half[b2] * std::abs(n.dot(axis_b[b2]));
        if (along - reach + 1e-9 * (along + reach) < best.separation * len) continue;
      }
      n /= len;
      if (n.dot(between) < 0) n = -n;
      // The support corners. An axis lying in a face plane of either box (a component of zero)
      // meets that face's edges at their ends, where the Gauss-map test is strict: the face axes
      // give that separation, so the axis is left to them, as there.
      const double ca1 = n.dot(axis_a[a1]), ca2 = n.dot(axis_a[a2]);
      const double cb1 = -n.dot(axis_b[b1]), cb2 = -n.dot(axis_b[b2]);
      if (ca1 == 0 || ca2 == 0 || cb1 == 0 || cb2 == 0) continue;
      const double radius_a = box_a.half[a1] * std::abs(ca1) + box_a.half[a2] * std::abs(ca2);
      const double radius_b = box_b.half[b1] * std::abs(cb1) + box_b.half[b2] * std::abs(cb2);
      const double sep = n.dot(between) - radius_a - radius_b;
      const int edge_a = box_a.edge[i][ca1 > 0][ca2 > 0], edge_b = box_b.edge[j][cb1 > 0][cb2 > 0];
      // Ties go to the pair the general query meets first (A's edge, then B's, by index).
      const bool better = sep > best.separation ||
                          (sep == best.separation && (edge_a < best.index_a || (edge_a == best.index_a && edge_b < best.index_b)));
      if (!better) continue;
      best = {sep, edge_a, edge_b};
      if (sep > stop_above) return best;
    }
  }
  return best;
}

}  // namespace tumble::narrow
