// The narrow phase for one pair of convex pieces: working frame, cached axis, full SAT, feature
// choice, manifold, reduction, back to world.
#include "collision/narrow_phase.h"

#include <algorithm>
#include <cassert>

#include "collision/narrow_internal.h"

namespace tumble {

namespace narrow {

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

}  // namespace narrow

namespace {

using narrow::AxisQuery;
using narrow::HullView;
using Axis = SatCache::Axis;

// A and B in the working frame, and the pose that takes the working frame to world.
struct PairView {
  HullView a, b;
  const Eigen::Isometry3d* to_world = nullptr;
};

HullView nativeView(const CollisionHull& h) {
  return {&h, h.piece->vertices.data(), h.piece->face_normals.data(), h.face_offsets.data(),
          h.centroid};
}

// Moves hull h by `rel` into the scratch buffers: vertices, normals, and plane offsets
// (n' . x' = n . x + n' . t for x' = R x + t).
HullView transformedView(const CollisionHull& h, const Eigen::Isometry3d& rel, narrow::Scratch& s) {
  const ConvexPiece& piece = *h.piece;
  const Eigen::Matrix3d R = rel.linear();
  const Eigen::Vector3d t = rel.translation();
  s.vertices.resize(piece.vertices.size());
  for (size_t i = 0; i < piece.vertices.size(); ++i) s.vertices[i] = R * piece.vertices[i] + t;
  s.normals.resize(piece.face_normals.size());
  s.offsets.resize(piece.face_normals.size());
  for (size_t f = 0; f < piece.face_normals.size(); ++f) {
    s.normals[f] = R * piece.face_normals[f];
    s.offsets[f] = h.face_offsets[f] + s.normals[f].dot(t);
  }
  return {&h, s.vertices.data(), s.normals.data(), s.offsets.data(), R * h.centroid + t};
}

// Works in the frame of the piece with more vertices, so only the smaller one is transformed.
PairView makePairView(const CollisionHull& a, const Eigen::Isometry3d& pose_a,
                      const CollisionHull& b, const Eigen::Isometry3d& pose_b) {
  narrow::Scratch& s = narrow::scratch();
  if (a.piece->vertices.size() >= b.piece->vertices.size()) {
    const Eigen::Isometry3d rel = pose_a.inverse(Eigen::Isometry) * pose_b;
    return {nativeView(a), transformedView(b, rel, s), &pose_a};
  }
  const Eigen::Isometry3d rel = pose_b.inverse(Eigen::Isometry) * pose_a;
  return {transformedView(a, rel, s), nativeView(b), &pose_b};
}

bool isRounded(const PairView& p) { return p.a.hull->piece->rounded() || p.b.hull->piece->rounded(); }
bool isRevolved(const PairView& p) { return p.a.hull->piece->revolved() || p.b.hull->piece->revolved(); }

double cachedSeparation(const PairView& p, const SatCache& c) {
  Eigen::Vector3d axis;
  double s = -INFINITY;
  switch (c.axis) {
    case Axis::None: break;
    case Axis::FaceA: s = narrow::faceSeparation(p.a, c.index_a, p.b); break;
    case Axis::FaceB: s = narrow::faceSeparation(p.b, c.index_b, p.a); break;
    case Axis::Edges:
      if (!narrow::edgeAxis(p.a, c.index_a, p.b, c.index_b, axis, s)) s = -INFINITY;
      break;
  }
  return s;
}

// The cached face axis's separation for two boxes, from only what faceSeparation reads of them (the
// face's normal and plane, the other box's three axes and centre), taken exactly as through the
// pair's view (makePairView: A's frame, B moved into it), so the same bits, without moving B's
// eight corners and six planes first: over half of a pile's pairs stop here, on the axis that
// separated them the step before.
std::optional<double> cachedBoxFaceSeparation(const CollisionHull& a, const Eigen::Isometry3d& pose_a,
                                              const CollisionHull& b, const Eigen::Isometry3d& pose_b,
                                              const SatCache& c) {
  if (!a.box || !b.box || a.piece->vertices.size() < b.piece->vertices.size()) return std::nullopt;
  if (c.axis != Axis::FaceA && c.axis != Axis::FaceB) return std::nullopt;
  const Eigen::Isometry3d rel = pose_a.inverse(Eigen::Isometry) * pose_b;
  const Eigen::Matrix3d R = rel.linear();
  const Eigen::Vector3d t = rel.translation();
  double radius = 0;
  if (c.axis == Axis::FaceA) {
    const Eigen::Vector3d n = a.piece->face_normals[static_cast<std::size_t>(c.index_a)];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d axis = R * b.piece->face_normals[static_cast<std::size_t>(b.box->plus_face[k])];
      radius += b.box->half[k] * std::abs(n.dot(axis));
    }
    const Eigen::Vector3d centre = R * b.centroid + t;
    return n.dot(centre) - radius - a.face_offsets[static_cast<std::size_t>(c.index_a)];
  }
  const Eigen::Vector3d n = R * b.piece->face_normals[static_cast<std::size_t>(c.index_b)];
  const double offset = b.face_offsets[static_cast<std::size_t>(c.index_b)] + n.dot(t);
  for (int k = 0; k < 3; ++k)
    radius += a.box->half[k] * std::abs(n.dot(a.piece->face_normals[static_cast<std::size_t>(a.box->plus_face[k])]));
  return n.dot(a.centroid) - radius - offset;
}

// A face counts as the larger of two when its area is larger by more than this share.
constexpr double kLargerFace = 1e-6;

struct SatResult {
  AxisQuery face_a, face_b, edges;
  bool separated = false;
};

// Every axis, stopping at the first that separates by more than stop_above (which it caches).
SatResult fullSat(const PairView& p, double stop_above, SatCache& cache) {
  SatResult r;
  r.face_a = narrow::queryFaces(p.a, p.b, stop_above);
  if (r.face_a.separation > stop_above) {
    cache = {Axis::FaceA, r.face_a.index_a, -1, cache.last_use, cache.early_exits};
    return r.separated = true, r;
  }
  r.face_b = narrow::queryFaces(p.b, p.a, stop_above);
  if (r.face_b.separation > stop_above) {
    cache = {Axis::FaceB, -1, r.face_b.index_b, cache.last_use, cache.early_exits};
    return r.separated = true, r;
  }
  const std::optional<BoxShape>& box_a = p.a.hull->box;
  const std::optional<BoxShape>& box_b = p.b.hull->box;
  r.edges = box_a && box_b ? narrow::queryBoxEdges(p.a, *box_a, p.b, *box_b, stop_above)
                           : narrow::queryEdges(p.a, p.b, stop_above);
  if (r.edges.separation > stop_above) {
    cache = {Axis::Edges, r.edges.index_a, r.edges.index_b, cache.last_use, cache.early_exits};
    r.separated = true;
  }
  return r;
}

struct Choice {
  Axis axis;
  int index_a, index_b;
};

double faceArea(const HullView& h, int face) {
  const std::vector<int>& f = h.hull->piece->faces[static_cast<std::size_t>(face)];
  Eigen::Vector3d twice = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < f.size(); ++k)
    twice += h.vertices[f[k]].cross(h.vertices[f[(k + 1) % f.size()]]);
  return 0.5 * twice.norm();
}

