// Hull simplification (geometry/hull_simplify.h): a hull above the vertex limit becomes the hull of
// some of its own vertices, valid, inside the full hull, and as close as it says.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

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

// Random clouds of every awkward kind the hull code knows (all points on the hull, rings of
// coplanar points, slivers 1000:1, noise at the merge tolerance, far from the origin): whatever
// the full hull, the simplified one is a valid convex piece of at most 255 of its vertices, and
// the deviation it reports is the brute-force one.
TEST_CASE("hull simplify: random awkward clouds give valid pieces within the limit", "[geometry][hull]") {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::normal_distribution<double> normal(0, 1);
  auto onSphere = [&] {
    Vector3d p(normal(rng), normal(rng), normal(rng));
    return Vector3d(p.normalized());
  };
  int simplified = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int kind = trial % 6;
    const int n = 300 + static_cast<int>(rng() % 1700);
    std::vector<Vector3d> cloud;
    for (int i = 0; i < n; ++i) {
      Vector3d p;
      switch (kind) {
        case 0: p = onSphere(); break;                                                      // all on the hull
        case 1: {                                                                           // two rings
          const double a = 2 * M_PI * (rng() % 997) / 997.0;
          p = {std::cos(a), std::sin(a), (i % 2) ? 0.5 : -0.5};
          break;
        }
        case 2: p = onSphere().cwiseProduct(Vector3d(1, 0.01, 0.001)); break;               // sliver
        case 3: p = onSphere() * (1 + 1e-7 * unit(rng)); break;                             // noise at the tolerance
        case 4: p = onSphere() + Vector3d(1e6, -2e5, 3e5); break;                           // far away
        default: p = Vector3d(unit(rng), unit(rng), unit(rng)) * (i % 3 ? 1.0 : 0.2); break; // uniform inside
      }
      cloud.push_back(p);
    }
    INFO("trial " << trial << ", kind " << kind << ", " << n << " points");
    std::optional<ConvexPiece> hull = convexHull(cloud, nullptr);
    REQUIRE(hull);
    std::optional<SimplifiedHull> smaller = simplifyHull(*hull, 255);
    if (hull->vertices.size() <= 255) {
      CHECK_FALSE(smaller);
      continue;
    }
    REQUIRE(smaller);
    ++simplified;
    CHECK(smaller->piece.vertices.size() <= 255);
    CHECK(test::convexPieceProblem(smaller->piece) == "");
    for (const Vector3d& v : smaller->piece.vertices)
      CHECK(std::find(hull->vertices.begin(), hull->vertices.end(), v) != hull->vertices.end());
    CHECK(smaller->deviation_m >= 0);
    CHECK(smaller->deviation_m == Approx(farthestOutside(smaller->piece, hull->vertices)).margin(1e-9));
  }
  CHECK(simplified >= 30);   // the test is about simplification: most clouds must need it
}
