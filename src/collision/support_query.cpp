// GJK and EPA on the Minkowski difference D = A - B of two convex sets given by support mappings
// (support_query.h; Gilbert, Johnson and Keerthi 1988; van den Bergen 2001; Ericson 2005), then a
// Newton polish of the normal where D is curved. The sets overlap when D holds the origin; apart,
// their distance is the distance from the origin to D, and overlapping, the penetration depth is
// the distance from the origin to D's boundary. Both are the least h(u) = max over D of u.x over
// unit directions u (minus the distance, or the depth), and any u gives a bound: h(u) >= the depth,
// -h(u) <= the distance.
//
// GJK keeps a simplex of up to four points of D and moves it towards the origin: each iteration
// adds the support point of D along -v (v the simplex's point nearest the origin) and keeps the
// smallest face of the simplex that holds the new nearest point; |v| bounds the distance from
// above. Smooth sets converge only asymptotically, so GJK runs on to the rounding floor.
//
// EPA starts from GJK's final simplex, blown up to a tetrahedron around the origin where GJK
// stopped with fewer points (the origin on a vertex, an edge or a face of it: touching sets, or
// sets that GJK found overlapping before enclosing the origin), and then, like a 3D quickhull,
// adds the support point along the normal of the polytope's face nearest the origin until that
// face lies on D's boundary within the tolerance. The polytope lies inside D, so its nearest face
// is a lower bound on the depth and the support along it an upper one. Where D has no volume (a
// flat disc against a coplanar one, a point or a segment against anything lying in it) no
// tetrahedron exists: the sets then only touch, and the direction in which D is thinnest parts
// them.
//
// Both polytopes approximate a curved D by chords and facets: they get the distance and depth to
// the tolerance but the normal and points only to its square root (1e-6), and EPA certifies a
// deep overlap of smooth sets only by refining its whole polytope, which its iteration cap cuts
// short. The polish (below) then takes the normal to rounding by Newton's method.
#include "collision/support_query.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace tumble {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Iteration caps, so that no input loops forever. GJK ends exactly on polytopes within a few dozen
// iterations and reaches the rounding floor on smooth pairs in about twenty; EPA adds one vertex
// per iteration, so its polytope keeps at most 4 + 128 vertices and 2 V - 4 faces.
constexpr int kGjkIterations = 128;
constexpr int kEpaIterations = 128;
// GJK's rounding floor: a gap |v|^2 - v.w below this share of |v|^2 is rounding in v.w.
constexpr double kRelativeGap = 1e-14;
// EPA: a point in front of a face's plane by less than this share of its coordinates is in it.
constexpr double kCoplanar = 1e-13;
// EPA: faces whose normals' cosine exceeds this lie on the same side of D (within 1.4e-3 rad).
constexpr double kSameSide = 1 - 1e-6;
// The turn (rad) off the line of centres of the GJK run that seeds EPA (supportQuery).
constexpr double kStartTurn = 1e-2;
// Tries at blowing GJK's simplex up to a tetrahedron (each adds a point or drops a degenerate one).
constexpr int kGrowSteps = 8;

// A point of D and the points of A and B that make it: w = a - b.
struct Vertex {
  Eigen::Vector3d w = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
};

// The size of the numbers a point of D was computed from: its rounding is relative to this.
double magnitude(const Vertex& v) { return v.a.norm() + v.b.norm(); }

// The support mapping of D = A - B: the point of D farthest along d.
class Difference {
 public:
  Difference(const SupportMapping& a, const SupportMapping& b) : a_(a), b_(b) {}
  Vertex operator()(const Eigen::Vector3d& d) const {
    const Eigen::Vector3d pa = a_(d), pb = b_(-d);
    return {pa - pb, pa, pb};
  }

 private:
  const SupportMapping& a_;
  const SupportMapping& b_;
};

// A unit direction u and the support of D along it: D lies in the half-space u.x <= h. Whatever u,
// h is an upper bound on the depth (moving B by h u parts the sets) and -h a lower bound on the
// distance; the least h over all u is the depth, or minus the distance.
struct Probe {
  Eigen::Vector3d u = Eigen::Vector3d::UnitZ();
  Vertex s;
  double h = kInf;
};

Probe probe(const Difference& support, const Eigen::Vector3d& u) {
  Probe p{u, support(u), 0.0};
  p.h = u.dot(p.s.w);
  return p;
}

// Two unit directions perpendicular to the unit `dir` and to each other (the first also to the
// axis least along dir).
std::pair<Eigen::Vector3d, Eigen::Vector3d> perpendiculars(const Eigen::Vector3d& dir) {
  Eigen::Index least = 0;
  dir.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e1 = dir.cross(Eigen::Vector3d::Unit(least)).normalized();
  return {e1, dir.cross(e1)};
}

// Up to four points of D with the barycentric weights of the simplex's point nearest the origin.
struct Simplex {
  std::array<Vertex, 4> p;
  std::array<double, 4> weight{};
  int size = 0;

