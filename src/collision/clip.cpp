// Contact points from the chosen feature pair: clipping for faces, closest points for edges.
#include <algorithm>
#include <cassert>
#include <utility>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

namespace {

// The vertex of `piece` deepest along -n (the first of equal ones: deterministic).
int deepestVertex(const HullView& piece, const Eigen::Vector3d& n) {
  int best = 0;
  double lowest = n.dot(piece.vertices[0]);   // each vertex's height once
  for (int v = 1; v < piece.vertexCount(); ++v) {
    const double h = n.dot(piece.vertices[v]);
    if (h < lowest) best = v, lowest = h;
  }
  return best;
}

// The face of `piece` that meets n's face: the most anti-parallel to n among the faces around the
// piece's deepest vertex along n. The deepest vertex must be on it: when n is the axis of least
// penetration that vertex lies inside the reference face's prism and is the manifold's deepest
// point, with depth equal to the SAT depth. The most anti-parallel face of the whole piece need not
// hold it (on a gem two faces on either side of a ridge can tie to 3 digits), and clipping the
// wrong one reported a piece 29 mm deep as 6 mm deep, or as apart.
int incidentFace(const HullView& piece, const Eigen::Vector3d& n, int deepest) {
  int best = -1;
  double lowest = INFINITY;
  const std::vector<std::vector<int>>& faces = piece.hull->piece->faces;
  for (int f = 0; f < piece.faceCount(); ++f) {
    if (std::find(faces[f].begin(), faces[f].end(), deepest) == faces[f].end()) continue;
    const double d = piece.normals[f].dot(n);
    if (best < 0 || d < lowest) lowest = d, best = f;  // best < 0: a face even when n is NaN
  }
  assert(best >= 0);  // a closed hull's every vertex is on a face
  return std::max(best, 0);
}

// One Sutherland-Hodgman pass: keeps the part of `in` with side . p <= offset + tol. A point
// within tol of the plane counts as on it, so a flush stack's corners are not split in two by
// rounding. Cuts are made only where the edge crosses strictly, so no duplicate points appear.
void clipAgainst(const std::vector<ClipVertex>& in, const Eigen::Vector3d& side, double offset,
                 double tol, std::uint32_t plane_id, std::vector<ClipVertex>& out) {
  out.clear();
  if (in.empty()) return;
  const ClipVertex* prev = &in.back();
  double d_prev = side.dot(prev->p) - offset;
  for (const ClipVertex& cur : in) {
    const double d_cur = side.dot(cur.p) - offset;
    const bool crosses = (d_prev < -tol && d_cur > tol) || (d_prev > tol && d_cur < -tol);
    if (crosses) {
      const double t = d_prev / (d_prev - d_cur);
      out.push_back({prev->p + t * (cur.p - prev->p),
                     mixFeature(mixFeature(plane_id, prev->id), cur.id)});
    }
    if (d_cur <= tol) out.push_back(cur);
    prev = &cur;
    d_prev = d_cur;
  }
}

// Clips the incident polygon against each side plane of the reference face (its edge x normal,
// outward for a counter-clockwise face) and leaves the result in s.poly.
void clipToReference(const HullView& ref, int ref_face, Scratch& s) {
  const std::vector<int>& face = ref.hull->piece->faces[ref_face];
  const Eigen::Vector3d n = ref.normals[ref_face];
  for (size_t k = 0; k < face.size() && !s.poly.empty(); ++k) {
    const Eigen::Vector3d v0 = ref.vertices[face[k]];
    const Eigen::Vector3d edge = ref.vertices[face[(k + 1) % face.size()]] - v0;
    const Eigen::Vector3d side = edge.cross(n);
    // 1e-9 of the piece's size: far below any physical feature, far above rounding (1e-16).
    const double tol = 1e-9 * ref.hull->size * edge.norm();
    clipAgainst(s.poly, side, side.dot(v0), tol, 0x5100u + std::uint32_t(k), s.poly_next);
    std::swap(s.poly, s.poly_next);
  }
}

}  // namespace

bool faceContact(const HullView& ref, int ref_face, const HullView& inc, bool ref_is_a,
                 double margin, ContactManifold& out) {
  Scratch& s = scratch();
  const Eigen::Vector3d n = ref.normals[ref_face];
  const int deepest = deepestVertex(inc, n);
  const int inc_face = incidentFace(inc, n, deepest);
  s.poly.clear();
  for (int v : inc.hull->piece->faces[inc_face]) s.poly.push_back({inc.vertices[v], std::uint32_t(v)});
  clipToReference(ref, ref_face, s);
  // Nothing left only when the reference face was kept by the feature choice's hysteresis although
  // the deepest vertex is outside its prism; the caller then checks the depth against the SAT.
  if (s.poly.empty()) s.poly.push_back({inc.vertices[deepest], 0x7e000000u + std::uint32_t(deepest)});

  out.normal = ref_is_a ? n : Eigen::Vector3d(-n);
  out.points.clear();
  const std::uint32_t base = mixFeature(mixFeature(ref_is_a ? 1u : 2u, std::uint32_t(ref_face)),
                                        std::uint32_t(inc_face));
  for (const ClipVertex& cv : s.poly) {
    const double dist = n.dot(cv.p) - ref.offsets[ref_face];  // incident point above the plane
    if (dist > margin) continue;
    out.points.push_back({cv.p - 0.5 * dist * n, -dist, mixFeature(base, cv.id)});
  }
  return !out.points.empty();
}

