// Hull simplification (geometry/hull_simplify.h): a hull above the vertex limit becomes the hull of
// some of its own vertices, valid, inside the full hull, and as close as it says.
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/convex_hull.h"
#include "geometry/hull_simplify.h"
#include "geometry/mesh_import.h"
#include "piece_validity.h"

using namespace tumble;
using Eigen::Vector3d;

namespace {

// n points spread over an ellipsoid with semi-axes (a, b, c): every one is a hull vertex.
std::vector<Vector3d> ellipsoidPoints(int n, double a, double b, double c) {
  std::vector<Vector3d> out;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1) / double(n), r = std::sqrt(1 - z * z);
    out.emplace_back(a * r * std::cos(golden * i), b * r * std::sin(golden * i), c * z);
  }
  return out;
}

// The farthest any of `points` lies outside `piece`, by brute force over its face planes.
double farthestOutside(const ConvexPiece& piece, const std::vector<Vector3d>& points) {
  double worst = 0;
  for (std::size_t f = 0; f < piece.faces.size(); ++f) {
    const Vector3d on = piece.vertices[piece.faces[f][0]];
    for (const Vector3d& p : points) worst = std::max(worst, piece.face_normals[f].dot(p - on));
  }
  return worst;
}

}  // namespace

TEST_CASE("hull simplify: a hull within the limit is left alone", "[geometry][hull]") {
  std::optional<ConvexPiece> hull = convexHull(ellipsoidPoints(200, 1, 1, 1), nullptr);
  REQUIRE(hull);
  CHECK_FALSE(simplifyHull(*hull, 255));
}

TEST_CASE("hull simplify: 4000 vertices of an ellipsoid become at most 255, valid and close", "[geometry][hull]") {
  const std::vector<Vector3d> points = ellipsoidPoints(4000, 2, 1, 0.5);
  std::optional<ConvexPiece> hull = convexHull(points, nullptr);
  REQUIRE(hull);
  REQUIRE(hull->vertices.size() == 4000);
  std::optional<SimplifiedHull> smaller = simplifyHull(*hull, 255);
  REQUIRE(smaller);
  CHECK(smaller->piece.vertices.size() <= 255);
  // Not far below the limit either: the lattice grows until it would pass it.
  CHECK(smaller->piece.vertices.size() >= 200);
  CHECK(test::convexPieceProblem(smaller->piece) == "");
  // Every vertex kept is one of the full hull's, so the new hull lies inside it.
  for (const Vector3d& v : smaller->piece.vertices)
    CHECK(std::find(points.begin(), points.end(), v) != points.end());
  // The deviation it reports is the brute-force one. 255 points on this ellipsoid are about
  // 0.12 m apart on the 2 m axis; a flat facet that wide sits ~0.12^2 / (8 * 0.5 curvature radius)
  // below the surface, a few millimetres; 0.02 m (1 % of the longest axis) bounds it with room.
  CHECK(smaller->deviation_m == Approx(farthestOutside(smaller->piece, points)).margin(1e-12));
  CHECK(smaller->deviation_m > 0);
  CHECK(smaller->deviation_m < 0.02);
}

TEST_CASE("hull simplify: an imported mesh with a large hull is simplified, with a warning", "[geometry][hull]") {
  const std::vector<Vector3d> points = ellipsoidPoints(1000, 1, 1, 1);
  std::optional<ConvexPiece> hull = convexHull(points, nullptr);
  REQUIRE(hull);
  // The hull's own triangles as the mesh: convex, so the only warning is the simplification.
  std::vector<std::array<int, 3>> triangles;
  for (const std::vector<int>& face : hull->faces)
    for (std::size_t i = 1; i + 1 < face.size(); ++i) triangles.push_back({face[0], face[i], face[i + 1]});
  std::vector<Vector3d> cloud = hull->vertices;
  std::string warning;
  ConvexPiece piece = convexPieceOf("ball", cloud, triangles, "ball.obj", &warning);
  CHECK(piece.vertices.size() <= 255);
  CHECK(test::convexPieceProblem(piece) == "");
  CHECK_THAT(warning, Catch::Matchers::Contains("its hull has 1000 vertices") &&
                          Catch::Matchers::Contains("m inside the full hull"));
}