  Eigen::Vector3d closest() const {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (int i = 0; i < size; ++i) v += weight[i] * p[i].w;
    return v;
  }
  // The points of A and B that the nearest point's weights make.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> witnesses() const {
    Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
    for (int i = 0; i < size; ++i) a += weight[i] * p[i].a, b += weight[i] * p[i].b;
    return {a, b};
  }
  bool holds(const Eigen::Vector3d& w) const {
    for (int i = 0; i < size; ++i)
      if (p[i].w == w) return true;
    return false;
  }
  // Keeps the listed points (index, weight), in that order.
  void keep(std::initializer_list<std::pair<int, double>> kept) {
    const std::array<Vertex, 4> old = p;
    size = 0;
    for (const auto& [i, wgt] : kept) {
      p[size] = old[i];
      weight[size++] = wgt;
    }
  }
};

// x / y clamped to [0, 1], 0 when y is 0: the parameter along an edge that may have no length.
double fraction(double x, double y) { return y > 0 ? std::clamp(x / y, 0.0, 1.0) : 0.0; }

void solveSegment(Simplex& s) {
  const Eigen::Vector3d a = s.p[0].w, ab = s.p[1].w - a;
  const double t = fraction(-a.dot(ab), ab.squaredNorm());
  if (t <= 0) return s.keep({{0, 1.0}});
  if (t >= 1) return s.keep({{1, 1.0}});
  s.keep({{0, 1 - t}, {1, t}});
}

