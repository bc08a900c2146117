// When two convex pieces moving freely first touch: conservative advancement (B. Mirtich,
// "Impulse-based dynamic simulation of rigid body systems", PhD thesis, UC Berkeley, 1996;
// E. Coumans, "Continuous collision detection and physics", 2005). At each iterate the exact
// distance d and the direction n between the closest points bound how soon the pieces can meet:
// the gap along n closes no faster than the relative speed along n plus |w| r for each piece, so
// the motion may advance by d over that bound without passing through. The closest features are
// followed as they turn, so a vertex passing beside an edge is seen to miss it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "collision/collision_hull.h"

namespace tumble {

// A piece's free motion over the horizon: its body's pose now, linear velocity of the body's
// origin (the centre of mass) and angular velocity, world frame.
struct FreeMotion {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();
  Eigen::Isometry3d at(double t) const;   // the pose after t seconds
};

struct FirstTouch {
  bool touches = false;   // they come within `within` of each other before the horizon
  double time = 0;        // s: when (0 when already that close)
  // At that time (world): the direction from A to B between the closest points, and those points.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero(), point_b = Eigen::Vector3d::Zero();
};

// Whether A and B, moving as given, come within `within` (m, > 0) of each other in [0, horizon].
// Conservative: when the advancement has not settled after its iteration cap, they are taken to
// touch where it stopped.
FirstTouch firstTouch(const CollisionHull& a, const FreeMotion& ma, const CollisionHull& b, const FreeMotion& mb,
                      double horizon, double within);

}  // namespace tumble