// Two faces that separate the pair equally well (within `tol`, the feature choice's own). For
// opposite faces in contact (a face resting on a face, tilted by rounding) the contact is the smaller face's edges on the larger face's inside (when
// its footprint lies within the larger face, as a 1 m cube's top under a 10 m cube), so the normal
// is the larger face's. The smaller face's normal, tilted by the 1e-6 rad a light cube squeezed
// between the ground and a 1000 times heavier cube takes, turned the heavy cube's weight into a
// 10 N push that moved the light cube out sideways by 1.8 cm in 10 s (no friction held it).
// Equal faces keep the choice made (A's, or the cached one). Faces meeting at an angle (a tent's
// ridge) take the bisector afterwards (shareEdgeNormal), whichever face was chosen.
Choice preferLargerFace(const SatResult& r, const PairView& p, const Choice& c, double tol) {
  if (c.axis != Axis::FaceA && c.axis != Axis::FaceB) return c;
  if (r.face_a.index_a < 0 || r.face_b.index_b < 0) return c;
  if (std::abs(r.face_a.separation - r.face_b.separation) > tol) return c;
  const double area_a = faceArea(p.a, r.face_a.index_a), area_b = faceArea(p.b, r.face_b.index_b);
  if (area_b > area_a * (1 + kLargerFace)) return {Axis::FaceB, -1, r.face_b.index_b};
  if (area_a > area_b * (1 + kLargerFace)) return {Axis::FaceA, r.face_a.index_a, -1};
  return c;
}

