// A convex piece: the unit of collision and of mass. A body is one or more of these. Most are
// convex polyhedra; a rounded piece (radius_m > 0) is its core swept by a ball of that radius: a
// point for an exact sphere, a segment for a capsule (Minkowski sum of the core and the ball; the
// "convex radius" of Jolt and Box2D, here the whole shape). Its surface is smooth, so contacts
// with it come from the distance between cores (collision/rounded_contact.cpp), not from faces.
// A solid of revolution (a cylinder, a cone) is given by its axis, vertices[0] -> vertices[1], and
// the radius of its discs; its contacts come from its support mapping (collision/support_contact.cpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>
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
  // A solid of revolution about the axis vertices[0] -> vertices[1] (no faces): a cylinder has a
  // disc of disc_radius_m at both ends, a cone one at vertices[0] and its apex at vertices[1].
  enum class Revolution : std::uint8_t { None, Cylinder, Cone };
  Revolution revolution = Revolution::None;
  double disc_radius_m = 0;
  // A tube: a cylinder with a bore of this radius along its axis. Only its mass and its picture
  // are hollow; other pieces collide with its outer cylinder (its convex hull), as a wheel's tyre
  // or a pipe rolling on the ground needs, but nothing can enter the bore.
  double bore_radius_m = 0;

  bool rounded() const { return radius_m > 0; }
  bool revolved() const { return revolution != Revolution::None; }
  bool smooth() const { return rounded() || revolved(); }   // no face list: not for the SAT
  // The point of the piece farthest along d (body frame; any d != 0).
  Eigen::Vector3d support(const Eigen::Vector3d& d) const;
  // The same with the piece's vertices moved rigidly to `moved` (count of them, in the same order;
  // the narrow phase's working frame): its radii do not change under the move.
  Eigen::Vector3d supportAt(const Eigen::Vector3d* moved, std::size_t count, const Eigen::Vector3d& d) const;
  // The radius of the surface that rolls over a contact of normal n (body frame, unit): a rounded
  // piece's radius, a cylinder's on its side; 0 where the contact stays on the same material
  // points (a face, an edge, a rim, a cone's side: its curvature along the side is not modelled).
  double rollingRadius(const Eigen::Vector3d& n) const;

  // Moves every vertex by p -> R p + t (used to put pieces in the body's principal frame).
  void transform(const Eigen::Matrix3d& R, const Eigen::Vector3d& t);
  // The thinnest width: the smallest extent of the vertices along a face normal (m), a rounded
  // piece's diameter, or a lower bound for a solid of revolution (a cone's inscribed ball). The most two pieces can overlap before one could pass through the other;
  // O(faces x vertices).
  double thickness() const;
};

}  // namespace tumble
