// The narrow phase's output: one normal and up to four points per pair of convex pieces.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace tumble {

struct ContactPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, world: midway between the two surfaces
  double depth = 0;           // m along the normal: > 0 penetrating, < 0 separated (within margin)
  std::uint32_t feature = 0;  // stable id of the feature pair that made the point, for warm starts
};

struct ContactManifold {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, world, from A to B: B is pushed
                                                      // along +normal, A along -normal
  std::vector<ContactPoint> points;                   // 1..8 points
  // Separated pieces closest at a vertex or an edge's end (narrow_phase.cpp, closestPointContact):
  // one point, the normal the direction between the closest points. That direction turns as the
  // pieces move past each other, so a gap along it may never close although it is within reach.
  bool closest_points = false;
};

}  // namespace tumble