// Ericson 5.1.5 with the query point at the origin: the Voronoi region of the triangle abc (a
// vertex, an edge or the face) that holds the origin, tested in that order. Each edge's
// denominator is its squared length, so `fraction` keeps a degenerate triangle finite.
void solveTriangle(Simplex& s) {
  const Eigen::Vector3d a = s.p[0].w, b = s.p[1].w, c = s.p[2].w;
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0 && d2 <= 0) return s.keep({{0, 1.0}});
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0 && d4 <= d3) return s.keep({{1, 1.0}});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = fraction(d1, d1 - d3);
    return s.keep({{0, 1 - t}, {1, t}});
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0 && d5 <= d6) return s.keep({{2, 1.0}});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = fraction(d2, d2 - d6);
    return s.keep({{0, 1 - t}, {2, t}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double t = fraction(d4 - d3, (d4 - d3) + (d5 - d6));
    return s.keep({{1, 1 - t}, {2, t}});
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) {   // collinear within rounding: the nearest of its edges
    Simplex best;
    double best_d2 = kInf;
    for (const auto& [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
      Simplex e;
      e.p[0] = s.p[i], e.p[1] = s.p[j], e.size = 2;
      solveSegment(e);
      const double d2e = e.closest().squaredNorm();
      if (d2e < best_d2) best_d2 = d2e, best = e;
    }
    s = best;
    return;
  }
  const double v = vb / denom, w = vc / denom;
  s.keep({{0, 1 - v - w}, {1, v}, {2, w}});
}

// Ericson 5.1.6: the nearest point of the faces that see the origin, or the whole tetrahedron when
// none does. Every face is wound so that its normal's product with the edge to the opposite vertex
// is the signed volume; taking that sign once for all faces keeps a sliver tetrahedron from
// claiming the origin through four independently rounded signs. A flat one (volume 0) has no
// inside: all its faces are tried.
void solveTetrahedron(Simplex& s) {
  static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  const double volume = (s.p[1].w - s.p[0].w).cross(s.p[2].w - s.p[0].w).dot(s.p[3].w - s.p[0].w);
  std::array<double, 4> origin_side{};   // per opposite vertex: the origin's side of its face, x volume
  Simplex best;
  double best_d2 = kInf;
  for (const auto& f : kFaces) {
    const Eigen::Vector3d a = s.p[f[0]].w;
    const Eigen::Vector3d n = (s.p[f[1]].w - a).cross(s.p[f[2]].w - a);
    origin_side[f[3]] = -n.dot(a);
    if (volume != 0 && origin_side[f[3]] * volume >= 0) continue;   // the origin is on the inner side
    Simplex t;
    t.p = {s.p[f[0]], s.p[f[1]], s.p[f[2]], s.p[f[3]]};
    t.size = 3;
    solveTriangle(t);
    const double d2 = t.closest().squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = t;
  }
  if (best.size > 0) {
    s = best;
    return;
  }
  for (int i = 0; i < 4; ++i) s.weight[i] = origin_side[i] / volume;   // the origin's barycentric coordinates
}

void solve(Simplex& s) {
  switch (s.size) {
    case 2: solveSegment(s); break;
    case 3: solveTriangle(s); break;
    case 4: solveTetrahedron(s); break;
    default: break;
  }
}

struct GjkEnd {
  Simplex simplex;                            // with the weights of v
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // the simplex's point nearest the origin
  bool encloses = false;                      // a tetrahedron around the origin: they overlap
  // The support along -v with the best lower bound on the distance, -h = v.w / |v|. Its direction
  // is better than the final v's: near the end GJK's |v| still falls while v's direction, known
  // only to the square root of that fall, wanders.
  Probe best;

  // Apart for sure: a plane parts D from the origin. Otherwise EPA decides, also for sets GJK
  // left within the tolerance of each other, or stalled on: touching sets whose difference is
  // flat where they touch stall GJK at |v| ~ 1e-11 x their size, rounding in v's direction.
  bool apart(double tolerance) const { return !encloses && v.norm() > tolerance && best.h < 0; }
};

// GJK from the interior point `start` of D. It stops when the gap |v|^2 - v.w falls to the
// rounding floor (or to tolerance^2, the distance then exact to tolerance^2 / |v|), when v comes
// within the tolerance of the origin, or when rounding leaves no progress.
GjkEnd gjk(const Difference& support, const Eigen::Vector3d& start, double tolerance) {
  GjkEnd end;
  Simplex& s = end.simplex;
  s.p[0] = support(-start);
  s.weight[0] = 1;
  s.size = 1;
  end.v = s.p[0].w;
  const double tol2 = tolerance * tolerance;
  for (int iter = 1; iter < kGjkIterations; ++iter) {
    const double v2 = end.v.squaredNorm();
    if (v2 <= tol2) break;
    const Vertex w = support(-end.v);
    const Eigen::Vector3d u = -end.v / std::sqrt(v2);
    if (u.dot(w.w) < end.best.h) end.best = {u, w, u.dot(w.w)};
    if (v2 - end.v.dot(w.w) <= std::max(tol2, kRelativeGap * v2)) break;
    if (s.holds(w.w)) break;   // a polytope's vertex again: v is exact
    Simplex next = s;
    next.p[next.size++] = w;
    solve(next);
    if (next.size == 4) {
      s = next;
      end.v.setZero();
      end.encloses = true;
      break;
    }
    const Eigen::Vector3d v_next = next.closest();
    if (!(v_next.squaredNorm() < v2)) break;
    s = next;
    end.v = v_next;
  }
  return end;
}

// Blows GJK's simplex (whose hull the origin is within the tolerance of) up to a tetrahedron of
// volume: each step adds the support point farthest from the simplex's affine hull along the
// directions that leave it, or drops a point of a simplex that is degenerate within the
// tolerance. The tetrahedron holds the simplex, so the origin stays within the tolerance of it.
// False when D is flat, a segment or a point within the tolerance: the origin then lies within
// the tolerance of it, and the probe with the least h (`thinnest`) parts the sets.
class Grower {
 public:
  Grower(const Difference& support, const Eigen::Vector3d& a_to_b, double tolerance)
      : support_(support), a_to_b_(a_to_b), tolerance_(tolerance) {}

  bool grow(std::vector<Vertex>& pts) {
    for (int step = 0; step < kGrowSteps; ++step) {
      switch (pts.size()) {
        case 1:
          if (!addOffPoint(pts, {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()})) return false;
          break;
        case 2:
          if (!growSegment(pts)) return false;
          break;
        case 3:
          if (!growTriangle(pts)) return false;
          break;
        default:
          if (solid(pts)) return true;
          break;
      }
    }
    return false;
  }
  const Probe& thinnest() const { return thinnest_; }

 private:
  // The support along u (unit), noting the thinnest direction.
  Vertex probeAlong(const Eigen::Vector3d& u) {
    const Probe p = probe(support_, u);
    if (p.h < thinnest_.h) thinnest_ = p;
    return p.s;
  }
  // Probes +-each direction (the one facing from A to B first, so that it wins a tie: touching
  // flat sets part along the direction between their centres) and adds the point farthest from
  // pts' affine hull (distance by `away`), unless none is farther than the tolerance.
  template <class Away>
  bool addFarthest(std::vector<Vertex>& pts, std::initializer_list<Eigen::Vector3d> dirs, Away away) {
    Vertex best;
    double best_away = -1;
    for (Eigen::Vector3d u : dirs) {
      u.normalize();
      if (u.dot(a_to_b_) < 0) u = -u;
      for (const Eigen::Vector3d& d : {u, Eigen::Vector3d(-u)}) {
        const Vertex w = probeAlong(d);
        const double x = away(w.w);
        if (x > best_away) best_away = x, best = w;
      }
    }
    if (!(best_away > tolerance_)) return false;
    pts.push_back(best);
    return true;
  }
  bool addOffPoint(std::vector<Vertex>& pts, std::initializer_list<Eigen::Vector3d> dirs) {
    const Eigen::Vector3d p0 = pts[0].w;
    return addFarthest(pts, dirs, [&](const Eigen::Vector3d& w) { return (w - p0).norm(); });
  }
  bool growSegment(std::vector<Vertex>& pts) {
    const Eigen::Vector3d p0 = pts[0].w, e = pts[1].w - p0;
    if (!(e.norm() > tolerance_)) {
      pts.pop_back();
      return true;
    }
    const Eigen::Vector3d dir = e.normalized();
    const auto [e1, e2] = perpendiculars(dir);
    return addFarthest(pts, {e1, e2}, [&](const Eigen::Vector3d& w) { return (w - p0).cross(dir).norm(); });
  }
  // A triangle thinner than the tolerance gives way to its longest edge.
  bool growTriangle(std::vector<Vertex>& pts) {
    static constexpr int kEdges[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    const Eigen::Vector3d p0 = pts[0].w, n = (pts[1].w - p0).cross(pts[2].w - p0);
    int longest = 0;
    double longest_len = 0;
    for (int k = 0; k < 3; ++k) {
      const double len = (pts[kEdges[k][1]].w - pts[kEdges[k][0]].w).norm();
      if (len > longest_len) longest_len = len, longest = k;
    }
    if (!(n.norm() > tolerance_ * longest_len)) {   // its height over the longest edge
      pts = {pts[kEdges[longest][0]], pts[kEdges[longest][1]]};
      return true;
    }
    const Eigen::Vector3d un = n.normalized();
    return addFarthest(pts, {un}, [&](const Eigen::Vector3d& w) { return std::abs(un.dot(w - p0)); });
  }
  // A tetrahedron thinner than the tolerance over its largest face gives way to its face nearest
  // the origin, to be grown along that face's normal.
  bool solid(std::vector<Vertex>& pts) {
    static constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    const double volume = (pts[1].w - pts[0].w).cross(pts[2].w - pts[0].w).dot(pts[3].w - pts[0].w);
    double largest = 0, nearest = kInf;
    int nearest_face = 0;
    for (int f = 0; f < 4; ++f) {
      const Eigen::Vector3d a = pts[kFaces[f][0]].w;
      largest = std::max(largest, (pts[kFaces[f][1]].w - a).cross(pts[kFaces[f][2]].w - a).norm());
      Simplex t;
      for (int k = 0; k < 3; ++k) t.p[k] = pts[kFaces[f][k]];
      t.size = 3;
      solveTriangle(t);
      const double d2 = t.closest().squaredNorm();
      if (d2 < nearest) nearest = d2, nearest_face = f;
    }
    if (std::abs(volume) > tolerance_ * largest) return true;
    pts = {pts[kFaces[nearest_face][0]], pts[kFaces[nearest_face][1]], pts[kFaces[nearest_face][2]]};
    return false;
  }

  const Difference& support_;
  Eigen::Vector3d a_to_b_;
  double tolerance_;
  Probe thinnest_;
};

// EPA's polytope: a closed triangulated surface inside D with the origin inside it (within the
// tolerance). Faces know their three neighbours, so that the faces a new point sees are found by
// walking from the one it was searched for (van den Bergen's silhouette), and dead faces' slots
// are reused, so the storage stays at the live count, at most 2 V - 4.
class Polytope {
 public:
  struct Face {
    std::array<int, 3> v{};    // vertex indices, counter-clockwise seen from outside
    std::array<int, 3> adj{};  // adj[k]: the face across the edge v[k] -> v[k + 1]
    Eigen::Vector3d n = Eigen::Vector3d::Zero();  // outward, unit; zero for a face with no area
    double d = kInf;           // n . (its points): the plane's signed distance from the origin
    bool alive = true;
    int seen = -1;             // the expansion whose search visited it last
    bool visible = false;      // and whether the new point was in front of it
  };

  // A tetrahedron of volume; its faces are wound outwards whatever its orientation.
  explicit Polytope(std::vector<Vertex> tetrahedron) : vertices_(std::move(tetrahedron)) {
    vertices_.reserve(4 + kEpaIterations);
    faces_.reserve(2 * (4 + kEpaIterations));
    const auto& p = vertices_;
    if ((p[1].w - p[0].w).cross(p[2].w - p[0].w).dot(p[3].w - p[0].w) > 0) std::swap(vertices_[1], vertices_[2]);
    // With the volume negative, face 012 faces away from vertex 3: all four are then outward.
    for (const auto& f : {std::array{0, 1, 2}, std::array{0, 3, 1}, std::array{0, 2, 3}, std::array{1, 3, 2}})
      addFace(f[0], f[1], f[2]);
    for (int f = 0; f < 4; ++f)
      for (int k = 0; k < 3; ++k) faces_[f].adj[k] = faceAcross(faces_[f].v[(k + 1) % 3], faces_[f].v[k]);
  }

  const Face& face(int f) const { return faces_[f]; }

  // The live face whose plane is nearest the origin (the first of equals), -1 if none has a plane.
  int nearestFace() const {
    int best = -1;
    for (int f = 0; f < int(faces_.size()); ++f)
      if (faces_[f].alive && faces_[f].d < (best < 0 ? kInf : faces_[best].d)) best = f;
    return best;
  }

  // In `t`, the nearest point to the origin of the triangles on the side of D that face `f` (whose
  // plane is nearest) lies on, by its weights. On a flat side of D the polytope splits the side
  // into triangles, and the origin's projection may fall in any of them (or just outside all, on
  // a curved rim's chords). Triangles facing another way (the far side of a symmetric pair, at the
  // same distance) are not on it. A triangle is no nearer than its plane, which bounds the search.
  void nearestOnSide(int f, Simplex& t) const {
    double best = solveFace(f, t);
    for (int g = 0; g < int(faces_.size()); ++g) {
      if (!faces_[g].alive || g == f || !(faces_[g].d < best) || faces_[g].n.dot(faces_[f].n) < kSameSide) continue;
      Simplex other;
      const double d = solveFace(g, other);
      if (d < best) best = d, t = other;
    }
  }

  bool holds(const Eigen::Vector3d& w) const {
    return std::any_of(vertices_.begin(), vertices_.end(), [&](const Vertex& v) { return v.w == w; });
  }

  // Adds w, in front of face `from`: removes the faces w sees (those reached from `from` across
  // edges, so the region is connected) and joins w to the rim they leave. False, with the polytope
  // unchanged, when rounding made that rim anything but one loop through distinct vertices.
  bool expand(int from, const Vertex& w) {
    if (!findSilhouette(from, w.w, kCoplanar * magnitude(w)) || !rimIsLoop()) return false;
    for (const int f : removed_) {
      faces_[f].alive = false;
      dead_.push_back(f);
    }
    const int iw = int(vertices_.size());
    vertices_.push_back(w);
    created_.clear();
    for (const RimEdge& e : rim_) {
      const int f = addFace(e.from, e.to, iw);
      created_.push_back(f);
      faces_[f].adj[0] = e.outside;
      Face& out = faces_[e.outside];
      for (int k = 0; k < 3; ++k)
        if (out.v[k] == e.to && out.v[(k + 1) % 3] == e.from) out.adj[k] = f;
    }
    // New face i = (from_i, to_i, w) meets across its edge to_i -> w the new face j with from_j = to_i.
    for (std::size_t i = 0; i < rim_.size(); ++i)
      for (std::size_t j = 0; j < rim_.size(); ++j)
        if (rim_[j].from == rim_[i].to) {
          faces_[created_[i]].adj[1] = created_[j];
          faces_[created_[j]].adj[2] = created_[i];
        }
    return true;
  }

 private:
  struct RimEdge {
    int from, to;  // wound as in the removed face
    int outside;   // the kept face across it
  };

  int addFace(int a, int b, int c) {
    int f = int(faces_.size());
    if (dead_.empty()) faces_.emplace_back();
    else f = dead_.back(), dead_.pop_back();
    Face& face = faces_[f];
    face = Face{};
    face.v = {a, b, c};
    const Eigen::Vector3d pa = vertices_[a].w;
    const Eigen::Vector3d n = (vertices_[b].w - pa).cross(vertices_[c].w - pa);
    const double len = n.norm();
    if (len > 0 && std::isfinite(len)) {   // a face with no area keeps no plane: never nearest, never seen
      face.n = n / len;
      face.d = face.n.dot(pa);
    }
    return f;
  }

  double solveFace(int f, Simplex& t) const {
    for (int k = 0; k < 3; ++k) t.p[k] = vertices_[faces_[f].v[k]];
    t.size = 3;
    solveTriangle(t);
    return t.closest().norm();
  }

  int faceAcross(int from, int to) const {   // the live face with the edge from -> to
    for (int f = 0; f < int(faces_.size()); ++f)
      for (int k = 0; k < 3; ++k)
        if (faces_[f].alive && faces_[f].v[k] == from && faces_[f].v[(k + 1) % 3] == to) return f;
    return -1;
  }

  // A face sees the new point when it lies in front of its plane by more than rounding, `margin`:
  // a face that rounding alone puts in front (w in its plane: D's flat sides, a box's faces) is
  // kept, and the new faces beside it continue its plane. Removed, it could leave a neighbour in
  // the same plane whose new face would fold back over it.
  bool findSilhouette(int from, const Eigen::Vector3d& w, double margin) {
    ++stamp_;
    removed_.clear();
    rim_.clear();
    stack_.assign(1, from);
    faces_[from].seen = stamp_;
    faces_[from].visible = true;
    while (!stack_.empty()) {
      const int f = stack_.back();
      stack_.pop_back();
      removed_.push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int g = faces_[f].adj[k];
        if (g < 0) return false;
        Face& other = faces_[g];
        if (other.seen != stamp_) {
          other.seen = stamp_;
          other.visible = other.n.dot(w) - other.d > margin;
          if (other.visible) stack_.push_back(g);
        }
        if (!other.visible) rim_.push_back({faces_[f].v[k], faces_[f].v[(k + 1) % 3], g});
      }
    }
    return true;
  }

  bool rimIsLoop() const {
    if (rim_.size() < 3) return false;
    for (std::size_t i = 0; i < rim_.size(); ++i) {
      int starts = 0, next = 0;
      for (const RimEdge& e : rim_) starts += e.from == rim_[i].from, next += e.from == rim_[i].to;
      if (starts != 1 || next != 1) return false;
    }
    return true;
  }

  std::vector<Vertex> vertices_;
  std::vector<Face> faces_;
  std::vector<int> dead_;                 // slots of removed faces, reused first
  std::vector<int> stack_, removed_, created_;
  std::vector<RimEdge> rim_;
  int stamp_ = 0;
};

// Sets that touch, or D without volume: the depth and normal of the thinnest direction probed
// (a depth of at most the tolerance), at the touching points GJK found.
SupportQuery touching(const GjkEnd& end, const Probe& thinnest) {
  SupportQuery q;
  q.overlapping = true;
  q.depth = std::isfinite(thinnest.h) ? std::max(thinnest.h, 0.0) : 0.0;
  q.normal = thinnest.u;
  std::tie(q.point_a, q.point_b) = end.simplex.witnesses();
  return q;
}

struct EpaEnd {
  SupportQuery answer;
  Probe least;             // the face normal along which D's support was least: where polishing starts
  bool solid = false;      // false when D has no volume and `answer` is a touching contact
  bool converged = false;  // the answer's face lies on D's boundary to within the tolerance
};

EpaEnd epa(const Difference& support, const GjkEnd& gjk_end, const Eigen::Vector3d& a_to_b, double tolerance) {
  EpaEnd end;
  std::vector<Vertex> pts(gjk_end.simplex.p.begin(), gjk_end.simplex.p.begin() + gjk_end.simplex.size);
  Grower grower(support, a_to_b, tolerance);
  if (!grower.grow(pts)) {
    end.answer = touching(gjk_end, grower.thinnest());
    return end;
  }
  Polytope poly(std::move(pts));
  int f = poly.nearestFace();
  for (int iter = 0; f >= 0 && iter < kEpaIterations; ++iter) {
    const Polytope::Face& face = poly.face(f);
    const Probe p = probe(support, face.n);
    if (p.h < end.least.h) end.least = p;
    // The support along the face's normal is an upper bound on the depth and the face a lower one.
    end.converged = p.h - face.d <= tolerance || poly.holds(p.s.w);
    if (end.converged || !poly.expand(f, p.s)) break;
    f = poly.nearestFace();
  }
  if (f < 0) {
    end.answer = touching(gjk_end, grower.thinnest());
    return end;
  }
  // The depth and normal are the nearest face's: certified, the support along its normal being
  // within the tolerance of its plane. The deepest points are the polytope's boundary point
  // nearest the origin, by its barycentric weights: on a flat side of D (a box's face, a cylinder's
  // cap) the origin's projection may fall outside the triangles found on it, and the nearest
  // triangle may then be a neighbour leaning off that side (measured: by up to 1e-8 m over the
  // tests' random pairs). The two points share the miss, so that point_a - point_b = depth normal.
  const Polytope::Face& face = poly.face(f);
  Simplex t;
  poly.nearestOnSide(f, t);
  end.answer.overlapping = true;
  end.answer.depth = std::max(face.d, 0.0);
  end.answer.normal = face.n;
  std::tie(end.answer.point_a, end.answer.point_b) = t.witnesses();
  const Eigen::Vector3d half_miss = 0.5 * (t.closest() - end.answer.depth * face.n);
  end.answer.point_a -= half_miss;
  end.answer.point_b += half_miss;
  end.solid = true;
  return end;
}

// Polishing. Both answers are the least h over unit directions u (the depth, or minus the
// distance). At that u the line of u meets D's support face along u (a point where D is smooth,
// a segment across an edge of D, a polygon on a flat side). GJK's and EPA's polytopes approximate
// a curved D by chords and facets, so where D curves they leave u wrong by about
// sqrt(2 x gap / curvature radius): 1e-7 for GJK at its rounding floor, 1e-6 for EPA at a 1e-12
// tolerance; and EPA may run out of iterations long before (a deep overlap of spheres needs its
// whole polytope refined, for its certificate). Newton's method on the miss across u takes u to
// rounding in a few steps, each kept only if h does not grow. How D's support moves as u turns a
// hair each way tells the cases apart: it moves by the radius of curvature per radian where D is
// smooth (Newton in both directions across u), jumps between the ends of the segment across an
// edge (the cylinder's side or a rim against a sphere: Newton across the edge, the segment then
// meeting the line), and jumps both ways on a flat side, where the polytope's answer is exact.
constexpr int kPolishSteps = 8;
constexpr int kStepHalvings = 4;
constexpr double kTurn = 1e-6;          // rad: the turn each way that shows how D's support moves
constexpr double kEdgeJump = 1e8;       // x tolerance: a support moving farther over 2 kTurn jumped an edge
constexpr double kParallelJumps = 1e-3; // sine: two jumps this near parallel cross one edge
constexpr double kLongestTurn = 0.5;    // rad: the largest Newton step
// What rounding may add to h = u.s between two steps: this share of the coordinates, or of the
// tolerance (the supports' own rounding, on coordinates the query cannot see: a sphere's centre
// and radius for a point near the origin). Nine steps may so raise h by 1e-2 tolerance at most.
constexpr double kRoundingOfH = 1e-15;
constexpr double kRoundingOfTolerance = 1e-3;

Vertex lerp(const Vertex& p, const Vertex& q, double t) {
  return {p.w + t * (q.w - p.w), p.a + t * (q.a - p.a), p.b + t * (q.b - p.b)};
}

// D's support a hair's turn of u each way along e.
struct Around {
  Vertex minus, plus;
};
Around around(const Difference& support, const Eigen::Vector3d& u, const Eigen::Vector3d& e) {
  return {support((u - kTurn * e).normalized()), support((u + kTurn * e).normalized())};
}

// On a flat side of D (jumps both ways) the polytope has u exact; the sides of A and B along it
// make D's. Where one of them is a point (its support moving by less than an edge's jump: a curved
// rim standing on a face), that point is exact, and the other set's point lies h u from it; the
// polytope's barycentric points are only as good as the chords around it. False where both are
// faces.
bool onFlatSide(const Probe& p, std::initializer_list<Vertex> around_u, double edge, Vertex& at) {
  double a_moves = 0, b_moves = 0;
  for (const Vertex& v : around_u) {
    a_moves = std::max(a_moves, (v.a - p.s.a).norm());
    b_moves = std::max(b_moves, (v.b - p.s.b).norm());
  }
  const Eigen::Vector3d hu = p.h * p.u;
  if (b_moves <= edge) at = {hu, p.s.b + hu, p.s.b};
  else if (a_moves <= edge) at = {hu, p.s.a, p.s.a - hu};
  else return false;
  return true;
}

// One Newton step where D is smooth at u: its miss g = s - h u across u vanishes at the answer,
// and d g / d turn = (the support's move per radian) - h. Sets `at` and returns true when the
// miss is within the tolerance.
bool smoothStep(const Probe& p, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, const Around& r1,
                const Around& r2, double tolerance, Eigen::Vector3d& turn, Vertex& at) {
  const Eigen::Vector2d g(e1.dot(p.s.w), e2.dot(p.s.w));
  if (g.norm() <= tolerance) {
    at = p.s;
    return true;
  }
  Eigen::Matrix2d jacobian;
  for (int i = 0; i < 2; ++i) {
    const Around& r = i == 0 ? r1 : r2;
    const Eigen::Vector3d move = (r.plus.w - r.minus.w) / (2 * kTurn);
    jacobian.col(i) = Eigen::Vector2d(e1.dot(move), e2.dot(move));
  }
  jacobian -= p.h * Eigen::Matrix2d::Identity();
  const Eigen::Vector2d t = -jacobian.inverse() * g;
  turn = t(0) * e1 + t(1) * e2;
  return false;
}

// One Newton step across an edge of D (the supports a turn each way along e1 are its segment's
// two ends): the answer's u is on the ridge of directions across the edge (both ends equally
// high: no `tilt`), where the segment meets u's line (no `miss` across it).
bool edgeStep(const Difference& support, const Probe& p, const Eigen::Vector3d& e1, const Around& r1,
              double tolerance, Eigen::Vector3d& turn, Vertex& at) {
  // The ends at u itself: the supports a turn each way drift with the turn where an end is curved
  // (a cone's rim); twice the turn's less the double turn's cancels that to second order, and
  // with it the frame's tilt off the ridge.
  const auto endAt = [&](const Vertex& once, double side) {
    const Vertex twice = support((p.u + 2 * side * kTurn * e1).normalized());
    return Vertex{2 * once.w - twice.w, 2 * once.a - twice.a, 2 * once.b - twice.b};
  };
  const Vertex end_minus = endAt(r1.minus, -1), end_plus = endAt(r1.plus, 1);
  const Eigen::Vector3d segment = end_plus.w - end_minus.w;
  const Eigen::Vector3d f1 = (segment - segment.dot(p.u) * p.u).normalized(), f2 = p.u.cross(f1);
  const double c_minus = f1.dot(end_minus.w), c_plus = f1.dot(end_plus.w);
  if (!(c_minus <= tolerance && c_plus >= -tolerance && c_plus > c_minus)) return false;
  const double t = std::clamp(-c_minus / (c_plus - c_minus), 0.0, 1.0);
  const Vertex meet = lerp(end_minus, end_plus, t);
  const double miss = f2.dot(meet.w), tilt = p.u.dot(segment);
  if (std::abs(miss) <= tolerance && std::abs(tilt) <= tolerance) {
    at = meet;
    return true;
  }
  // Each end moves across as u turns along f2 by its own radius of curvature (a cone's side
  // curves more near its apex): the meeting point by theirs interpolated.
  const auto endMove = [&](const Vertex& once, double side) {
    return f2.dot(support((p.u + side * kTurn * e1 + kTurn * f2).normalized()).w - once.w) / kTurn;
  };
  const double slope = (1 - t) * endMove(r1.minus, -1) + t * endMove(r1.plus, 1) - p.h;
  turn = -tilt / (c_plus - c_minus) * f1 - miss / slope * f2;
  return false;
}

// Moves `p` (in steps that do not raise h) to a direction where the line of u meets D's support
// face within the tolerance, and sets `at` to that meeting point; false when it cannot (on a
// flat side of D where both sets are flat, or where Newton's steps fail), p then holding no worse
// a direction.
bool polish(const Difference& support, Probe& p, Vertex& at, double tolerance) {
  const double edge = kEdgeJump * tolerance;
  Eigen::Vector3d e1 = perpendiculars(p.u).first;
  for (int step = 0; step <= kPolishSteps; ++step) {
    // The frame across u, carried along as u turns (a new one if e1 has come to lie along u).
    const Eigen::Vector3d carried = e1 - e1.dot(p.u) * p.u;
    e1 = carried.norm() > 1e-3 * e1.norm() ? carried.normalized() : perpendiculars(p.u).first;
    const Eigen::Vector3d e2 = p.u.cross(e1);
    const Around r1 = around(support, p.u, e1), r2 = around(support, p.u, e2);
    const Eigen::Vector3d jump1 = r1.plus.w - r1.minus.w, jump2 = r2.plus.w - r2.minus.w;
    Eigen::Vector3d turn = Eigen::Vector3d::Zero();
    if (jump1.norm() <= edge && jump2.norm() <= edge) {
      if (smoothStep(p, e1, e2, r1, r2, tolerance, turn, at)) return true;
    } else {
      const bool first = jump1.norm() >= jump2.norm();
      const Eigen::Vector3d big = first ? jump1 : jump2, small = first ? jump2 : jump1;
      if (small.norm() > edge && big.cross(small).norm() > kParallelJumps * big.norm() * small.norm())
        return onFlatSide(p, {r1.minus, r1.plus, r2.minus, r2.plus}, edge, at);   // jumps both ways
      if (std::abs(big.normalized().dot(e2)) > kParallelJumps) {
        e1 = big;   // turn the frame so that e1 crosses the edge
        continue;
      }
      if (edgeStep(support, p, e1, r1, tolerance, turn, at)) return true;
    }
    if (!turn.allFinite()) return false;
    if (turn.norm() > kLongestTurn) turn *= kLongestTurn / turn.norm();
    bool moved = false;
    for (int k = 0; k < kStepHalvings && !moved; ++k, turn /= 2) {
      const Probe next = probe(support, (p.u + turn).normalized());
      const double rounding = std::max(kRoundingOfH * std::max(magnitude(p.s), magnitude(next.s)),
                                       kRoundingOfTolerance * tolerance);
      moved = next.h <= p.h + rounding;
      if (moved) p = next;
    }
    if (!moved) return false;
  }
  return false;
}

// The answer along a probe's direction u at D's point `at` (at.w = at.a - at.b): at.w misses h u
// by a part split between the points so that point_a - point_b = h u. That part is within the
// tolerance after a polish; otherwise (EPA out of iterations) it is how far the points are off
// the sets, across u.
SupportQuery atProbe(const Probe& p, const Vertex& at, bool overlapping) {
  SupportQuery q;
  q.overlapping = overlapping;
  if (overlapping) q.depth = std::max(p.h, 0.0);
  else q.distance = -p.h;
  q.normal = p.u;
  const Eigen::Vector3d half_miss = 0.5 * (at.w - p.h * p.u);
  q.point_a = at.a - half_miss;
  q.point_b = at.b + half_miss;
  return q;
}

}  // namespace

