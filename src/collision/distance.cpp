// The distance between two convex pieces and its closest points: the Gilbert-Johnson-Keerthi
// algorithm (E. G. Gilbert, D. W. Johnson and S. S. Keerthi, "A fast procedure for computing the
// distance between complex objects in three-dimensional space", IEEE Journal of Robotics and
// Automation, 1988) on the Minkowski difference A - B, with the closest point of each simplex
// found by Voronoi regions (C. Ericson, "Real-Time Collision Detection", 2005, 5.1.5 and 5.1.6).
// On polytopes it ends exactly: a support point already in the simplex means no progress is left.
#include <algorithm>
#include <array>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

namespace {

struct SimplexPoint {
  Eigen::Vector3d w, a, b;   // w = a - b: a point of A - B and the points of A and B that make it
};

struct Simplex {
  std::array<SimplexPoint, 4> p;
  std::array<double, 4> weight{};   // barycentric weights of the closest point
  int size = 0;
  Eigen::Vector3d closest() const {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (int i = 0; i < size; ++i) v += weight[i] * p[i].w;
    return v;
  }
  void keep(std::initializer_list<std::pair<int, double>> kept) {
    std::array<SimplexPoint, 4> q = p;
    int n = 0;
    for (const auto& [i, wgt] : kept) {
      q[n] = p[i];
      weight[n++] = wgt;
    }
    p = q;
    size = n;
  }
};

void closestOnSegment(Simplex& s) {
  const Eigen::Vector3d a = s.p[0].w, ab = s.p[1].w - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? -a.dot(ab) / len2 : 0.0;
  if (t <= 0) return s.keep({{0, 1.0}});
  if (t >= 1) return s.keep({{1, 1.0}});
  s.keep({{0, 1 - t}, {1, t}});
}

// Ericson 5.1.5, for the point at the origin.
void closestOnTriangle(Simplex& s) {
  const Eigen::Vector3d a = s.p[0].w, b = s.p[1].w, c = s.p[2].w;
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0 && d2 <= 0) return s.keep({{0, 1.0}});
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0 && d4 <= d3) return s.keep({{1, 1.0}});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return s.keep({{0, 1 - v}, {1, v}});
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0 && d5 <= d6) return s.keep({{2, 1.0}});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return s.keep({{0, 1 - w}, {2, w}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return s.keep({{1, 1 - w}, {2, w}});
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) {   // a degenerate triangle: its first edge
    s.size = 2;
    return closestOnSegment(s);
  }
  const double v = vb / denom, w = vc / denom;
  s.keep({{0, 1 - v - w}, {1, v}, {2, w}});
}

// Ericson 5.1.6: the closest point of the faces that see the origin; none sees it when the origin
// is inside (the pieces overlap), and the simplex keeps all four points.
void closestOnTetrahedron(Simplex& s) {
  static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  Simplex best;
  double best_d2 = INFINITY;
  bool seen = false;
  for (const auto& f : kFaces) {
    const Eigen::Vector3d a = s.p[f[0]].w;
    const Eigen::Vector3d n = (s.p[f[1]].w - a).cross(s.p[f[2]].w - a);
    const double origin_side = -n.dot(a), other_side = n.dot(s.p[f[3]].w - a);
    // A flat tetrahedron (other_side 0) has no inside: every face is tried.
    if (origin_side * other_side > 0) continue;
    seen = true;
    Simplex t;
    t.p = {s.p[f[0]], s.p[f[1]], s.p[f[2]], s.p[f[3]]};
    t.size = 3;
    closestOnTriangle(t);
    const double d2 = t.closest().squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = t;
  }
  if (seen) s = best;
  else s.weight = {0.25, 0.25, 0.25, 0.25};
}

}  // namespace

PieceDistance distance(const HullView& a, const HullView& b) {
  auto support = [&](const Eigen::Vector3d& d) {   // the point of A - B farthest along -d
    // Each vertex's height along d once (the same comparisons as recomputing the best's).
    int ia = 0, ib = 0;
    double lowest_a = a.vertices[0].dot(d), highest_b = b.vertices[0].dot(d);
    for (int i = 1; i < a.vertexCount(); ++i) {
      const double h = a.vertices[i].dot(d);
      if (h < lowest_a) ia = i, lowest_a = h;
    }
    for (int j = 1; j < b.vertexCount(); ++j) {
      const double h = b.vertices[j].dot(d);
      if (h > highest_b) ib = j, highest_b = h;
    }
    return SimplexPoint{a.vertices[ia] - b.vertices[ib], a.vertices[ia], b.vertices[ib]};
  };
  Eigen::Vector3d v = a.centroid - b.centroid;
  if (!(v.squaredNorm() > 0)) v = Eigen::Vector3d::UnitX();
  Simplex s;
  s.p[0] = support(v);
  s.weight[0] = 1;
  s.size = 1;
  v = s.p[0].w;
  // A polytope pair ends within a few dozen iterations; the cap only guards against rounding loops.
  for (int iter = 0; iter < 64; ++iter) {
    const double v2 = v.squaredNorm();
    if (!(v2 > 0)) break;
    const SimplexPoint w = support(v);
    // No point of A - B lies beyond v by more than rounding: v is the closest point.
    if (v2 - v.dot(w.w) <= 1e-12 * v2) break;
    bool known = false;
    for (int i = 0; i < s.size; ++i) known = known || s.p[i].w == w.w;
    if (known) break;
    Simplex next = s;
    next.p[next.size++] = w;
    switch (next.size) {
      case 2: closestOnSegment(next); break;
      case 3: closestOnTriangle(next); break;
      default: closestOnTetrahedron(next); break;
    }
    if (next.size == 4) {   // the origin is inside: they overlap
      s = next;
      break;
    }
    const Eigen::Vector3d v_next = next.closest();
    if (!(v_next.squaredNorm() < v2)) break;   // no progress: rounding
    s = next;
    v = v_next;
  }
  PieceDistance out;
  for (int i = 0; i < s.size; ++i) {
    out.point_a += s.weight[i] * s.p[i].a;
    out.point_b += s.weight[i] * s.p[i].b;
  }
  out.distance = s.size == 4 ? 0.0 : v.norm();
  return out;
}

}  // namespace tumble::narrow
