// Penetration measured geometrically from poses, as docs/bench/scenes.md defines it, so every
// engine is judged by the same ruler and never by its own contact reports.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tumble::bench {

struct BoxPose {
  Eigen::Vector3d half_extents;   // m
  Eigen::Vector3d x;              // m, centre
  Eigen::Matrix3d R;              // box axes -> world (columns are the axes)
};

// Depth of a box below the ground plane z = 0: max(0, -lowest corner z).
double groundDepth(const BoxPose& box);
// Overlap of two boxes: the smallest projection overlap over the 15 separating-axis directions
// (3 + 3 face normals, 9 edge cross products); 0 when some axis separates them. Exact for boxes.
double boxOverlap(const BoxPose& a, const BoxPose& b);

}  // namespace tumble::bench
