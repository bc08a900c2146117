// Pairs with a rounded piece (an exact sphere: a point swept by a ball; a capsule: a segment swept
// by a ball; convex_piece.h). The surface of a rounded piece lies at its radius from its core, so
// two pieces are apart by the distance between their cores less the radii, along the direction
// between the cores' closest points (GJK, distance.cpp): exact to rounding, with no facets for a
// ball to hop over. The SAT of narrow_phase.cpp stays for polyhedron pairs.
//
// A capsule lying flat on a face (or beside a parallel capsule) touches along a segment, not at a
// point: its contact is that segment's two ends, so the support it stands on has a width and it
// does not rock about one point. Cores that overlap (a penetration deeper than the radii, far
// beyond the contact tolerance) are separated along the axis of least core overlap instead.
#include <algorithm>
#include <cmath>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

namespace {

// Two directions closer than this (the sine of their angle) are parallel: a capsule lying on a
// face or beside another capsule. 1e-6 rad tilts one end of a 1 m capsule by a micrometre, the
// contact tolerance: below it the two ends are equally deep to within what the pipeline resolves.
constexpr double kFlatSine = 1e-6;
// Cores closer than this share of the pair's size touch: their direction is not defined, and
// the pair is treated as overlapping cores.
constexpr double kCoreContact = 1e-12;

double radiusOf(const HullView& h) { return h.hull->piece->radius_m; }
bool isSegment(const HullView& h) { return h.hull->piece->rounded() && h.vertexCount() == 2; }

Eigen::Vector3d closestOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& s0, const Eigen::Vector3d& s1) {
  const Eigen::Vector3d d = s1 - s0;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - s0).dot(d) / len2, 0.0, 1.0) : 0.0;
  return s0 + t * d;
}

// The face of polyhedron `h` whose outward normal is `n` to within kFlatSine, or -1.
int faceAlong(const HullView& h, const Eigen::Vector3d& n) {
  if (h.hull->piece->rounded()) return -1;
  for (int f = 0; f < h.faceCount(); ++f)
    if (h.normals[f].dot(n) > 0 && h.normals[f].cross(n).norm() < kFlatSine) return f;
  return -1;
}

