#include "geometry/piece_builder.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>

namespace tumble {

Eigen::Vector3d polygonNormal(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<int>& face) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i : face) mean += vertices[i];
  mean /= double(face.size());
  // Newell: n = 1/2 sum_i (p_i - m) x (p_{i+1} - m) is twice the vector area of the polygon.
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < face.size(); ++i) {
    const Eigen::Vector3d a = vertices[face[i]] - mean;
    const Eigen::Vector3d b = vertices[face[(i + 1) % face.size()]] - mean;
    n += a.cross(b);
  }
  return n.normalized();
}

ConvexPiece buildPiece(std::vector<Eigen::Vector3d> vertices, std::vector<std::vector<int>> faces) {
  ConvexPiece piece;
  piece.vertices = std::move(vertices);
  piece.faces = std::move(faces);
  piece.face_normals.reserve(piece.faces.size());
  for (const std::vector<int>& face : piece.faces) {
    piece.face_normals.push_back(polygonNormal(piece.vertices, face));
    for (size_t i = 0; i < face.size(); ++i) {
      const int a = face[i], b = face[(i + 1) % face.size()];
      // On a closed surface every edge is walked once in each direction; keep the a < b walk.
      if (a < b) piece.edges.emplace_back(a, b);
    }
  }
  std::sort(piece.edges.begin(), piece.edges.end());
  piece.edges.erase(std::unique(piece.edges.begin(), piece.edges.end()), piece.edges.end());
  return piece;
}

}  // namespace tumble