// The feature that makes the manifold (tolerances and their reasons in narrow_internal.h).
// A cached face within the face tolerance of the winner keeps its role: near ties between two
// faces (a box rocking on its face) then do not swap the reference face every step.
Choice chooseFeature(const SatResult& r, const PairView& p, double cached_sep, SatCache& cache) {
  const double abs_tol = narrow::kAbsTolerance * std::min(p.a.hull->size, p.b.hull->size);
  const double best_face = std::max(r.face_a.separation, r.face_b.separation);
  if (r.edges.separation > best_face + narrow::kEdgeRelTolerance * std::abs(best_face) + abs_tol) {
    return {Axis::Edges, r.edges.index_a, r.edges.index_b};
  }
  const double sa = r.face_a.separation;
  Choice c{Axis::FaceA, r.face_a.index_a, -1};
  double chosen = sa;
  if (r.face_b.separation > sa + narrow::kFaceRelTolerance * std::abs(sa) + abs_tol) {
    c = {Axis::FaceB, -1, r.face_b.index_b};
    chosen = r.face_b.separation;
  }
  const bool cached_face = cache.axis == Axis::FaceA || cache.axis == Axis::FaceB;
  const double keep_tol = narrow::kFaceRelTolerance * std::abs(chosen) + abs_tol;
  if (cached_face && cached_sep >= chosen - keep_tol) c = {cache.axis, cache.index_a, cache.index_b};
  return preferLargerFace(r, p, c, keep_tol);
}

// The SAT's own answer: the axis of least penetration (largest separation), first of ties in the
// order face of A, face of B, edges.
Choice leastPenetration(const SatResult& r) {
  const double sa = r.face_a.separation, sb = r.face_b.separation, se = r.edges.separation;
  if (sa >= sb && sa >= se) return {Axis::FaceA, r.face_a.index_a, -1};
  if (sb >= se) return {Axis::FaceB, -1, r.face_b.index_b};
  return {Axis::Edges, r.edges.index_a, r.edges.index_b};
}

bool sameFeature(const Choice& x, const Choice& y) {
  return x.axis == y.axis && x.index_a == y.index_a && x.index_b == y.index_b;
}

// Built on the least-penetration axis, the manifold's deepest point is exactly as deep as the SAT
// says (clip.cpp, incidentFace). A feature kept by the tolerances of chooseFeature measures
// something else: the depth along its own normal of what is left inside its face's prism. For a
// face resting with a small tilt the two differ by about depth x tilt^2 / 2, far below this
// tolerance, so the face stays; for pieces crossing deeply they differed by millimetres in either
// direction (the prism can cut the deepest part away), and back-stepping and the projection then
// missed the overlap or pushed too far. Within `share` of the smaller piece's size: rounding-sized
// (kDepthAgreement, like the clipping tolerance), or kParallelSine for a face whose normal the
// least-penetration edge axis is (edgeAxisIsFaceNormal).
bool agreesWithSat(const ContactManifold& m, const SatResult& r, const PairView& p, double share) {
  if (m.points.empty()) return false;
  const double sat_depth = -std::max({r.face_a.separation, r.face_b.separation, r.edges.separation});
  double deepest = -INFINITY;
  for (const ContactPoint& cp : m.points) deepest = std::max(deepest, cp.depth);
  // Pairs apart within the margin are held to it too: the pipeline calls a contact touching when its
  // depth is above -1e-6 m, and a face saying "0.1 mm apart" of a pair the SAT sees touching would
  // drop its resting force. (Exempting pairs that both call apart raised the pile's
  // sampled penetration from 1.1 to 6.8 mm.)
  const double tol = share * std::min(p.a.hull->size, p.b.hull->size);
  return std::abs(deepest - sat_depth) <= tol;
}

