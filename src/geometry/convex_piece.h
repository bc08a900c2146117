// A convex piece: the unit of collision and of mass. A body is one or more of these. Most are
// convex polyhedra; a rounded piece (radius_m > 0) is its core swept by a ball of that radius: a
// point for an exact sphere, a segment for a capsule (Minkowski sum of the core and the ball; the
// "convex radius" of Jolt and Box2D, here the whole shape). Its surface is smooth, so contacts
// with it come from the distance between cores (collision/rounded_contact.h), not from faces.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace tumble {

struct ConvexPiece {
  std::string name;                             // from the mesh file (for messages), may be empty
  std::vector<Eigen::Vector3d> vertices;        // hull vertices only, no interior points
  std::vector<std::vector<int>> faces;          // vertex indices, counter-clockwise seen from outside;
                                                // coplanar triangles merged into one polygon
  std::vector<Eigen::Vector3d> face_normals;    // outward, unit length, one per face
  std::vector<std::pair<int, int>> edges;       // each undirected hull edge once (first < second)
  double radius_m = 0;                          // > 0: rounded; vertices are then the core only
                                                // (one point, or a segment's two ends; no faces)

  bool rounded() const { return radius_m > 0; }

  // Moves every vertex by p -> R p + t (used to put pieces in the body's principal frame).
  void transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& t);
  // The thinnest width: the smallest extent of the vertices along a face normal (m), or a rounded
  // piece's diameter. The most two pieces can overlap before one could pass through the other;
  // O(faces x vertices).
  double thickness() const;
};

}  // namespace tumble
