// The separating-axis test (Yang, "Rigid Bodies and Contacts", 2020: "axes are normals of faces or the cross product of two
// edges, one from each object"; Xiang, "Robot Control and Physical Simulation", 2020: O(e1 e2) axes). Edge pairs are pruned on the Gauss map:
// only pairs whose arcs cross form a face of the Minkowski difference A - B, and only those can
// give the separating plane (Gregorius, GDC 2013/2015).
#include <array>
#include <cassert>
#include <cmath>
#include <optional>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

// Gap between the plane of `face` of ref and the deepest vertex of other along its normal.
double faceSeparation(const HullView& ref, int face, const HullView& other) {
  const Eigen::Vector3d n = ref.normals[face];
  // A box's deepest point along n lies its support radius, sum_k half_k |n . axis_k|, below its
  // centre: three products for the eight corners' (box_shape.h puts them there to 1e-12 of the
  // size). A box against a box spent a fifth of its narrow phase here.
  if (const std::optional<BoxShape>& box = other.hull->box) {
    double radius = 0;
    for (int k = 0; k < 3; ++k) radius += box->half[k] * std::abs(n.dot(other.normals[box->plus_face[k]]));
    return n.dot(other.centroid) - radius - ref.offsets[face];
  }
  double lowest = INFINITY;
  for (int v = 0; v < other.vertexCount(); ++v) lowest = std::min(lowest, n.dot(other.vertices[v]));
  return lowest - ref.offsets[face];
}

AxisQuery queryFaces(const HullView& ref, const HullView& other, double stop_above) {
  AxisQuery best;
  for (int f = 0; f < ref.faceCount(); ++f) {
    const double s = faceSeparation(ref, f, other);
    if (s > best.separation) best = {s, f, f};
    if (s > stop_above) break;
  }
  return best;
}

namespace {

// Arcs a->b (A's two face normals at its edge) and c->d (B's, negated) cross on the unit sphere
// iff c, d lie on opposite sides of the plane of a, b, a and b on opposite sides of the plane of
// c, d, and the arcs lie in one hemisphere. Strict: arcs meeting at an end point (axis-aligned
// boxes) are left to the face axes, which give the same separation.
bool arcsCross(const EdgeArc& ab, const EdgeArc& cd) {
  const double cba = cd.n0.dot(ab.n1xn0), dba = cd.n1.dot(ab.n1xn0);
  const double adc = ab.n0.dot(cd.n1xn0), bdc = ab.n1.dot(cd.n1xn0);
  return cba * dba < 0 && adc * bdc < 0 && cba * bdc > 0;
}

EdgeArc arcOf(const HullView& h, int edge, double sign) {
  const auto& [f0, f1] = h.hull->edge_faces[edge];
  EdgeArc arc{sign * h.normals[f0], sign * h.normals[f1], Eigen::Vector3d::Zero()};
  arc.n1xn0 = arc.n1.cross(arc.n0);
  return arc;
}

// For a Minkowski-face edge pair the edge points are the supports of A along +axis and of B along
// -axis, so the gap along the axis is axis . (pb - pa), with the axis turned away from A's interior.
bool minkowskiEdgeAxis(const HullView& a, int ea, const HullView& b, int eb, Eigen::Vector3d& axis,
                       double& separation) {
  const auto& [a0, a1] = a.hull->piece->edges[ea];
  const auto& [b0, b1] = b.hull->piece->edges[eb];
  const Eigen::Vector3d pa = a.vertices[a0], da = a.vertices[a1] - pa;
  const Eigen::Vector3d pb = b.vertices[b0], db = b.vertices[b1] - pb;
  axis = da.cross(db);
  // |da x db| = sin(angle) |da| |db|, compared squared to save two square roots
  const double len2 = axis.squaredNorm();
  if (!(len2 > kParallelSine * kParallelSine * da.squaredNorm() * db.squaredNorm())) {
    return false;  // parallel (or NaN)
  }
  axis /= std::sqrt(len2);
  if (axis.dot(pa - a.centroid) < 0) axis = -axis;
  separation = axis.dot(pb - pa);
  return true;
}

}  // namespace