// Two edges lying in parallel faces (the joints of a brick wall, the two halves of a cut block)
// have those faces' normal for their axis, and measure the faces' separation up to rounding: of the
// normalised cross product, and of the mesh itself (a file's vertices written to nine decimals
// leave its faces flat only to 1e-9 m, more than kDepthAgreement allows). The face's manifold,
// every point where the faces meet, is then the contact as long as it holds the deepest point to
// within what the axes' difference can make (kParallelSine times the size); the edge pair's one
// point would be a single corner of it, and a face held at one corner turns about it into its
// neighbour (half the cut bricks of scenes/hard/debris_wall.json had their halves held so).
// Parallel: within the sine below which two edges count as parallel.
bool edgeAxisIsFaceNormal(const PairView& p, const Choice& face, const Choice& edges) {
  if (edges.axis != Axis::Edges || (face.axis != Axis::FaceA && face.axis != Axis::FaceB)) return false;
  Eigen::Vector3d axis;
  double unused = 0;
  if (!narrow::edgeAxis(p.a, edges.index_a, p.b, edges.index_b, axis, unused)) return false;
  // Both point from A to B: A's outward face normal, B's turned around.
  const Eigen::Vector3d n = face.axis == Axis::FaceA ? p.a.normals[face.index_a] : Eigen::Vector3d(-p.b.normals[face.index_b]);
  return axis.dot(n) > 0 && axis.cross(n).norm() < narrow::kParallelSine;
}

// Faces turned a little against each other across the pair's contact (the two halves of a cut
// brick, set spinning at different rates by a blow): the separating axis is then an edge pair's or
// the direction between closest points, a few milliradians off both faces' normals, and its one
// point is a corner of where the faces meet; held there, the halves turned about it into each
// other (3.2 cm in the step after a steel ball struck a wall of cut bricks, time stepping). When
// a face of either piece is within kOppositeFaces of that axis, its clipped manifold (every point
// within the margin, each at its own gap along the face's normal) is the contact, as long as its
// deepest point is as deep as the axis says, to within what measuring along a direction up to
// 0.8 degrees off can change: for pieces apart, kParallelSine of the size (far below the contact
// tolerance); for pieces overlapping, 1 - kOppositeFaces (1e-4) of the depth, so that the drift
// correction pushes them apart by the overlap to 0.01 %. A wedge's edge across another's, whose
// faces stand tens of degrees off the axis, keeps its one point.
bool nearParallelFaceContact(const PairView& p, const Eigen::Vector3d& axis, double depth, double margin,
                             ContactManifold& out) {
  double best = narrow::kOppositeFaces;
  int face = -1;
  bool on_a = true;
  for (int f = 0; f < p.a.faceCount(); ++f)
    if (const double c = axis.dot(p.a.normals[f]); c > best) best = c, face = f, on_a = true;
  for (int f = 0; f < p.b.faceCount(); ++f)
    if (const double c = -axis.dot(p.b.normals[f]); c > best) best = c, face = f, on_a = false;
  if (face < 0) return false;
  thread_local ContactManifold faces;   // reused: a warm step allocates nothing
  const bool built = on_a ? narrow::faceContact(p.a, face, p.b, true, margin, faces)
                          : narrow::faceContact(p.b, face, p.a, false, margin, faces);
  if (!built || faces.points.size() < 2) return false;
  double deepest = -INFINITY;
  for (const ContactPoint& cp : faces.points) deepest = std::max(deepest, cp.depth);
  const double size = std::min(p.a.hull->size, p.b.hull->size);
  const double agree = depth > 0 ? narrow::kDepthAgreement * size + (1 - narrow::kOppositeFaces) * depth
                                 : narrow::kParallelSine * size;
  if (std::abs(deepest - depth) > agree) return false;
  out.normal = faces.normal;
  out.points.assign(faces.points.begin(), faces.points.end());
  out.closest_points = false;
  return true;
}

