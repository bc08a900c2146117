// One contact point between two bodies, as the dynamics stages see it, and how a pair's
// materials combine (the settings that decide when bodies touch, collide or rest: settings.h).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "dynamics/settings.h"

namespace tumble {

struct Contact {
  int a = -1, b = -1;                                   // body indices; b may be static (the ground)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      // m, world, midway between the surfaces
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();    // unit, world, from A to B
  double depth = 0;                                     // m: > 0 penetrating, < 0 separated
  double restitution = 0, friction = 0;                 // of the pair (see combineMaterials)
  // Separated pieces closest at a vertex or an edge's end (collision/contact_manifold.h): the
  // normal turns as they move, so the gap along it says little about whether they will meet.
  bool closest_points = false;
  // Rounding radii of the two pieces (a sphere's, a capsule's; 0 for a polyhedron): a rounded
  // surface rolls over the contact, whose motion follows the piece's core point behind it.
  double radius_a = 0, radius_b = 0;
};

// Material of a contact pair. Friction: geometric mean (two equal values give that value; an ice
// body slides on anything). Restitution: the mean, so two equal values give that value.
inline double combineFriction(double a, double b) { return std::sqrt(a * b); }
inline double combineRestitution(double a, double b) { return 0.5 * (a + b); }

}  // namespace tumble
