// Pairs with a solid of revolution (a cylinder, a cone; convex_piece.h), whatever the other piece:
// the separation, the penetration depth and the normal come from the two support mappings (GJK and
// EPA, support_query.h), exact to the query's tolerance with no facets.
//
// The contact points come from the two features facing each other along the normal: a face, a
// flat disc (eight rim points), a side line (a cylinder lying, a capsule, a cone's slant), an edge,
// or a point. The features are projected on the plane across the normal and the smaller clipped
// by the larger, as the SAT path clips faces (clip.cpp); each point's depth is the gap along the
// normal between the two features there, so a can standing on a box holds its whole base, one
// lying on its side holds its length, and a tilted one its rim's points within the margin, from
// the lowest (which touches first). The deepest point is then set to the query's depth, which
// back-stepping and the projection read.
#include <algorithm>
#include <cmath>

#include "collision/narrow_internal.h"
#include "collision/support_query.h"

namespace tumble::narrow {

namespace {

// Features within this angle (rad) of facing the normal are taken whole: a face, a disc, a side.
// Its points then carry their own depths along the normal, so a feature tilted within it only
// gives points deeper or shallower by their lever times the tilt, dropped beyond the margin.
constexpr double kFeatureAngle = 1e-3;

const ConvexPiece& pieceOf(const HullView& h) { return *h.hull->piece; }

Eigen::Vector3d supportOf(const HullView& h, const Eigen::Vector3d& d) {
  return pieceOf(h).supportAt(h.vertices, static_cast<std::size_t>(h.vertexCount()), d);
}

SupportQuery query(const HullView& a, const HullView& b) {
  const double size = std::min(a.hull->size, b.hull->size);
  return supportQuery([&](const Eigen::Vector3d& d) { return supportOf(a, d); },
                      [&](const Eigen::Vector3d& d) { return supportOf(b, d); }, a.centroid, b.centroid,
                      1e-12 * size);
}

// What of a piece faces along `dir` (unit): 1 point, 2 (a line), or a convex polygon in order.
using Feature = std::vector<Eigen::Vector3d>;

// The rim points of a disc, starting at `u` (unit, square to the axis): a tilted disc starts at
// its lowest rim point, so the point the pair touches first is one of them, exactly.
void discFeature(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, const Eigen::Vector3d& u, double r,
                 Feature& f) {
  const Eigen::Vector3d v = axis.cross(u);
  for (int k = 0; k < kDiscRimPoints; ++k) f.push_back(discRimPoint(centre, u, v, r, k));
}

Feature featureAlong(const HullView& h, const Eigen::Vector3d& dir) {
  const ConvexPiece& p = pieceOf(h);
  const double flat = std::sin(kFeatureAngle), facing = std::cos(kFeatureAngle);
  Feature f;
  if (p.revolved()) {
    const Eigen::Vector3d base = h.vertices[0], top = h.vertices[1];
    const Eigen::Vector3d axis = (top - base).normalized();
    const double along = axis.dot(dir);
    Eigen::Vector3d across = dir - along * axis;
    const bool cylinder = p.revolution == ConvexPiece::Revolution::Cylinder;
    const double r = p.disc_radius_m;
    if (along > facing && cylinder) discFeature(top, axis, axis.unitOrthogonal(), r, f);
    else if (along < -facing) discFeature(base, axis, axis.unitOrthogonal(), r, f);
    else if (cylinder && std::abs(along) < flat) {
      across.normalize();
      f = {base + r * across, top + r * across};
    } else if (cylinder) {
      // A tilted can touches at its rim's lowest point, but the rim beside it comes within the
      // margin as the can rocks: the whole rim goes in, and the points beyond the margin are
      // dropped by their depths, as the SAT path drops an incident face's far corners.
      discFeature(along > 0 ? top : base, axis, across.normalized(), r, f);
    } else {
      // a cone's slant faces dir when its rim point and its apex are equally far along it; its
      // base (tilted) faces dir when the rim's lowest point is farther along it than the apex
      const Eigen::Vector3d rim = base + r * across.normalized();
      const double lead = (rim - top).dot(dir);
      if (std::abs(lead) < flat * (rim - top).norm()) f = {rim, top};
      else if (lead > 0) discFeature(base, axis, across.normalized(), r, f);
    }
    if (f.empty()) f = {supportOf(h, dir)};
    return f;
  }
  if (p.rounded()) {
    if (h.vertexCount() == 2 && std::abs((h.vertices[1] - h.vertices[0]).normalized().dot(dir)) < flat)
      return {h.vertices[0] + p.radius_m * dir, h.vertices[1] + p.radius_m * dir};
    return {supportOf(h, dir)};
  }
  int best = -1;
  for (int k = 0; k < h.faceCount(); ++k)
    if (h.normals[k].dot(dir) > facing && (best < 0 || h.normals[k].dot(dir) > h.normals[best].dot(dir))) best = k;
  if (best >= 0) {
    for (int v : p.faces[static_cast<std::size_t>(best)]) f.push_back(h.vertices[v]);
    return f;
  }
  for (const auto& [i, j] : p.edges) {   // an edge square to dir, at the support
    const Eigen::Vector3d e = h.vertices[j] - h.vertices[i];
    if (std::abs(e.normalized().dot(dir)) < flat) {
      const double top = supportOf(h, dir).dot(dir);
      if (top - h.vertices[i].dot(dir) < flat * e.norm()) return {h.vertices[i], h.vertices[j]};
    }
  }
  return {supportOf(h, dir)};
}

// The plane across the normal: 2-d coordinates, and the height along the normal.
struct Frame {
  Eigen::Vector3d n, t1, t2;
  Eigen::Vector2d flat(const Eigen::Vector3d& p) const { return {t1.dot(p), t2.dot(p)}; }
};

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The height along n of the feature above the flat point q: a polygon's plane, a line's
// interpolation (clamped to its ends), a point's own height.
double heightAt(const Feature& f, const Frame& fr, const Eigen::Vector2d& q) {
  if (f.size() == 1) return fr.n.dot(f[0]);
  if (f.size() == 2) {
    const Eigen::Vector2d a = fr.flat(f[0]), d = fr.flat(f[1]) - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((q - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return fr.n.dot(f[0] + t * (f[1] - f[0]));
  }
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();   // Newell's normal: robust for any polygon
  for (std::size_t k = 0; k < f.size(); ++k) normal += f[k].cross(f[(k + 1) % f.size()]);
  const double nn = normal.dot(fr.n);
  if (std::abs(nn) < 1e-12 * normal.norm()) return fr.n.dot(f[0]);
  // the plane: normal . x = normal . f[0]; x = q1 t1 + q2 t2 + s n
  return (normal.dot(f[0]) - q.x() * normal.dot(fr.t1) - q.y() * normal.dot(fr.t2)) / nn;
}

// The part of `subject` (flat points) inside the convex polygon `clip` (counter-clockwise).
std::vector<Eigen::Vector2d> clipPolygon(std::vector<Eigen::Vector2d> subject, const std::vector<Eigen::Vector2d>& clip) {
  for (std::size_t k = 0; k < clip.size() && !subject.empty(); ++k) {
    const Eigen::Vector2d a = clip[k], e = clip[(k + 1) % clip.size()] - a;
    std::vector<Eigen::Vector2d> kept;
    const bool closed = subject.size() > 2;   // a line is clipped as a line, not as a loop
    for (std::size_t i = 0; i < subject.size(); ++i) {
      if (!closed && i + 1 == subject.size()) {
        if (cross2(e, subject[i] - a) >= 0) kept.push_back(subject[i]);
        break;
      }
      const Eigen::Vector2d p = subject[i], q = subject[(i + 1) % subject.size()];
      const double sp = cross2(e, p - a), sq = cross2(e, q - a);
      if (sp >= 0) kept.push_back(p);
      if ((sp < 0) != (sq < 0)) kept.push_back(p + sp / (sp - sq) * (q - p));
    }
    subject = std::move(kept);
  }
  return subject;
}

std::vector<Eigen::Vector2d> flatPolygon(const Feature& f, const Frame& fr) {
  std::vector<Eigen::Vector2d> out;
  for (const Eigen::Vector3d& p : f) out.push_back(fr.flat(p));
  if (out.size() > 2) {
    double area = 0;
    for (std::size_t k = 0; k < out.size(); ++k) area += cross2(out[k], out[(k + 1) % out.size()]);
    if (area < 0) std::reverse(out.begin(), out.end());
  }
  return out;
}

// Where the two features overlap across the normal.
std::vector<Eigen::Vector2d> overlap(const Feature& fa, const Feature& fb, const Frame& fr) {
  const std::vector<Eigen::Vector2d> a = flatPolygon(fa, fr), b = flatPolygon(fb, fr);
  if (a.size() > 2 && b.size() > 1) return clipPolygon(b, a);
  if (b.size() > 2 && a.size() > 1) return clipPolygon(a, b);
  if (a.size() == 2 && b.size() == 2) {   // two lines: their common stretch when parallel
    const Eigen::Vector2d d = a[1] - a[0];
    const double len2 = d.squaredNorm();
    if (len2 > 0 && std::abs(cross2(d.normalized(), (b[1] - b[0]).normalized())) < std::sin(kFeatureAngle)) {
      double t0 = (b[0] - a[0]).dot(d) / len2, t1 = (b[1] - a[0]).dot(d) / len2;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0), t1 = std::min(t1, 1.0);
      if (t0 <= t1) return {a[0] + t0 * d, a[0] + t1 * d};
    }
  }
  return {};
}

}  // namespace

bool supportContact(const HullView& a, const HullView& b, double margin, ContactManifold& out) {
  const SupportQuery q = query(a, b);
  const double depth = q.overlapping ? q.depth : -q.distance;
  if (-depth > margin) return false;
  Frame fr;
  fr.n = q.normal;
  fr.t1 = fr.n.unitOrthogonal();
  fr.t2 = fr.n.cross(fr.t1);
  const Feature fa = featureAlong(a, fr.n), fb = featureAlong(b, -fr.n);
  out.normal = fr.n;
  out.points.clear();
  std::uint32_t id = 0;
  for (const Eigen::Vector2d& p : overlap(fa, fb, fr)) {
    const double ha = heightAt(fa, fr, p), hb = heightAt(fb, fr, p);
    const Eigen::Vector3d at = p.x() * fr.t1 + p.y() * fr.t2 + 0.5 * (ha + hb) * fr.n;
    out.points.push_back({at, ha - hb, mixFeature(9u, id++)});
  }
  if (out.points.empty()) {   // one point: where the query found the pair closest (or deepest)
    out.points.push_back({0.5 * (q.point_a + q.point_b), depth, mixFeature(9u, 99u)});
  } else {
    // the deepest point is the query's depth: the features' own heights agree with it to their
    // tolerances, and back-stepping and the projection must see one depth for the pair
    double deepest = -INFINITY;
    for (const ContactPoint& cp : out.points) deepest = std::max(deepest, cp.depth);
    for (ContactPoint& cp : out.points) cp.depth += depth - deepest;
    out.points.erase(std::remove_if(out.points.begin(), out.points.end(),
                                    [&](const ContactPoint& cp) { return cp.depth < -margin; }),
                     out.points.end());
  }
  reduceManifold(out.points, out.normal);
  // The normal turns as they move unless a flat feature holds it (a face, a disc, a side line).
  out.closest_points = !q.overlapping && fa.size() == 1 && fb.size() == 1;
  return true;
}

double supportSeparation(const HullView& a, const HullView& b, Eigen::Vector3d& axis) {
  const SupportQuery q = query(a, b);
  axis = q.normal;
  return q.overlapping ? -q.depth : q.distance;
}

PieceDistance supportDistance(const HullView& a, const HullView& b) {
  const SupportQuery q = query(a, b);
  PieceDistance d;
  d.distance = q.overlapping ? 0.0 : q.distance;
  d.point_a = q.point_a;
  d.point_b = q.point_b;
  return d;
}

}  // namespace tumble::narrow