bool buildManifold(const PairView& p, const Choice& c, double margin, ContactManifold& out) {
  switch (c.axis) {
    case Axis::FaceA: return narrow::faceContact(p.a, c.index_a, p.b, true, margin, out);
    case Axis::FaceB: return narrow::faceContact(p.b, c.index_b, p.a, false, margin, out);
    case Axis::Edges: return narrow::edgeContact(p.a, c.index_a, p.b, c.index_b, margin, out);
    case Axis::None: break;
  }
  return false;
}

// The feature a pair's contact was built on is tried first next time.
void keepAxis(const Choice& c, SatCache& cache) {
  if (c.axis == cache.axis && c.index_a == cache.index_a && c.index_b == cache.index_b) {
    cache.last_use = SatCache::Use::Reused;
  }
  cache.axis = c.axis;
  cache.index_a = c.index_a;
  cache.index_b = c.index_b;
}

// How far apart the pieces certainly are along the direction between GJK's closest points: the
// gap between their supports along it, which no pair of points undercuts. GJK's own distance
// stops at rounding, which on large near-coplanar faces is far above the SAT's: a 0.3 m box lying
// on a 4 m ramp 1.01e-7 m apart came out 1.02e-7 m apart, 1.2e-9 m more than the face's gap, and
// was taken for a pair closest at a vertex: one point, about which the box turned two corners
// 1.25 mm into the ramp within a step. Along a face normal the gap is the face's separation.
double certifiedGap(const PieceDistance& d, const PairView& p) {
  if (!(d.distance > 0)) return 0;
  const Eigen::Vector3d n = (d.point_b - d.point_a) / d.distance;   // from A to B
  double high_a = -INFINITY, low_b = INFINITY;
  for (int v = 0; v < p.a.vertexCount(); ++v) high_a = std::max(high_a, n.dot(p.a.vertices[v]));
  for (int v = 0; v < p.b.vertexCount(); ++v) low_b = std::min(low_b, n.dot(p.b.vertices[v]));
  return low_b - high_a;
}

// Whether face f of `face` is what the other piece is closest to: the other's vertex deepest along
// the face's normal lies over the inside of the face, clear of its edges (by 1e-9 of the smaller
// piece). Then the distance is that vertex's height over the face, the face's SAT separation,
// exactly: the SAT's lower bound is met, and the distance query may be skipped.
bool faceGapIsDistance(const HullView& face, int f, const HullView& other, double clear) {
  const Eigen::Vector3d& n = face.normals[f];
  int deepest = 0;
  double low = INFINITY;
  for (int v = 0; v < other.vertexCount(); ++v)
    if (const double h = n.dot(other.vertices[v]); h < low) low = h, deepest = v;
  const Eigen::Vector3d& s = other.vertices[deepest];
  const std::vector<int>& loop = face.hull->piece->faces[static_cast<std::size_t>(f)];
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d& v0 = face.vertices[loop[i]];
    const Eigen::Vector3d edge = face.vertices[loop[(i + 1) % loop.size()]] - v0;
    // Counter-clockwise seen from outside: n x edge points into the face.
    const Eigen::Vector3d inward = n.cross(edge);
    if (!((s - v0).dot(inward) > clear * inward.norm())) return false;
  }
  return true;
}

// Separated pieces whose distance is more than the SAT's best axis shows meet first at a vertex or
// at the end of an edge: a vertex beside a face, past its edge (a tetrahedron falling past a box's
// top edge), vertex to vertex, edge to edge beyond an end. No tested axis is their separating
// direction, and a manifold built on the best one puts its point where nothing is near (the
// vertex deepest along a face normal, outside that face) with that axis's normal and gap: a
// speculative contact there stops a body that would have passed. Their contact is the one point
// they are closest at, along the direction between the two closest points, with the true distance.
// Unless the features closest along that direction are two parallel edges (a tent's two cards
// parted at the ridge): then a point at each end of their overlap, or the pair would meet at one
// end of a line contact and be turned about it. Their normal turns as they move all the same
// (edges passing beside each other, not towards), so they are closest points too.
void closestPointContact(const PieceDistance& d, const PairView& p, ContactManifold& out) {
  out.closest_points = true;
  const Eigen::Vector3d n = (d.point_b - d.point_a) / d.distance;
  const double abs_tol = narrow::kAbsTolerance * std::min(p.a.hull->size, p.b.hull->size);
  if (narrow::parallelEdgeContact(p.a, p.b, n, abs_tol, out)) return;
  out.normal = n;
  out.points.assign(1, {0.5 * (d.point_a + d.point_b), -d.distance, narrow::mixFeature(4u, 0u)});
}

