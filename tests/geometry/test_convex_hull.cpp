// Quickhull: exact topology on boxes, robustness to duplicates and near-degenerate clouds, and
// invariants (closed, convex, contains its input) on random clouds.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <chrono>
#include <random>

#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "piece_checks.h"

using namespace tumble;
using Eigen::Vector3d;
using Cloud = std::vector<Vector3d>;

namespace {

Cloud cubeCorners(double h) {
  Cloud c;
  for (int i = 0; i < 8; ++i) c.emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
  return c;
}

void checkBoxTopology(const ConvexPiece& p) {
  CHECK(p.vertices.size() == 8);
  CHECK(p.faces.size() == 6);
  CHECK(p.edges.size() == 12);
  for (const auto& face : p.faces) CHECK(face.size() == 4);
  test::checkConvexPiece(p);
}

Cloud randomCloud(unsigned seed, int kind, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g;
  Cloud c;
  for (int i = 0; i < n; ++i) {
    Vector3d p(u(rng), u(rng), u(rng));
    if (kind == 1) p = Vector3d(g(rng), g(rng), g(rng));
    if (kind == 2) p = Vector3d(g(rng), g(rng), g(rng)).normalized();
    c.push_back(p);
  }
  return c;
}

}  // namespace

TEST_CASE("cube from its corners plus interior, face and duplicate points: 8 V, 6 quads, 12 E",
          "[hull]") {
  Cloud pts = cubeCorners(0.5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (int i = 0; i < 200; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
  for (int i = 0; i < 50; ++i) pts.emplace_back(0.5, u(rng), u(rng));  // on the +x face
  for (int i = 0; i < 50; ++i) pts.emplace_back(u(rng), -0.5, -0.5);   // on an edge
  const Cloud corners = cubeCorners(0.5);
  pts.insert(pts.end(), corners.begin(), corners.end());                // every corner twice
  std::string why;
  const auto hull = convexHull(pts, &why);
  REQUIRE(hull);
  checkBoxTopology(*hull);
  CHECK(containsAll(*hull, pts));
  CHECK(volume(*hull) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("a rotated, float-rounded box still merges into 6 quads", "[hull]") {
  // Meshes arrive as float32: a tilted face is then flat only to ~1e-7 of its size.
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.6, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  Cloud pts;
  for (const Vector3d& c : cubeCorners(0.3)) {
    pts.push_back((r * Vector3d(c.x(), 0.5 * c.y(), 2 * c.z()) + Vector3d(1, 2, 3))
                      .cast<float>().cast<double>());
  }
  const auto hull = convexHull(pts, nullptr);
  REQUIRE(hull);
  checkBoxTopology(*hull);
}

TEST_CASE("duplicated tetrahedron corners give the tetrahedron", "[hull]") {
  const Cloud corners{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Cloud pts;
  for (int k = 0; k < 3; ++k) pts.insert(pts.end(), corners.begin(), corners.end());
  const auto hull = convexHull(pts, nullptr);
  REQUIRE(hull);
  CHECK(hull->vertices.size() == 4);
  CHECK(hull->faces.size() == 4);
  CHECK(hull->edges.size() == 6);
  test::checkConvexPiece(*hull);
}

TEST_CASE("degenerate clouds give nullopt and say why", "[hull]") {
  std::string why;
  CHECK_FALSE(convexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, &why));
  CHECK(why == "fewer than 4 points");
  CHECK_FALSE(convexHull(Cloud(10, Vector3d(1, 2, 3)), &why));
  CHECK(why == "all points coincide");
  Cloud line, plane;
  for (int i = 0; i < 10; ++i) line.push_back(Vector3d(1, 2, 3) * i);
  CHECK_FALSE(convexHull(line, &why));
  CHECK(why == "all points are collinear");
  // A tilted 5 x 5 grid, with one point lifted by 1e-12 of the size: still flat.
  const Vector3d a(1, 0.3, -0.2), b(-0.1, 1, 0.7);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) plane.push_back(i * a + j * b);
  plane[12] += 1e-12 * a.cross(b).normalized();
  CHECK_FALSE(convexHull(plane, &why));
  CHECK(why == "all points are coplanar");
  plane[12] += 1e-3 * a.cross(b).normalized();  // a real (if thin) pyramid
  CHECK(convexHull(plane, &why));
  Cloud bad = cubeCorners(1);
  bad[3].x() = std::nan("");
  CHECK_FALSE(convexHull(bad, &why));
}

TEST_CASE("random clouds: closed, convex, Euler 2, contain every input point", "[hull]") {
  const int kind = GENERATE(0, 1, 2);
  const unsigned seed = GENERATE(1u, 2u, 3u, 4u);
  const double offset = GENERATE(0.0, 1e4);
  Cloud pts = randomCloud(seed, kind, 2000);
  for (Vector3d& p : pts) p += Vector3d::Constant(offset);
  std::string why;
  const auto hull = convexHull(pts, &why);
  REQUIRE(hull);
  test::checkConvexPiece(*hull);
  CHECK(containsAll(*hull, pts));
  if (kind == 2) CHECK(hull->vertices.size() == pts.size());  // points on a sphere are all extreme
}

TEST_CASE("hull of an icosphere's vertices: 642 V, 1280 F, 1920 E", "[hull]") {
  const ConvexPiece sphere = makeIcosphere(0.5, 3);
  const auto hull = convexHull(sphere.vertices, nullptr);
  REQUIRE(hull);
  CHECK(hull->vertices.size() == 642);
  CHECK(hull->faces.size() == 1280);
  CHECK(hull->edges.size() == 1920);
  test::checkConvexPiece(*hull);
  CHECK(volume(*hull) == Approx(volume(sphere)).epsilon(1e-12));
}

TEST_CASE("containsAll rejects a point outside", "[hull]") {
  const ConvexPiece box = makeBox(Vector3d(1, 2, 3));
  CHECK(containsAll(box, {{0.999, 1.999, -2.999}}));
  CHECK_FALSE(containsAll(box, {{0, 0, 3.001}}));
}

// Timings are reported, not asserted (numbers come from benchmarks, never from
// timed tests). Run with: test_geometry "[.timing]"
TEST_CASE("hull timings", "[.timing]") {
  using Clock = std::chrono::steady_clock;
  auto time = [](const Cloud& pts) {
    const int reps = 20;
    const auto t0 = Clock::now();
    for (int i = 0; i < reps; ++i) REQUIRE(convexHull(pts, nullptr));
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / reps;
  };
  WARN("icosphere 642 points: " << time(makeIcosphere(1, 3).vertices) << " ms");
  WARN("uniform cube 5000 points: " << time(randomCloud(1, 0, 5000)) << " ms");
  WARN("gaussian 5000 points: " << time(randomCloud(1, 1, 5000)) << " ms");
  WARN("sphere surface 5000 points: " << time(randomCloud(1, 2, 5000)) << " ms");
}
