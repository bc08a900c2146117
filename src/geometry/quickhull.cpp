#include "geometry/quickhull.h"

#include <Eigen/Geometry>  // cross products
#include <cmath>
#include <utility>

namespace tumble {
namespace {

using Eigen::Vector3d;

struct Face {
  std::array<int, 3> v{};         // CCW seen from outside
  std::array<int, 3> adj{-1, -1, -1};  // adj[i]: face across edge v[i] -> v[i+1]
  Vector3d normal = Vector3d::Zero();
  std::vector<int> outside;       // points strictly above this face (by more than the tolerance)
  bool alive = true;
  int visible_round = -1;         // == the current round while the face is seen by the eye point
};

struct HorizonEdge {
  int a, b;      // the edge a -> b as walked by the visible face
  int neighbor;  // the face beyond it, not visible
};

class Quickhull {
 public:
  Quickhull(const std::vector<Vector3d>& points, double tol) : pts_(points), tol_(tol) {}

  std::optional<TriangleHull> run(std::string* why) {
    faces_.reserve(8 * pts_.size());  // a hull of n points made ~6n faces on the way, in tests
    if (!initialSimplex(why)) return std::nullopt;
    // Faces made while adding a point are appended, and the faces a point sees die, so one pass
    // in creation order visits every face that ever holds outside points.
    for (size_t f = 0; f < faces_.size(); ++f) {
      while (faces_[f].alive && !faces_[f].outside.empty()) addPoint(int(f));
    }
    return output();
  }

 private:
  // Signed distance from the face plane, measured from one of its vertices rather than through a
  // stored offset n.p0: for a cloud far from the origin, p - p0 is exact-ish, n.p - d is not.
  double distance(const Face& f, int p) const { return f.normal.dot(pts_[p] - pts_[f.v[0]]); }

  int addFace(int a, int b, int c) {
    Face f;
    f.v = {a, b, c};
    f.normal = (pts_[b] - pts_[a]).cross(pts_[c] - pts_[a]).normalized();
    faces_.push_back(std::move(f));
    return int(faces_.size()) - 1;
  }

  bool initialSimplex(std::string* why);
  void linkSimplex();
  void assign(const std::vector<int>& candidates, const std::vector<int>& new_faces);
  void addPoint(int f);
  void collectHorizon(int f, int from_edge, int eye, std::vector<int>& visible,
                      std::vector<HorizonEdge>& horizon);
  static bool isCycle(const std::vector<HorizonEdge>& horizon);
  std::vector<int> stitch(const std::vector<HorizonEdge>& horizon, int eye);
  TriangleHull output() const;