// Two pieces touching along edges that are parallel (the ridge of a tent of two leaning cards,
// two wedges edge to edge) have no single contact normal: every direction between the two faces'
// normals separates them, the SAT finds both faces equally good, and its tie-break (A's face)
// pushed along one card's face normal, 25 degrees off the horizontal: the ridge force lifted one
// card and pressed the other down, and the tent fell. When the faces of both pieces separate them
// equally (within the feature-choice tolerances), touch (neither overlaps by more than the
// absolute tolerance) and are not opposite (not resting face on face),
// the contact's normal is the bisector of the two normals, the symmetric choice inside that range;
// the points keep their places, their depths shifted so that the deepest is the pair's depth
// along the bisector.
void shareEdgeNormal(const SatResult& r, const PairView& p, const Choice& c, ContactManifold& m) {
  if (c.axis == Axis::Edges || r.face_a.index_a < 0 || r.face_b.index_b < 0 || m.points.empty()) return;
  const double sa = r.face_a.separation, sb = r.face_b.separation;
  const double abs_tol = narrow::kAbsTolerance * std::min(p.a.hull->size, p.b.hull->size);
  if (std::max(std::abs(sa), std::abs(sb)) > abs_tol) return;   // not touching: a deep overlap
  if (std::abs(sa - sb) > narrow::kFaceRelTolerance * std::max(std::abs(sa), std::abs(sb)) + abs_tol) return;
  const Eigen::Vector3d na = p.a.normals[r.face_a.index_a], nb = -p.b.normals[r.face_b.index_b];
  // Opposite faces (resting face on face) keep the reference face's normal; faces more than a
  // right angle apart do not meet at a shared edge line.
  if (na.dot(nb) > narrow::kOppositeFaces || na.dot(nb) < 0) return;
  const Eigen::Vector3d n = (na + nb).normalized();
  // The touching features are two parallel edges (a card's ridge edge on the other's): the contact
  // is their overlap, a point at each end. Clipping one face against the other cannot give it
  // reliably: the incident edge lies on the reference face's boundary, where rounding keeps or
  // drops its ends and cuts it at arbitrary places (a tent's 64 mm ridge held at one end only).
  if (narrow::parallelEdgeContact(p.a, p.b, n, abs_tol, m)) return;
  double low_b = INFINITY, high_a = -INFINITY;
  for (int v = 0; v < p.b.vertexCount(); ++v) low_b = std::min(low_b, n.dot(p.b.vertices[v]));
  for (int v = 0; v < p.a.vertexCount(); ++v) high_a = std::max(high_a, n.dot(p.a.vertices[v]));
  double deepest = -INFINITY;
  for (const ContactPoint& cp : m.points) deepest = std::max(deepest, cp.depth);
  const double shift = (high_a - low_b) - deepest;
  for (ContactPoint& cp : m.points) cp.depth += shift;
  m.normal = n;
}

void toWorld(const Eigen::Isometry3d& pose, ContactManifold& m) {
  m.normal = (pose.linear() * m.normal).normalized();
  for (ContactPoint& cp : m.points) cp.position = pose * cp.position;
}

}  // namespace