namespace {

// Parameters (s, t) in [0,1]^2 of the closest points of segments p + s d and q + t e (Ericson,
// Real-Time Collision Detection 5.1.9). Callers pass non-parallel edges, but a zero denominator
// is still guarded so that no NaN can leave this function.
void closestOnSegments(const Eigen::Vector3d& p, const Eigen::Vector3d& d, const Eigen::Vector3d& q,
                       const Eigen::Vector3d& e, double& s, double& t) {
  const Eigen::Vector3d r = p - q;
  const double a = d.dot(d), b = d.dot(e), c = d.dot(r), ee = e.dot(e), f = e.dot(r);
  const double denom = a * ee - b * b;
  s = denom > 0 ? std::clamp((b * f - c * ee) / denom, 0.0, 1.0) : 0.0;
  t = ee > 0 ? (b * s + f) / ee : 0.0;
  if (t < 0 || t > 1) {
    t = std::clamp(t, 0.0, 1.0);
    s = a > 0 ? std::clamp((b * t - c) / a, 0.0, 1.0) : 0.0;
  }
}

}  // namespace

bool edgeContact(const HullView& a, int ea, const HullView& b, int eb, double margin,
                 ContactManifold& out) {
  Eigen::Vector3d axis;
  double sep = 0;
  if (!edgeAxis(a, ea, b, eb, axis, sep) || sep > margin) return false;
  const auto& [a0, a1] = a.hull->piece->edges[ea];
  const auto& [b0, b1] = b.hull->piece->edges[eb];
  // Edges within kAbsTolerance of parallel touch along a line, not at a point: held at one point
  // (where skew lines cross, anywhere along it) the pair would turn about it.
  if (edgeOverlapContact(a, a0, a1, b, b0, b1, axis, out)) return true;
  const Eigen::Vector3d p = a.vertices[a0], d = a.vertices[a1] - p;
  const Eigen::Vector3d q = b.vertices[b0], e = b.vertices[b1] - q;
  double s = 0, t = 0;
  closestOnSegments(p, d, q, e, s, t);
  out.normal = axis;
  out.points.clear();
  out.points.push_back({0.5 * ((p + s * d) + (q + t * e)), -sep,
                        mixFeature(mixFeature(3u, std::uint32_t(ea)), std::uint32_t(eb))});
  return true;
}

namespace {

// The two vertices of `piece` highest along n, when they stand clear of the rest by more than
// `clear`: the piece's support feature along n is then the edge between them. -1 when it is not.
std::pair<int, int> supportEdge(const HullView& piece, const Eigen::Vector3d& n, double clear) {
  int first = -1, second = -1;
  double h_first = 0, h_second = 0;   // their heights, each vertex's taken once
  for (int v = 0; v < piece.vertexCount(); ++v) {
    const double h = n.dot(piece.vertices[v]);
    if (first < 0 || h > h_first) second = first, h_second = h_first, first = v, h_first = h;
    else if (second < 0 || h > h_second) second = v, h_second = h;
  }
  if (second < 0) return {-1, -1};
  const double low = h_second;
  for (int v = 0; v < piece.vertexCount(); ++v)
    if (v != first && v != second && n.dot(piece.vertices[v]) > low - clear) return {-1, -1};
  return {std::min(first, second), std::max(first, second)};
}

}  // namespace

bool edgeOverlapContact(const HullView& a, int a0, int a1, const HullView& b, int b0, int b1,
                        const Eigen::Vector3d& n, ContactManifold& out) {
  const Eigen::Vector3d p = a.vertices[a0], d = a.vertices[a1] - p;
  const Eigen::Vector3d q = b.vertices[b0], e = b.vertices[b1] - q;
  const Eigen::Vector3d along = d.normalized();
  const double de = along.dot(e);
  if (!(along.cross(e).norm() <= kAbsTolerance * e.norm())) return false;   // not parallel
  // The overlap of the two edges along their common direction: its ends are the contact's points.
  const double pa0 = along.dot(p), pa1 = pa0 + d.norm(), pb0 = along.dot(q), pb1 = pb0 + de;
  const double lo = std::max(pa0, std::min(pb0, pb1)), hi = std::min(pa1, std::max(pb0, pb1));
  if (!(hi >= lo)) return false;   // end to end: no overlap along the line
  out.points.clear();   // reused: the narrow phase allocates nothing once warm
  for (int end = 0; end < (hi > lo ? 2 : 1); ++end) {
    const double t = end == 0 ? lo : hi;
    const Eigen::Vector3d on_a = p + ((t - pa0) / d.norm()) * d, on_b = q + ((t - pb0) / de) * e;
    out.points.push_back({0.5 * (on_a + on_b), n.dot(on_a - on_b),
                      mixFeature(mixFeature(mixFeature(6u, std::uint32_t(a0)), std::uint32_t(b0)), std::uint32_t(end))});
  }
  out.normal = n;
  return true;
}

bool parallelEdgeContact(const HullView& a, const HullView& b, const Eigen::Vector3d& n, double clear,
                         ContactManifold& out) {
  const auto [a0, a1] = supportEdge(a, n, clear);
  const auto [b0, b1] = supportEdge(b, -n, clear);
  return a0 >= 0 && b0 >= 0 && edgeOverlapContact(a, a0, a1, b, b0, b1, n, out);
}

}  // namespace tumble::narrow
