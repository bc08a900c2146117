#include "collision/collision_hull.h"

#include <cassert>
#include <map>
#include <utility>

#include "collision/aabb.h"

namespace tumble {

namespace {

// Faces are CCW from outside, so each edge runs first->second in one neighbour (slot 0) and
// second->first in the other (slot 1).
std::vector<std::array<int, 2>> edgeFaces(const ConvexPiece& piece) {
  std::map<std::pair<int, int>, int> index;
  for (int k = 0; k < int(piece.edges.size()); ++k) index[piece.edges[k]] = k;
  std::vector<std::array<int, 2>> faces(piece.edges.size(), {-1, -1});
  for (int f = 0; f < int(piece.faces.size()); ++f) {
    const std::vector<int>& poly = piece.faces[f];
    for (size_t i = 0; i < poly.size(); ++i) {
      const int u = poly[i], v = poly[(i + 1) % poly.size()];
      const auto it = index.find(std::minmax(u, v));
      assert(it != index.end());
      faces[it->second][u < v ? 0 : 1] = f;
    }
  }
  // A rounded piece's core (a segment) and a solid of revolution's axis have an edge but no faces.
  if (!piece.smooth())
    for ([[maybe_unused]] const auto& ef : faces) assert(ef[0] >= 0 && ef[1] >= 0);
  return faces;
}

}  // namespace

CollisionHull makeCollisionHull(const ConvexPiece& piece) {
  assert(!piece.vertices.empty() && piece.faces.size() == piece.face_normals.size());
  CollisionHull hull;
  hull.piece = &piece;
  hull.edge_faces = edgeFaces(piece);
  for (size_t f = 0; f < piece.faces.size(); ++f) {
    // offset from the face's mean, not one vertex: best fit for faces flat only within tolerance
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : piece.faces[f]) mean += piece.vertices[v];
    mean /= double(piece.faces[f].size());
    hull.face_offsets.push_back(piece.face_normals[f].dot(mean));
  }
  Eigen::Vector3d lo = piece.vertices[0], hi = piece.vertices[0];
  for (const Eigen::Vector3d& v : piece.vertices) {
    hull.centroid += v;
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  hull.centroid /= double(piece.vertices.size());
  hull.radius = pieceRadius(piece);
  hull.size = (hi - lo).maxCoeff() + 2 * (piece.radius_m + piece.disc_radius_m);
  hull.box = recogniseBox(piece, hull.centroid);
  return hull;
}

}  // namespace tumble