bool collide(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
             const Eigen::Isometry3d& pose_b, double margin_m, SatCache& cache,
             ContactManifold& out) {
  out.points.clear();
  out.closest_points = false;
  if (const std::optional<double> sep = cachedBoxFaceSeparation(a, pose_a, b, pose_b, cache); sep && *sep > margin_m) {
    cache.last_use = SatCache::Use::EarlyExit;
    ++cache.early_exits;
    return false;
  }
  const PairView p = makePairView(a, pose_a, b, pose_b);
  if (isRevolved(p)) {   // a cylinder or a cone: its support mapping (support_contact.cpp)
    cache.last_use = SatCache::Use::Miss;
    if (!narrow::supportContact(p.a, p.b, margin_m, out)) return false;
    toWorld(*p.to_world, out);
    return true;
  }
  if (isRounded(p)) {   // a sphere or a capsule: no faces to test (rounded_contact.cpp)
    cache.last_use = SatCache::Use::Miss;
    if (!narrow::roundedContact(p.a, p.b, margin_m, out)) return false;
    toWorld(*p.to_world, out);
    return true;
  }
  // the seed's "defining face/edge": while it still separates, nothing else need be tested
  const double cached_sep = cachedSeparation(p, cache);
  if (cached_sep > margin_m) {
    cache.last_use = SatCache::Use::EarlyExit;
    ++cache.early_exits;
    return false;
  }
  const SatResult r = fullSat(p, margin_m, cache);
  cache.last_use = SatCache::Use::Miss;
  if (r.separated) return false;
  const double sat_sep = std::max({r.face_a.separation, r.face_b.separation, r.edges.separation});
  PieceDistance d;
  const double clear = narrow::kDepthAgreement * std::min(p.a.hull->size, p.b.hull->size);
  // A face axis whose gap is the distance (faceGapIsDistance) leaves nothing for the distance query
  // to find: no certified gap above the SAT's, and a distance within the margin. Of the pairs apart
  // within the margin in the 1000-box pile's time-stepping run, 48 % are such a face and a corner
  // or a face over it (2026-11-29).
  const bool face_is_closest =
      sat_sep > 0 && ((sat_sep == r.face_a.separation && faceGapIsDistance(p.a, r.face_a.index_a, p.b, clear)) ||
                      (sat_sep == r.face_b.separation && faceGapIsDistance(p.b, r.face_b.index_b, p.a, clear)));
  if (sat_sep > 0 && !face_is_closest) {
    // The SAT value is a lower bound on the distance; equal to it when the closest features are a
    // face and what faces it, or the insides of two edges. Above it, they are not (see
    // closestPointContact), which only a gap the supports certify may show (certifiedGap); and a
    // pair farther than the margin is no contact at all.
    d = narrow::distance(p.a, p.b);
    if (d.distance > margin_m) return false;
    if (certifiedGap(d, p) > sat_sep + clear) {
      const Eigen::Vector3d n = (d.point_b - d.point_a) / d.distance;
      if (nearParallelFaceContact(p, n, -d.distance, margin_m, out)) {
        narrow::reduceManifold(out.points, out.normal);
        toWorld(*p.to_world, out);
        return true;
      }
      closestPointContact(d, p, out);
      toWorld(*p.to_world, out);
      return true;
    }
  }
  Choice c = chooseFeature(r, p, cached_sep, cache);
  bool built = buildManifold(p, c, margin_m, out);
  const Choice exact = leastPenetration(r);
  const double agreement = edgeAxisIsFaceNormal(p, c, exact) ? narrow::kParallelSine : narrow::kDepthAgreement;
  if (!sameFeature(c, exact) && !(built && agreesWithSat(out, r, p, agreement))) {
    c = exact;
    built = buildManifold(p, c, margin_m, out);
  }
  keepAxis(c, cache);
  if (!built && sat_sep > 0) {
    if (face_is_closest) d = narrow::distance(p.a, p.b);
    // Pieces apart within the margin whose reference face and incident face meet only along a
    // line on the reference face's border (a box's top edge level with the bottom edge of a box
    // beside and above it): the clip keeps or drops that line by rounding, and dropped it, the
    // pair within the margin would be reported as nothing (two 0.4 m cubes of a pile 0.70 mm
    // apart, found afresh at one step and not at the next; a kept manifold took the "nothing" and
    // held it). The closest points stand for them, as for pieces whose faces do not face.
    closestPointContact(d, p, out);
    toWorld(*p.to_world, out);
    return true;
  }
  if (!built) return false;
  if (c.axis == Axis::Edges) {
    Eigen::Vector3d axis;
    double unused = 0;
    if (narrow::edgeAxis(p.a, c.index_a, p.b, c.index_b, axis, unused))
      nearParallelFaceContact(p, axis, -r.edges.separation, margin_m, out);
  }
  shareEdgeNormal(r, p, c, out);
  narrow::reduceManifold(out.points, out.normal);
  toWorld(*p.to_world, out);
  return true;
}