bool edgeAxis(const HullView& a, int ea, const HullView& b, int eb, Eigen::Vector3d& axis,
              double& separation) {
  if (!arcsCross(arcOf(a, ea, 1.0), arcOf(b, eb, -1.0))) return false;
  return minkowskiEdgeAxis(a, ea, b, eb, axis, separation);
}

// The Gauss-map test of edge i of A against edge j of B takes the dot products of A's arc plane
// (n1 x n0 of edge i) with B's two face normals at edge j, and of B's arc plane with A's two face
// normals at edge i. Each is a dot of one edge's arc plane with one face normal of the other piece,
// so they are computed once per (edge, face) — E_a F_b + F_a E_b dot products instead of 4 E_a E_b
// (a box pair: 144 instead of 576) — with the same operands in the same order as arcsCross, so
// every test comes out bit for bit as it did. The loop over pairs then only compares signs, and
// only pairs that pass pay for an axis.
AxisQuery queryEdges(const HullView& a, const HullView& b, double stop_above) {
  Scratch& s = scratch();
  const int ea = a.edgeCount(), eb = b.edgeCount(), fa = a.faceCount(), fb = b.faceCount();
  s.arcs_a.resize(ea);
  s.arcs_b.resize(eb);
  for (int i = 0; i < ea; ++i) s.arcs_a[i] = arcOf(a, i, 1.0);
  for (int j = 0; j < eb; ++j) s.arcs_b[j] = arcOf(b, j, -1.0);
  // B's Gauss map enters reversed: its normals negated, as arcOf(b, j, -1.0) has them.
  s.plane_a_dot_b.resize(static_cast<std::size_t>(ea) * fb);   // [i][g]: (-n_b[g]) . (n1 x n0)_a[i]
  s.plane_b_dot_a.resize(static_cast<std::size_t>(eb) * fa);   // [j][f]: n_a[f] . (n1 x n0)_b[j]
  for (int g = 0; g < fb; ++g) {
    const Eigen::Vector3d n = -1.0 * b.normals[g];
    for (int i = 0; i < ea; ++i) s.plane_a_dot_b[static_cast<std::size_t>(i) * fb + g] = n.dot(s.arcs_a[i].n1xn0);
  }
  for (int j = 0; j < eb; ++j)
    for (int f = 0; f < fa; ++f)
      s.plane_b_dot_a[static_cast<std::size_t>(j) * fa + f] = a.normals[f].dot(s.arcs_b[j].n1xn0);
  const std::array<int, 2>* faces_a = a.hull->edge_faces.data();
  const std::array<int, 2>* faces_b = b.hull->edge_faces.data();
  AxisQuery best;
  Eigen::Vector3d axis;
  double sep = 0;
  for (int i = 0; i < ea; ++i) {
    const double* plane_a = &s.plane_a_dot_b[static_cast<std::size_t>(i) * fb];
    const int f0 = faces_a[i][0], f1 = faces_a[i][1];
    for (int j = 0; j < eb; ++j) {
      // arcsCross with A's arc ab = edge i, B's arc cd = edge j
      const double cba = plane_a[faces_b[j][0]], dba = plane_a[faces_b[j][1]];
      const double* plane_b = &s.plane_b_dot_a[static_cast<std::size_t>(j) * fa];
      const double adc = plane_b[f0], bdc = plane_b[f1];
      if (!(cba * dba < 0 && adc * bdc < 0 && cba * bdc > 0)) continue;
      if (!minkowskiEdgeAxis(a, i, b, j, axis, sep) || sep <= best.separation) continue;
      best = {sep, i, j};
      if (sep > stop_above) return best;
    }
  }
  return best;
}

}  // namespace tumble::narrow