// The part [t0, t1] of the segment s0 + t (s1 - s0) inside the prism of face `f` of `h` (the
// face's side planes, Cyrus-Beck); false when none of it is.
bool clipToFace(const HullView& h, int f, const Eigen::Vector3d& s0, const Eigen::Vector3d& s1, double& t0,
                double& t1) {
  const std::vector<int>& face = h.hull->piece->faces[static_cast<std::size_t>(f)];
  const Eigen::Vector3d n = h.normals[f], d = s1 - s0;
  t0 = 0, t1 = 1;
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Eigen::Vector3d v = h.vertices[face[k]];
    const Eigen::Vector3d inward = n.cross(h.vertices[face[(k + 1) % face.size()]] - v);   // CCW face
    const double at0 = inward.dot(s0 - v), rate = inward.dot(d);
    if (rate == 0) {
      if (at0 < 0) return false;
      continue;
    }
    const double t = -at0 / rate;
    if (rate > 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  return t0 <= t1;
}

// A contact point of the rounded core point `s` (of A when a_side, else of B), whose partner on the
// other core is `q`, along the manifold's normal n (A to B).
ContactPoint pointBetween(const Eigen::Vector3d& s, const Eigen::Vector3d& q, const Eigen::Vector3d& n, double r_a,
                          double r_b, bool a_side, std::uint32_t id) {
  const double core_gap = a_side ? n.dot(q - s) : n.dot(s - q);
  const Eigen::Vector3d on_a = a_side ? Eigen::Vector3d(s + r_a * n) : Eigen::Vector3d(q + r_a * n);
  const Eigen::Vector3d on_b = a_side ? Eigen::Vector3d(q - r_b * n) : Eigen::Vector3d(s - r_b * n);
  return {0.5 * (on_a + on_b), r_a + r_b - core_gap, id};
}

// A segment core lying flat along n against a face or a parallel segment of the other piece: the
// two ends of the part of it that faces the other, each with its own depth. Empty when the
// configuration is not flat.
void flatContacts(const HullView& seg, const HullView& other, bool seg_is_a, const Eigen::Vector3d& n,
                  double margin, ContactManifold& out) {
  const Eigen::Vector3d s0 = seg.vertices[0], s1 = seg.vertices[1];
  const Eigen::Vector3d axis = (s1 - s0).normalized();
  if (std::abs(axis.dot(n)) > kFlatSine) return;   // tilted: one end is nearer, one point
  const double r_a = seg_is_a ? radiusOf(seg) : radiusOf(other);
  const double r_b = seg_is_a ? radiusOf(other) : radiusOf(seg);
  const Eigen::Vector3d toward = seg_is_a ? n : Eigen::Vector3d(-n);   // from the segment to the other
  double t0 = 0, t1 = 1;
  std::vector<ContactPoint> points;
  if (isSegment(other)) {
    const Eigen::Vector3d o0 = other.vertices[0], o1 = other.vertices[1];
    const Eigen::Vector3d od = o1 - o0;
    if (od.normalized().cross(axis).norm() > kFlatSine) return;   // crossing capsules: one point
    // the part of the segment between the planes through the other's ends
    const double a0 = od.dot(s0 - o0), rate = od.dot(s1 - s0), len2 = od.squaredNorm();
    if (rate == 0) return;
    double u0 = (0 - a0) / rate, u1 = (len2 - a0) / rate;
    if (u0 > u1) std::swap(u0, u1);
    t0 = std::max(0.0, u0), t1 = std::min(1.0, u1);
    if (t0 >= t1) return;
    for (const double t : {t0, t1}) {
      const Eigen::Vector3d s = s0 + t * (s1 - s0);
      points.push_back(pointBetween(s, closestOnSegment(s, o0, o1), n, r_a, r_b, seg_is_a,
                                    mixFeature(7u, t == t0 ? 0u : 1u)));
    }
  } else {
    const int f = faceAlong(other, -toward);
    if (f < 0 || !clipToFace(other, f, s0, s1, t0, t1)) return;
    const Eigen::Vector3d fn = other.normals[f];
    const double offset = other.offsets[f];
    for (const double t : {t0, t1}) {
      const Eigen::Vector3d s = s0 + t * (s1 - s0);
      const Eigen::Vector3d q = s - (fn.dot(s) - offset) * fn;   // foot on the face's plane
      points.push_back(pointBetween(s, q, n, r_a, r_b, seg_is_a, mixFeature(8u, t == t0 ? 0u : 1u)));
    }
  }
  if (t1 - t0 <= 1e-9) points.resize(1);   // the segment only grazes the face: one point
  points.erase(std::remove_if(points.begin(), points.end(), [&](const ContactPoint& p) { return p.depth < -margin; }),
               points.end());
  if (!points.empty()) out.points = std::move(points);
}

struct CoreOverlap {
  double depth = 0;                       // m: how far the cores overlap along `normal`
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // A to B
};

double lowestAlong(const HullView& h, const Eigen::Vector3d& n) {
  double lo = INFINITY;
  for (int v = 0; v < h.vertexCount(); ++v) lo = std::min(lo, n.dot(h.vertices[v]));
  return lo;
}
double highestAlong(const HullView& h, const Eigen::Vector3d& n) { return -lowestAlong(h, -n); }

// Overlapping cores: the axis of least overlap among the polyhedra's face normals and the cross
// products of the cores' edges (the SAT's axes; a segment's one edge among them). Two points, or a
// point in a segment, have no such axis: they part along the line between their centres.
CoreOverlap coreOverlap(const HullView& a, const HullView& b) {
  CoreOverlap best;
  double best_sep = -INFINITY;
  auto consider = [&](Eigen::Vector3d n) {
    if (!(n.squaredNorm() > 0)) return;
    n.normalize();
    if (n.dot(b.centroid - a.centroid) < 0) n = -n;
    const double sep = lowestAlong(b, n) - highestAlong(a, n);
    if (sep > best_sep) best_sep = sep, best.normal = n;
  };
  if (!a.hull->piece->rounded())
    for (int f = 0; f < a.faceCount(); ++f) consider(a.normals[f]);
  if (!b.hull->piece->rounded())
    for (int f = 0; f < b.faceCount(); ++f) consider(-b.normals[f]);
  const auto& ea = a.hull->piece->edges;
  const auto& eb = b.hull->piece->edges;
  for (const auto& [a0, a1] : ea)
    for (const auto& [b0, b1] : eb) {
      const Eigen::Vector3d da = a.vertices[a1] - a.vertices[a0], db = b.vertices[b1] - b.vertices[b0];
      const Eigen::Vector3d c = da.cross(db);
      if (c.norm() > kFlatSine * da.norm() * db.norm()) consider(c);
    }
  if (best_sep == -INFINITY) {   // points and parallel segments: along the line between the centres
    Eigen::Vector3d d = b.centroid - a.centroid;
    if (isSegment(a)) d -= d.dot((a.vertices[1] - a.vertices[0]).normalized()) * (a.vertices[1] - a.vertices[0]).normalized();
    consider(d.squaredNorm() > 0 ? d : Eigen::Vector3d(Eigen::Vector3d::UnitZ()));
  }
  best.depth = std::max(0.0, -best_sep);
  return best;
}

struct CoreGap {
  double gap = 0;                        // m: the cores' distance, minus their overlap when they overlap
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // A to B
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero(), point_b = Eigen::Vector3d::Zero();   // on the cores
  bool apart = false;                    // the cores are apart and the normal is between their closest points
};

CoreGap coreGap(const HullView& a, const HullView& b) {
  CoreGap g;
  const PieceDistance d = distance(a, b);
  const double size = std::min(a.hull->size, b.hull->size);
  if (d.distance > kCoreContact * size) {
    g.apart = true;
    g.gap = d.distance;
    g.normal = (d.point_b - d.point_a) / d.distance;
    g.point_a = d.point_a;
    g.point_b = d.point_b;
    return g;
  }
  const CoreOverlap o = coreOverlap(a, b);
  g.gap = -o.depth;
  g.normal = o.normal;
  // the deepest core points along the axis: a rounded core's extreme vertex, a polyhedron's nearest
  g.point_a = a.vertices[0], g.point_b = b.vertices[0];
  for (int v = 1; v < a.vertexCount(); ++v)
    if (o.normal.dot(a.vertices[v]) > o.normal.dot(g.point_a)) g.point_a = a.vertices[v];
  for (int v = 1; v < b.vertexCount(); ++v)
    if (o.normal.dot(b.vertices[v]) < o.normal.dot(g.point_b)) g.point_b = b.vertices[v];
  return g;
}

}  // namespace