std::optional<ContactManifold> collide(const CollisionHull& a, const Eigen::Isometry3d& pose_a,
                                       const CollisionHull& b, const Eigen::Isometry3d& pose_b,
                                       double margin_m, SatCache& cache) {
  ContactManifold m;
  if (!collide(a, pose_a, b, pose_b, margin_m, cache, m)) return std::nullopt;
  return m;
}

std::optional<ContactManifold> collide(const ConvexPiece& a, const Eigen::Isometry3d& pose_a,
                                       const ConvexPiece& b, const Eigen::Isometry3d& pose_b,
                                       double margin_m, SatCache& cache) {
  return collide(makeCollisionHull(a), pose_a, makeCollisionHull(b), pose_b, margin_m, cache);
}

namespace {

// The SAT value over every axis of the pair as seen in its working frame, the best axis cached.
double fullSeparation(const PairView& p, SatCache& cache) {
  // every axis, even when the cached one separates: the largest value is the tightest lower bound
  // on the distance, which lets conservative advancement take the longest safe step
  const SatResult r = fullSat(p, INFINITY, cache);
  const double s = std::max({r.face_a.separation, r.face_b.separation, r.edges.separation});
  cache.index_a = cache.index_b = -1;
  if (s == r.face_a.separation) {
    cache.axis = Axis::FaceA, cache.index_a = r.face_a.index_a;
  } else if (s == r.face_b.separation) {
    cache.axis = Axis::FaceB, cache.index_b = r.face_b.index_b;
  } else {
    cache.axis = Axis::Edges, cache.index_a = r.edges.index_a, cache.index_b = r.edges.index_b;
  }
  return s;
}

}  // namespace

PieceDistance pieceDistance(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
                            const Eigen::Isometry3d& pose_b) {
  const PairView p = makePairView(a, pose_a, b, pose_b);
  PieceDistance d = isRevolved(p) ? narrow::supportDistance(p.a, p.b)
                    : isRounded(p) ? narrow::roundedDistance(p.a, p.b)
                                   : narrow::distance(p.a, p.b);
  d.point_a = *p.to_world * d.point_a;
  d.point_b = *p.to_world * d.point_b;
  return d;
}

double separation(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
                  const Eigen::Isometry3d& pose_b, SatCache& cache) {
  Eigen::Vector3d unused;
  return separation(a, pose_a, b, pose_b, cache, unused);
}

double separation(const CollisionHull& a, const Eigen::Isometry3d& pose_a, const CollisionHull& b,
                  const Eigen::Isometry3d& pose_b, SatCache& cache, Eigen::Vector3d& axis) {
  const PairView p = makePairView(a, pose_a, b, pose_b);   // one working frame for value and axis
  if (isRevolved(p) || isRounded(p)) {   // exact: from the support mappings, or the cores' distance less the radii
    const double s = isRevolved(p) ? narrow::supportSeparation(p.a, p.b, axis) : narrow::roundedSeparation(p.a, p.b, axis);
    axis = p.to_world->linear() * axis;
    return s;
  }
  const double s = fullSeparation(p, cache);
  double unused = 0;
  switch (cache.axis) {
    case Axis::FaceA: axis = p.a.normals[cache.index_a]; break;
    case Axis::FaceB: axis = -p.b.normals[cache.index_b]; break;
    case Axis::Edges:
      if (narrow::edgeAxis(p.a, cache.index_a, p.b, cache.index_b, axis, unused)) break;
      [[fallthrough]];
    default: axis = Eigen::Vector3d::Zero(); break;   // no valid axis: the caller cannot use one
  }
  axis = p.to_world->linear() * axis;
  return s;
}

}  // namespace tumble
