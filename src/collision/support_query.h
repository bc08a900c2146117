// The distance, or the penetration, between two convex sets known only by their support mappings:
// smooth shapes with no vertex list (cylinders, cones) against any other convex shape.
//
// Apart, GJK finds the closest points (E. G. Gilbert, D. W. Johnson and S. S. Keerthi, "A fast
// procedure for computing the distance between complex objects in three-dimensional space", IEEE
// Journal of Robotics and Automation, 1988; closest points of a simplex by Voronoi regions,
// C. Ericson, "Real-Time Collision Detection", 2005). Overlapping, the expanding polytope algorithm
// (EPA) grows GJK's simplex inside the Minkowski difference A - B until its face nearest the origin
// lies on the difference's boundary to within the tolerance (G. van den Bergen, "Proximity queries
// and penetration depth computation on 3D game objects", Game Developers Conference, 2001). Where
// the sets are curved, a few Newton steps then take the normal and points from the polytopes'
// chord accuracy (the square root of the tolerance) to rounding (support_query.cpp).
#pragma once

#include <Eigen/Core>
#include <functional>

namespace tumble {

// A convex set by its support mapping: the point of the set farthest along d (any d != 0, not
// necessarily unit). Ties may return any farthest point, but deterministically.
using SupportMapping = std::function<Eigen::Vector3d(const Eigen::Vector3d& d)>;

struct SupportQuery {
  bool overlapping = false;  // also for sets that touch, or are apart by less than the tolerance
  double distance = 0;       // m, >= 0: the distance between the sets when apart, 0 when overlapping
  double depth = 0;          // m, >= 0: the penetration depth (smallest translation that parts them) when overlapping, 0 when apart
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, from A to B: when apart (point_b - point_a) / distance;
                                                      // when overlapping, moving B by +depth * normal parts them
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  // apart: the closest points; overlapping: the deepest point of each
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();  // (point_a on A's surface along +normal, point_b on B's along -normal,
                                                      //  point_a - point_b = depth * normal up to the tolerance)
};

// `centre_a`, `centre_b`: interior points (the first search direction is between them).
// `tolerance` (m): the answer's accuracy (distance and depth exact to it; callers pass ~1e-12 x the sets' size).
// Deterministic, never NaN for finite supports, and bounded: at most 128 GJK and 128 EPA iterations
// (one support of each set apiece) and 9 Newton steps (up to 12 apiece).
SupportQuery supportQuery(const SupportMapping& a, const SupportMapping& b, const Eigen::Vector3d& centre_a,
                          const Eigen::Vector3d& centre_b, double tolerance);

}  // namespace tumble
