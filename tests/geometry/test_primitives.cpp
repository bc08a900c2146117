#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "piece_checks.h"

using namespace tumble;
using Eigen::Vector3d;

TEST_CASE("makeBox: 8 vertices, 6 outward quads, 12 edges", "[primitives]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.25, 0.1));
  CHECK(box.vertices.size() == 8);
  CHECK(box.faces.size() == 6);
  CHECK(box.edges.size() == 12);
  test::checkConvexPiece(box);
  for (const Vector3d& n : box.face_normals) CHECK(n.cwiseAbs().maxCoeff() == 1.0);
  CHECK(volume(box) == Approx(1.0 * 0.5 * 0.2).epsilon(1e-12));
}

TEST_CASE("makeIcosphere: counts per level, vertices on the sphere", "[primitives]") {
  const int level = GENERATE(0, 1, 3);
  const ConvexPiece s = makeIcosphere(0.3, level);
  const size_t faces = 20 * size_t(std::pow(4, level));
  CHECK(s.faces.size() == faces);
  CHECK(s.vertices.size() == faces / 2 + 2);
  CHECK(s.edges.size() == faces * 3 / 2);
  test::checkConvexPiece(s);
  for (const Vector3d& v : s.vertices) CHECK(v.norm() == Approx(0.3).epsilon(1e-15));
  const double ball = 4.0 / 3 * std::numbers::pi * 0.3 * 0.3 * 0.3;
  CHECK(volume(s) < ball);
  if (level == 3) CHECK(volume(s) > 0.98 * ball);  // inscribed polyhedron: ~1.2 % short at level 3
}
