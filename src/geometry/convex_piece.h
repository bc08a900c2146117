// A convex polyhedron: the unit of collision and of mass. A body is one or more of these.
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

  // Moves every vertex by p -> R p + t (used to put pieces in the body's principal frame).
  void transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& t);
  // The thinnest width: the smallest extent of the vertices along a face normal (m). The most two
  // pieces can overlap before one could pass through the other; O(faces x vertices).
  double thickness() const;
};

}  // namespace tumble
