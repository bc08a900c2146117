// The separating-axis test (Yang, "Rigid Bodies and Contacts", 2020: "axes are normals of faces or the cross product of two
// edges, one from each object"; Xiang, "Robot Control and Physical Simulation", 2020: O(e1 e2) axes). Edge pairs are pruned on the Gauss map:
// only pairs whose arcs cross form a face of the Minkowski difference A - B, and only those can
// give the separating plane (Gregorius, GDC 2013/2015).
#include <cassert>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

// Gap between the plane of `face` of ref and the deepest vertex of other along its normal.
double faceSeparation(const HullView& ref, int face, const HullView& other) {
  const Eigen::Vector3d n = ref.normals[face];
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

// The arcs are computed once per call; the O(E_a E_b) loop is then four dot products per pair,
// and only pairs that pass the Gauss-map test pay for an axis.
AxisQuery queryEdges(const HullView& a, const HullView& b, double stop_above) {
  Scratch& s = scratch();
  s.arcs_a.resize(a.edgeCount());
  s.arcs_b.resize(b.edgeCount());
  for (int i = 0; i < a.edgeCount(); ++i) s.arcs_a[i] = arcOf(a, i, 1.0);
  for (int j = 0; j < b.edgeCount(); ++j) s.arcs_b[j] = arcOf(b, j, -1.0);
  AxisQuery best;
  Eigen::Vector3d axis;
  double sep = 0;
  for (int i = 0; i < a.edgeCount(); ++i) {
    for (int j = 0; j < b.edgeCount(); ++j) {
      if (!arcsCross(s.arcs_a[i], s.arcs_b[j])) continue;
      if (!minkowskiEdgeAxis(a, i, b, j, axis, sep) || sep <= best.separation) continue;
      best = {sep, i, j};
      if (sep > stop_above) return best;
    }
  }
  return best;
}

}  // namespace tumble::narrow
