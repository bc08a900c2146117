#include "geometry/hull_simplify.h"

#include <algorithm>
#include <cmath>

#include "geometry/convex_hull.h"

namespace tumble {
namespace {

using Eigen::Vector3d;

// `count` unit directions of a Fibonacci lattice: nearly even spacing, no clustering at poles.
std::vector<Vector3d> evenDirections(int count) {
  std::vector<Vector3d> out;
  out.reserve(count);
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1 - (2 * i + 1) / double(count);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

// Indices (ascending, distinct) of the vertices extreme along each direction.
std::vector<int> extremeVertices(const std::vector<Vector3d>& vertices, const std::vector<Vector3d>& directions) {
  std::vector<int> out;
  out.reserve(directions.size());
  for (const Vector3d& d : directions) {
    int best = 0;
    double reach = d.dot(vertices[0]);
    for (int v = 1; v < int(vertices.size()); ++v) {
      const double r = d.dot(vertices[v]);
      if (r > reach) reach = r, best = v;
    }
    out.push_back(best);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// For each face of `piece`, the vertex of `all` farthest in front of it (and how far), when any is.
std::vector<std::pair<double, int>> farthestInFront(const ConvexPiece& piece, const std::vector<Vector3d>& all) {
  std::vector<std::pair<double, int>> out;
  for (std::size_t f = 0; f < piece.faces.size(); ++f) {
    const Vector3d on_face = piece.vertices[piece.faces[f][0]];
    double far = 0;
    int which = -1;
    for (int v = 0; v < int(all.size()); ++v) {
      const double d = piece.face_normals[f].dot(all[v] - on_face);
      if (d > far) far = d, which = v;
    }
    if (which >= 0) out.emplace_back(far, which);
  }
  return out;
}

}  // namespace

std::optional<SimplifiedHull> simplifyHull(const ConvexPiece& hull, int max_vertices) {
  if (int(hull.vertices.size()) <= max_vertices || max_vertices < 4) return std::nullopt;
  // Half the vertices from directions spread evenly: a coarse hull touching the full one all
  // round (more directions find more distinct vertices; the lattice grows while they fit).
  const int coarse = std::max(4, max_vertices / 2);
  std::vector<int> chosen;
  for (int count = coarse; count <= 64 * coarse; count = count * 5 / 4) {
    std::vector<int> found = extremeVertices(hull.vertices, evenDirections(count));
    if (int(found.size()) > coarse) break;
    chosen = std::move(found);
  }
  if (chosen.size() < 4) return std::nullopt;
  auto hullOf = [&](const std::vector<int>& indices) {
    std::vector<Vector3d> points;
    points.reserve(indices.size());
    for (int v : indices) points.push_back(hull.vertices[v]);
    return convexHull(points, nullptr);
  };
  std::optional<ConvexPiece> smaller = hullOf(chosen);
  if (!smaller) return std::nullopt;
  // Then the rest where the coarse hull is farthest inside: even directions leave big facets where
  // the surface is flattest (the long sides of an elongated shape), which these rounds fill in,
  // each adding the farthest vertices in front of its faces, at most half the budget left.
  while (int(chosen.size()) < max_vertices) {
    std::vector<std::pair<double, int>> ahead = farthestInFront(*smaller, hull.vertices);
    std::sort(ahead.begin(), ahead.end(), [](const auto& x, const auto& y) {
      return x.first > y.first || (x.first == y.first && x.second < y.second);
    });
    const int room = max_vertices - int(chosen.size());
    const int take = std::max(1, room / 2);
    int added = 0;
    for (const auto& [distance, v] : ahead) {
      if (added == take) break;
      if (std::find(chosen.begin(), chosen.end(), v) != chosen.end()) continue;
      chosen.push_back(v);
      ++added;
    }
    if (added == 0) break;
    std::sort(chosen.begin(), chosen.end());
    std::optional<ConvexPiece> finer = hullOf(chosen);
    if (!finer) break;
    smaller = std::move(finer);
  }
  SimplifiedHull out{std::move(*smaller), 0};
  for (std::size_t f = 0; f < out.piece.faces.size(); ++f) {
    const Vector3d on_face = out.piece.vertices[out.piece.faces[f][0]];
    for (const Vector3d& v : hull.vertices)
      out.deviation_m = std::max(out.deviation_m, out.piece.face_normals[f].dot(v - on_face));
  }
  return out;
}

}  // namespace tumble