SupportQuery supportQuery(const SupportMapping& a, const SupportMapping& b, const Eigen::Vector3d& centre_a,
                          const Eigen::Vector3d& centre_b, double tolerance) {
  const Difference support(a, b);
  Eigen::Vector3d start = centre_a - centre_b;   // a point of D, inside it
  if (!(start.squaredNorm() > 0)) start = Eigen::Vector3d::UnitX();
  const GjkEnd end = gjk(support, start, tolerance);
  if (!end.apart(tolerance)) {
    // EPA starts from a second GJK whose first direction is turned off the line of centres: from
    // that line itself, a pair symmetric about it (a sphere on a sphere, or over a cylinder's
    // axis) puts the deepest point among the simplex's vertices, and EPA's faces around a vertex
    // at the answer close in on it slowly (sphere pairs: over 128 iterations instead of 50).
    const GjkEnd turned = gjk(support, start + kStartTurn * start.norm() * perpendiculars(start.normalized()).first,
                              tolerance);
    const bool usable = turned.encloses || !(turned.v.norm() > tolerance);
    EpaEnd e = epa(support, usable ? turned : end, centre_b - centre_a, tolerance);
    if (!e.solid) return e.answer;
    // Polished, or if EPA ran out of iterations its best probe: a translation that parts the sets
    // for certain, and nearer the depth than the polytope's lower bound (10 to 100 times on
    // spheres).
    Probe best = e.least;
    Vertex at;
    if (polish(support, best, at, tolerance)) return atProbe(best, at, true);
    return e.converged ? e.answer : atProbe(best, best.s, true);
  }
  // Apart: polished, or else along GJK's best probe (whose plane is within the distance's
  // certified bounds, where the final v's direction may have wandered) at GJK's closest points.
  Probe p = end.best;
  Vertex at;
  if (polish(support, p, at, tolerance)) return atProbe(p, at, false);
  at.w = end.v;
  std::tie(at.a, at.b) = end.simplex.witnesses();
  return atProbe(p, at, false);
}

}  // namespace tumble
