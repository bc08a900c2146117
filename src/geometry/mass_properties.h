// Exact mass properties of convex polyhedra (volume integrals over the faces) and of rounded
// pieces (closed forms), and of unions.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/convex_piece.h"

namespace tumble {

struct MassProperties {
  double mass = 0;                                     // kg
  Eigen::Vector3d center = Eigen::Vector3d::Zero();    // m, centre of mass in the input frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // kg m^2, about `center`, input frame axes
};

// Closed forms for rounded pieces (a sphere, a capsule), rounded_mass.cpp.
double roundedVolume(const ConvexPiece& piece);
MassProperties roundedMassProperties(const ConvexPiece& piece, double density);
// Closed forms for solids of revolution (a cylinder, a cone), revolved_mass.cpp.
double revolvedVolume(const ConvexPiece& piece);
MassProperties revolvedMassProperties(const ConvexPiece& piece, double density);

// Volume in m^3 of a closed convex piece.
double volume(const ConvexPiece& piece);
// Mass properties of a solid piece of uniform density (kg/m^3).
MassProperties massProperties(const ConvexPiece& piece, double density);
// Mass properties of a union of pieces of the same density (pieces must not overlap).
MassProperties massProperties(const std::vector<ConvexPiece>& pieces, double density);

// The principal frame: inertia = R diag(moments) R^T, R a proper rotation (det +1), moments
// ascending. Body-frame vertices are R^T (p - center).
struct PrincipalFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();   // kg m^2
};
PrincipalFrame principalFrame(const Eigen::Matrix3d& inertia);

}  // namespace tumble
