#include "collision/box_shape.h"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

// Rounding of a box built from its extents (a cube's corners, rotated or not, are exact to a few
// ulps); a mesh box whose corners were written to nine decimals is off by 1e-9 of its size and is
// left to the general test, which reads its vertices as they are.
constexpr double kCornerAgreement = 1e-12;

}  // namespace

std::optional<BoxShape> recogniseBox(const ConvexPiece& piece, const Eigen::Vector3d& centre) {
  if (piece.smooth() || piece.vertices.size() != 8 || piece.faces.size() != 6 || piece.edges.size() != 12)
    return std::nullopt;
  for (const std::vector<int>& f : piece.faces)
    if (f.size() != 4) return std::nullopt;
  BoxShape box;
  std::array<Eigen::Vector3d, 3> axis;
  std::array<bool, 6> paired{};
  int axes = 0;
  for (int f = 0; f < 6; ++f) {
    if (paired[f]) continue;
    int opposite = -1;
    for (int g = f + 1; g < 6 && opposite < 0; ++g)
      if (!paired[g] && piece.face_normals[f].dot(piece.face_normals[g]) < -1 + kCornerAgreement) opposite = g;
    if (opposite < 0 || axes == 3) return std::nullopt;
    paired[f] = paired[opposite] = true;
    box.plus_face[axes] = f;
    box.minus_face[axes] = opposite;
    axis[axes++] = piece.face_normals[f];
  }
  for (int k = 0; k < 3; ++k)
    for (int l = k + 1; l < 3; ++l)
      if (std::abs(axis[k].dot(axis[l])) > kCornerAgreement) return std::nullopt;
  double size = 0;
  for (const Eigen::Vector3d& v : piece.vertices) size = std::max(size, (v - centre).norm());
  const double tol = kCornerAgreement * size;
  for (int k = 0; k < 3; ++k) {
    double half = 0;
    for (const Eigen::Vector3d& v : piece.vertices) half = std::max(half, std::abs((v - centre).dot(axis[k])));
    for (const Eigen::Vector3d& v : piece.vertices)
      if (std::abs(std::abs((v - centre).dot(axis[k])) - half) > tol) return std::nullopt;
    box.half[k] = half;
  }
  for (auto& by_axis : box.edge)
    for (auto& row : by_axis) row = {-1, -1};
  for (int e = 0; e < 12; ++e) {
    const auto [v0, v1] = piece.edges[static_cast<std::size_t>(e)];
    const Eigen::Vector3d along = piece.vertices[v1] - piece.vertices[v0];
    const Eigen::Vector3d middle = 0.5 * (piece.vertices[v0] + piece.vertices[v1]) - centre;
    int k = 0;
    for (int m = 1; m < 3; ++m)
      if (std::abs(along.dot(axis[m])) > std::abs(along.dot(axis[k]))) k = m;
    const auto [first, second] = otherAxes(k);
    int& slot = box.edge[k][middle.dot(axis[first]) > 0][middle.dot(axis[second]) > 0];
    if (slot >= 0) return std::nullopt;
    slot = e;
  }
  return box;
}

}  // namespace tumble