bool roundedContact(const HullView& a, const HullView& b, double margin, ContactManifold& out) {
  const double r_a = radiusOf(a), r_b = radiusOf(b);
  const CoreGap g = coreGap(a, b);
  const double gap = g.gap - r_a - r_b;
  if (gap > margin) return false;
  const Eigen::Vector3d n = g.normal;
  out.normal = n;
  // One point between the surfaces, on the line of the cores' closest points.
  const Eigen::Vector3d on_a = g.point_a + r_a * n, on_b = g.point_b - r_b * n;
  out.points.assign(1, {0.5 * (on_a + on_b), -gap, mixFeature(6u, 0u)});
  if (g.apart) {
    if (isSegment(a)) flatContacts(a, b, true, n, margin, out);
    else if (isSegment(b)) flatContacts(b, a, false, n, margin, out);
  }
  // The normal turns as the pieces move unless a face of either holds it (a ball on a box's top).
  out.closest_points = g.apart && faceAlong(a, n) < 0 && faceAlong(b, -n) < 0;
  return true;
}

double roundedSeparation(const HullView& a, const HullView& b, Eigen::Vector3d& axis) {
  const CoreGap g = coreGap(a, b);
  axis = g.normal;
  return g.gap - radiusOf(a) - radiusOf(b);
}

PieceDistance roundedDistance(const HullView& a, const HullView& b) {
  const CoreGap g = coreGap(a, b);
  PieceDistance d;
  d.distance = std::max(0.0, g.gap - radiusOf(a) - radiusOf(b));
  d.point_a = g.point_a + radiusOf(a) * g.normal;
  d.point_b = g.point_b - radiusOf(b) * g.normal;
  return d;
}

}  // namespace tumble::narrow
