// From quickhull's triangles to a ConvexPiece: coplanar triangles merged into polygons, vertices
// that ended up in the middle of an edge dropped, the survivors re-indexed.
#include "geometry/convex_hull.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "geometry/hull_tolerance.h"
#include "geometry/piece_builder.h"
#include "geometry/quickhull.h"

namespace tumble {
namespace {

using Eigen::Vector3d;
using Loop = std::vector<int>;

double triangleArea(const std::vector<Vector3d>& p, const std::array<int, 3>& t) {
  return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
}

struct Groups {
  std::vector<std::vector<int>> members;  // triangles of each group, seed first
  std::vector<int> group_of;              // group of each triangle
};

// Groups of edge-connected triangles lying in one plane within `merge` (m). Seeds go largest
// first, because a large triangle's normal is the most accurate estimate of the group's plane;
// every member is tested against the seed's plane, never its neighbour's, so that a gently curved
// surface cannot creep into one group triangle by triangle.

Groups coplanarGroups(const std::vector<Vector3d>& p, const TriangleHull& h, double merge) {
  std::vector<int> order(h.triangles.size());
  std::vector<double> area(h.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  for (int t : order) area[t] = triangleArea(p, h.triangles[t]);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });
  std::vector<int> group_of(h.triangles.size(), -1);
  std::vector<std::vector<int>> groups;
  for (int seed : order) {
    if (group_of[seed] >= 0) continue;
    const Vector3d& n = h.normals[seed];
    const Vector3d& origin = p[h.triangles[seed][0]];
    std::vector<int> group{seed};
    group_of[seed] = int(groups.size());
    for (size_t k = 0; k < group.size(); ++k) {
      for (int t : h.neighbors[group[k]]) {
        if (group_of[t] >= 0 || h.normals[t].dot(n) <= 0) continue;
        bool flat = true;
        for (int v : h.triangles[t]) flat = flat && std::abs(n.dot(p[v] - origin)) <= merge;
        if (!flat) continue;
        group_of[t] = int(groups.size());
        group.push_back(t);
      }
    }
    groups.push_back(std::move(group));
  }
  return {std::move(groups), std::move(group_of)};
}

// The boundary of a group: its triangles' directed edges whose neighbour is outside the group,
// chained head to tail. Empty when they do not form one simple loop (two loops, or a vertex
// where the boundary pinches), in which case the caller keeps the triangles unmerged.
Loop boundaryLoop(const TriangleHull& h, const Groups& groups, int g) {
  const std::vector<int>& group = groups.members[g];
  if (group.size() == 1) return Loop(h.triangles[group[0]].begin(), h.triangles[group[0]].end());
  std::map<int, int> next;
  for (int t : group) {
    for (int i = 0; i < 3; ++i) {
      if (groups.group_of[h.neighbors[t][i]] == g) continue;
      if (!next.emplace(h.triangles[t][i], h.triangles[t][(i + 1) % 3]).second) return {};
    }
  }
  Loop loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    const auto it = next.find(loop.back());
    if (it == next.end()) return {};
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  return loop.size() == next.size() ? loop : Loop{};
}

std::vector<Loop> mergedFaces(const std::vector<Vector3d>& p, const TriangleHull& h, double merge) {
  std::vector<Loop> faces;
  const Groups groups = coplanarGroups(p, h, merge);
  for (size_t g = 0; g < groups.members.size(); ++g) {
    Loop loop = boundaryLoop(h, groups, int(g));
    if (!loop.empty()) {
      faces.push_back(std::move(loop));
      continue;
    }
    for (int t : groups.members[g]) faces.emplace_back(h.triangles[t].begin(), h.triangles[t].end());
  }
  return faces;
}

// A vertex of a polytope meets at least three faces. One that meets only two lies on their
// common edge (a point quickhull added before a farther one made it redundant, flattened by the
// merge): dropping it from both loops keeps the surface closed and the polygons convex.
void dropEdgeVertices(std::vector<Loop>& faces, size_t vertex_count) {
  std::vector<int> face_count(vertex_count, 0);
  for (const Loop& f : faces) {
    for (int v : f) ++face_count[v];
  }
  for (Loop& f : faces) {
    std::erase_if(f, [&](int v) { return face_count[v] < 3; });
  }
  std::erase_if(faces, [](const Loop& f) { return f.size() < 3; });
}

// Keeps the vertices the faces use, in their input order, and renumbers the faces.
ConvexPiece reindexed(const std::vector<Vector3d>& p, std::vector<Loop> faces) {
  std::vector<int> index(p.size(), -1);
  for (const Loop& f : faces) {
    for (int v : f) index[v] = 0;
  }
  std::vector<Vector3d> vertices;
  for (size_t i = 0; i < p.size(); ++i) {
    if (index[i] < 0) continue;
    index[i] = int(vertices.size());
    vertices.push_back(p[i]);
  }
  for (Loop& f : faces) {
    for (int& v : f) v = index[v];
  }
  return buildPiece(std::move(vertices), std::move(faces));
}

// The smallest extent of the hull's vertices along the normals of its largest triangles: an upper
// bound of its width, exact for a slab, whose two large sides hold the largest triangles. A few
// normals keep this O(V) on meshes of any size; closed() below catches what it misses.
double slabWidth(const std::vector<Vector3d>& p, const TriangleHull& h) {
  std::vector<int> order(h.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  const size_t count = std::min<size_t>(order.size(), 16);
  std::partial_sort(order.begin(), order.begin() + count, order.end(), [&](int a, int b) {
    return triangleArea(p, h.triangles[a]) > triangleArea(p, h.triangles[b]);
  });
  std::vector<int> used;
  for (const std::array<int, 3>& tri : h.triangles) used.insert(used.end(), tri.begin(), tri.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  double thinnest = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < count; ++k) {
    const Vector3d& n = h.normals[order[k]];
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int v : used) {
      lo = std::min(lo, n.dot(p[v]));
      hi = std::max(hi, n.dot(p[v]));
    }
    thinnest = std::min(thinnest, hi - lo);
  }
  return thinnest;
}

// A closed polyhedron: at least 4 faces, every directed edge walked once and its reverse once.
bool closed(const std::vector<Loop>& faces) {
  if (faces.size() < 4) return false;
  std::map<std::pair<int, int>, int> directed;
  for (const Loop& f : faces)
    for (size_t i = 0; i < f.size(); ++i) ++directed[{f[i], f[(i + 1) % f.size()]}];
  for (const auto& [edge, count] : directed)
    if (count != 1 || !directed.count({edge.second, edge.first})) return false;
  return true;
}

}  // namespace

