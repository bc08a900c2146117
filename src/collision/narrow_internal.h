// Internal to the narrow phase (not for other layers): both pieces expressed in one working frame,
// the scratch buffers reused across calls, the feature ids and the tolerances.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cmath>
#include <cstdint>
#include <vector>

#include "collision/collision_hull.h"
#include "collision/contact_manifold.h"
#include "collision/narrow_phase.h"

namespace tumble::narrow {

// Tolerances. Sizes are the smaller hull's extent, so they scale with the scene's units.
//
// Edge pairs whose directions make a sine below this are treated as parallel and skipped: the
// normalised cross product has direction error ~ 1e-16 / sine, and for parallel edges the face
// axes beside them already give the pair's separation (skipping only lowers the SAT value, so it
// stays a lower bound on the distance).
constexpr double kParallelSine = 1e-6;
// Feature choice (Gregorius, "Robust contact creation for physics simulations", GDC 2015): an edge
// axis must beat the best face by 10 % of its value plus kAbsTolerance * size, and B's face must
// beat A's by 2 % plus the same, so near ties always resolve to A's face: a box resting flat stays
// face-face whatever rounding does to edge axes that coincide with the face normal.
constexpr double kEdgeRelTolerance = 0.10;
constexpr double kFaceRelTolerance = 0.02;
constexpr double kAbsTolerance = 1e-3;
// The manifold's deepest point must be as deep as the SAT says within this times size; a feature
// kept by the tolerances above that misses it gives way to the least-penetration axis
// (narrow_phase.cpp, agreesWithSat).
constexpr double kDepthAgreement = 1e-9;
// Faces whose outward normals (B's negated) agree to within about 0.8 degrees rest face on face:
// their contact normal stays the reference face's (and only such manifolds are kept between
// steps, kept_manifold.h).
constexpr double kOppositeFaces = 0.9999;

// One piece as seen in the working frame (the frame of the piece with more vertices; the other is
// transformed into it, so only the smaller one pays for the transform).
struct HullView {
  const CollisionHull* hull = nullptr;
  const Eigen::Vector3d* vertices = nullptr;
  const Eigen::Vector3d* normals = nullptr;
  const double* offsets = nullptr;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  int vertexCount() const { return int(hull->piece->vertices.size()); }
  int faceCount() const { return int(hull->piece->faces.size()); }
  int edgeCount() const { return int(hull->piece->edges.size()); }
};

struct ClipVertex {
  Eigen::Vector3d p;
  std::uint32_t id;  // where it came from: a vertex, or an edge cut by a side plane
};

// One edge's arc on the Gauss map: its two face normals (negated for B, whose Gauss map enters
// the Minkowski difference A - B reversed) and their cross product.
struct EdgeArc {
  Eigen::Vector3d n0, n1, n1xn0;
};

// Reused by every call on this thread: after the first few calls the hot path allocates nothing.
struct Scratch {
  std::vector<Eigen::Vector3d> vertices, normals;  // the transformed piece
  std::vector<double> offsets;
  std::vector<ClipVertex> poly, poly_next;         // Sutherland-Hodgman ping-pong
  std::vector<EdgeArc> arcs_a, arcs_b;             // edge query
  std::vector<double> plane_a_dot_b, plane_b_dot_a;  // edge query: arc planes against face normals
};
Scratch& scratch();

// Order-dependent mix of small integers into a 32-bit feature id (boost::hash_combine's scheme).
inline std::uint32_t mixFeature(std::uint32_t h, std::uint32_t x) {
  return h ^ (x + 0x9e3779b9u + (h << 6) + (h >> 2));
}

// sat.cpp
struct AxisQuery {
  double separation = -INFINITY;  // m; -inf when no axis of this kind was valid
  int index_a = -1, index_b = -1;
};
double faceSeparation(const HullView& ref, int face, const HullView& other);
// Faces of `ref` against the vertices of `other`; returns at once when one exceeds stop_above.
AxisQuery queryFaces(const HullView& ref, const HullView& other, double stop_above);
// false when the pair is not a face of the Minkowski difference or the edges are parallel.
bool edgeAxis(const HullView& a, int ea, const HullView& b, int eb, Eigen::Vector3d& axis,
              double& separation);
AxisQuery queryEdges(const HullView& a, const HullView& b, double stop_above);

// box_sat.cpp: the same for two boxes, from their axes and half extents.
AxisQuery queryBoxEdges(const HullView& a, const BoxShape& box_a, const HullView& b, const BoxShape& box_b,
                        double stop_above);

// clip.cpp: contacts in the working frame; the normal of `out` is set from A to B.
bool faceContact(const HullView& ref, int ref_face, const HullView& inc, bool ref_is_a,
                 double margin, ContactManifold& out);
bool edgeContact(const HullView& a, int ea, const HullView& b, int eb, double margin,
                 ContactManifold& out);
// The overlap of edge (a0, a1) of A and edge (b0, b1) of B, when they are within kAbsTolerance of
// parallel: a point at each end of it, with n as the normal and the depth along n at each end.
// false (and `out` untouched) when they are not parallel or do not overlap.
bool edgeOverlapContact(const HullView& a, int a0, int a1, const HullView& b, int b0, int b1,
                        const Eigen::Vector3d& n, ContactManifold& out);
// Two pieces whose support features along n (A's highest, B's lowest) are parallel edges, each
// standing clear of its piece's other vertices by more than `clear`: the contact is the overlap of
// the two edges, one point at each end, with n as the normal and the depth along n at each end.
// false (and `out` untouched) when either feature is not an edge or they do not overlap.
bool parallelEdgeContact(const HullView& a, const HullView& b, const Eigen::Vector3d& n, double clear,
                         ContactManifold& out);

// distance.cpp: the distance between A and B (0 when they overlap) and a closest point of each,
// by GJK; exact to rounding for separated pieces.
// (The result type is the public one, in the working frame here.)
PieceDistance distance(const HullView& a, const HullView& b);

// rounded_contact.cpp: pairs where either piece is rounded (a sphere, a capsule): from the
// distance between the cores less the radii. The contact (false when apart by more than the
// margin), the signed separation and its axis (A to B), and the distance with closest points.
bool roundedContact(const HullView& a, const HullView& b, double margin, ContactManifold& out);
double roundedSeparation(const HullView& a, const HullView& b, Eigen::Vector3d& axis);
PieceDistance roundedDistance(const HullView& a, const HullView& b);

// The rim points a flat disc (a cylinder's end, a cone's base) is held at, against a face or the
// ground: a regular octagon inside the circle, whose support polygon loses 1 - cos(pi/8) = 7.6 %
// of the radius at its worst (between two points). Point k of the disc about `centre`, radius r,
// spanned by u and v (unit, square to each other and to the axis), from u.
constexpr int kDiscRimPoints = 8;
inline Eigen::Vector3d discRimPoint(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                    double r, int k) {
  const double t = 2 * M_PI * k / kDiscRimPoints;
  return centre + r * (std::cos(t) * u + std::sin(t) * v);
}

// support_contact.cpp: pairs where either piece is a solid of revolution (a cylinder, a cone):
// from the two support mappings (GJK and EPA, support_query.h), the contact points from the
// features facing each other. The same three answers as the rounded pairs'.
bool supportContact(const HullView& a, const HullView& b, double margin, ContactManifold& out);
double supportSeparation(const HullView& a, const HullView& b, Eigen::Vector3d& axis);
PieceDistance supportDistance(const HullView& a, const HullView& b);

// manifold_reduce.cpp: keeps 4 points (deepest, farthest from it, then the two that enlarge the
// support polygon most), in that order, then up to 4 more corners where each adds a large share
// of the polygon (faces turned against each other); deterministic.
void reduceManifold(std::vector<ContactPoint>& points, const Eigen::Vector3d& normal);

}  // namespace tumble::narrow