  const std::vector<Vector3d>& pts_;
  const double tol_;
  std::vector<Face> faces_;
  int round_ = 0;
};

int farthestFromLine(const std::vector<Vector3d>& pts, int a, int b, double* dist) {
  const Vector3d dir = (pts[b] - pts[a]).normalized();
  int best = -1;
  *dist = -1;
  for (size_t i = 0; i < pts.size(); ++i) {
    const double d = (pts[i] - pts[a]).cross(dir).norm();
    if (d > *dist) *dist = d, best = int(i);
  }
  return best;
}

int farthestFromPlane(const std::vector<Vector3d>& pts, int a, int b, int c, double* dist) {
  const Vector3d n = (pts[b] - pts[a]).cross(pts[c] - pts[a]).normalized();
  int best = -1;
  *dist = -1;
  for (size_t i = 0; i < pts.size(); ++i) {
    const double d = std::abs(n.dot(pts[i] - pts[a]));
    if (d > *dist) *dist = d, best = int(i);
  }
  return best;
}

// The simplex spans the cloud as widely as cheaply possible: the farthest pair among the six
// axis extremes, the point farthest from their line, the point farthest from that plane. Each
// failure to find the next one beyond the tolerance is exactly one kind of degeneracy.
bool Quickhull::initialSimplex(std::string* why) {
  if (pts_.size() < 4) return *why = "fewer than 4 points", false;
  std::array<int, 6> ext{0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < pts_.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (pts_[i][k] < pts_[ext[2 * k]][k]) ext[2 * k] = int(i);
      if (pts_[i][k] > pts_[ext[2 * k + 1]][k]) ext[2 * k + 1] = int(i);
    }
  }
  int a = ext[0], b = ext[1];
  for (int i : ext) {
    for (int j : ext) {
      if ((pts_[j] - pts_[i]).norm() > (pts_[b] - pts_[a]).norm()) a = i, b = j;
    }
  }
  if ((pts_[b] - pts_[a]).norm() <= tol_) return *why = "all points coincide", false;
  double dist = 0;
  const int c = farthestFromLine(pts_, a, b, &dist);
  if (dist <= tol_) return *why = "all points are collinear", false;
  const int d = farthestFromPlane(pts_, a, b, c, &dist);
  if (dist <= tol_) return *why = "all points are coplanar", false;
  // Orient each face so that the fourth vertex lies behind it.
  const std::array<std::array<int, 4>, 4> tris{{{a, b, c, d}, {a, b, d, c}, {a, c, d, b}, {b, c, d, a}}};
  for (const auto& t : tris) {
    const int f = addFace(t[0], t[1], t[2]);
    if (distance(faces_[f], t[3]) > 0) {
      std::swap(faces_[f].v[1], faces_[f].v[2]);
      faces_[f].normal = -faces_[f].normal;
    }
  }
  linkSimplex();
  std::vector<int> rest;
  for (size_t i = 0; i < pts_.size(); ++i) {
    if (int(i) != a && int(i) != b && int(i) != c && int(i) != d) rest.push_back(int(i));
  }
  assign(rest, {0, 1, 2, 3});
  return true;
}

// Each edge a -> b of one simplex face is walked b -> a by exactly one other face.
void Quickhull::linkSimplex() {
  for (Face& f : faces_) {
    for (int i = 0; i < 3; ++i) {
      for (int g = 0; g < 4; ++g) {
        for (int j = 0; j < 3; ++j) {
          const Face& h = faces_[g];
          if (h.v[j] == f.v[(i + 1) % 3] && h.v[(j + 1) % 3] == f.v[i]) f.adj[i] = g;
        }
      }
    }
  }
}

// Gives each candidate point to the new face it is farthest above; points above none are inside
// (or on the hull within the tolerance) and are dropped for good.
void Quickhull::assign(const std::vector<int>& candidates, const std::vector<int>& new_faces) {
  for (int p : candidates) {
    int best = -1;
    double best_d = tol_;
    for (int f : new_faces) {
      const double d = distance(faces_[f], p);
      if (d > best_d) best_d = d, best = f;
    }
    if (best >= 0) faces_[best].outside.push_back(p);
  }
}

// Depth-first over the faces the eye sees. Entering a face across edge `from_edge` and leaving by
// the following edges in CCW order makes the horizon come out as one CCW chain of edges.
void Quickhull::collectHorizon(int f, int from_edge, int eye, std::vector<int>& visible,
                               std::vector<HorizonEdge>& horizon) {
  faces_[f].visible_round = round_;
  visible.push_back(f);
  for (int k = 0; k < 3; ++k) {
    const int i = (from_edge + k) % 3;
    const int n = faces_[f].adj[i];
    if (faces_[n].visible_round == round_) continue;
    if (distance(faces_[n], eye) > tol_) {
      int back = 0;
      while (faces_[n].adj[back] != f) ++back;
      collectHorizon(n, back, eye, visible, horizon);
    } else {
      horizon.push_back({faces_[f].v[i], faces_[f].v[(i + 1) % 3], n});
    }
  }
}

bool Quickhull::isCycle(const std::vector<HorizonEdge>& horizon) {
  if (horizon.size() < 3) return false;
  for (size_t k = 0; k < horizon.size(); ++k) {
    if (horizon[k].b != horizon[(k + 1) % horizon.size()].a) return false;
  }
  return true;
}

// One new face per horizon edge, a fan around the eye; each is linked to the old face beyond its
// horizon edge and to its two neighbours in the fan.
std::vector<int> Quickhull::stitch(const std::vector<HorizonEdge>& horizon, int eye) {
  const size_t n = horizon.size();
  std::vector<int> made(n);
  for (size_t k = 0; k < n; ++k) {
    const HorizonEdge& e = horizon[k];
    made[k] = addFace(e.a, e.b, eye);
    Face& beyond = faces_[e.neighbor];
    for (int j = 0; j < 3; ++j) {
      if (beyond.v[j] == e.b && beyond.v[(j + 1) % 3] == e.a) beyond.adj[j] = made[k];
    }
    faces_[made[k]].adj[0] = e.neighbor;
  }
  for (size_t k = 0; k < n; ++k) {
    faces_[made[k]].adj[1] = made[(k + 1) % n];
    faces_[made[k]].adj[2] = made[(k + n - 1) % n];
  }
  return made;
}

void Quickhull::addPoint(int f) {
  std::vector<int>& out = faces_[f].outside;
  size_t far = 0;
  double far_d = distance(faces_[f], out[0]);
  for (size_t i = 1; i < out.size(); ++i) {
    const double d = distance(faces_[f], out[i]);
    if (d > far_d) far = i, far_d = d;
  }
  const int eye = out[far];
  out.erase(out.begin() + long(far));
  ++round_;
  std::vector<int> visible;
  std::vector<HorizonEdge> horizon;
  collectHorizon(f, 0, eye, visible, horizon);
  // Within the tolerance the visible region can in principle fail to be a disc (near-coplanar
  // faces seen by a point barely above them). Then the point is dropped: it is within a few
  // tolerances of the hull, and the hull stays a valid closed surface.
  if (!isCycle(horizon)) return;
  std::vector<int> orphans;
  for (int v : visible) {
    faces_[v].alive = false;
    orphans.insert(orphans.end(), faces_[v].outside.begin(), faces_[v].outside.end());
    faces_[v].outside.clear();
  }
  assign(orphans, stitch(horizon, eye));
}

TriangleHull Quickhull::output() const {
  std::vector<int> index(faces_.size(), -1);
  TriangleHull hull;
  for (size_t f = 0; f < faces_.size(); ++f) {
    if (!faces_[f].alive) continue;
    index[f] = int(hull.triangles.size());
    hull.triangles.push_back(faces_[f].v);
    hull.normals.push_back(faces_[f].normal);
  }
  for (size_t f = 0; f < faces_.size(); ++f) {
    if (!faces_[f].alive) continue;
    const std::array<int, 3>& a = faces_[f].adj;
    hull.neighbors.push_back({index[a[0]], index[a[1]], index[a[2]]});
  }
  return hull;
}

}  // namespace

std::optional<TriangleHull> quickhull(const std::vector<Eigen::Vector3d>& points, double plane_tol,
                                      std::string* why) {
  std::string ignored;
  return Quickhull(points, plane_tol).run(why ? why : &ignored);
}

}  // namespace tumble