std::optional<ConvexPiece> convexHull(const std::vector<Eigen::Vector3d>& points, std::string* why) {
  std::string ignored;
  if (!why) why = &ignored;
  for (const Vector3d& p : points) {
    if (!p.allFinite()) return *why = "a point has a NaN or infinite coordinate", std::nullopt;
  }
  const HullTolerance tol = hullTolerance(points);
  std::optional<TriangleHull> triangles = quickhull(points, tol.plane, why);
  if (!triangles) return std::nullopt;
  // A cloud thinner than the merge tolerance (found by fuzzing: a 3 km sliver 4e-5 m thick) has
  // its two sides merged into one face each, and its vertices then meet two faces only and are
  // dropped: nothing would be left. Such a cloud is flat at the precision the hull promises.
  if (slabWidth(points, *triangles) <= 2 * tol.merge)
    return *why = "the points lie within the merge tolerance of a plane (flat)", std::nullopt;
  std::vector<Loop> faces = mergedFaces(points, *triangles, tol.merge);
  dropEdgeVertices(faces, points.size());
  if (!closed(faces)) return *why = "merging coplanar faces left no closed surface (too thin)", std::nullopt;
  return reindexed(points, std::move(faces));
}

bool containsAll(const ConvexPiece& hull, const std::vector<Eigen::Vector3d>& points) {
  const double tol = hullTolerance(hull.vertices).contain;
  for (size_t f = 0; f < hull.faces.size(); ++f) {
    // Measured from the face's mean vertex: a merged face is flat only within the merge
    // tolerance, and its mean lies on its best-fit plane.
    Vector3d mean = Vector3d::Zero();
    for (int v : hull.faces[f]) mean += hull.vertices[v];
    mean /= double(hull.faces[f].size());
    for (const Vector3d& p : points) {
      if (!(hull.face_normals[f].dot(p - mean) <= tol)) return false;
    }
  }
  return true;
}

}  // namespace tumble
