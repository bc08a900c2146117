// Two boxes' edge axes from their half extents (box_sat.cpp) against the general Gauss-map query
// (sat.cpp) that tests every pair of their edges: the same axis, the same edges, the same
// separation. Tolerance: 1e-12 of the boxes' size, rounding of a few dot products on unit vectors
// (the two compute the gap along the same axis from different points: the edges' first ends, and
// the centres less the support radii).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "collision/box_shape.h"
#include "collision/narrow_internal.h"
#include "geometry/convex_hull.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;

namespace {

// A hull seen in A's frame: its vertices, normals and face planes moved by `rel`.
struct MovedView {
  std::vector<Vector3d> vertices, normals;
  std::vector<double> offsets;
  narrow::HullView view;
  MovedView(const CollisionHull& h, const Eigen::Isometry3d& rel) {
    for (const Vector3d& v : h.piece->vertices) vertices.push_back(rel * v);
    for (const Vector3d& n : h.piece->face_normals) normals.push_back(rel.linear() * n);
    for (std::size_t f = 0; f < normals.size(); ++f) offsets.push_back(h.face_offsets[f] + normals[f].dot(rel.translation()));
    view = {&h, vertices.data(), normals.data(), offsets.data(), rel * h.centroid};
  }
};

Eigen::Isometry3d randomPose(std::mt19937& rng, double reach) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
  p.linear() = q.normalized().toRotationMatrix();
  p.translation() = reach * Vector3d(u(rng), u(rng), u(rng));
  return p;
}

}  // namespace

TEST_CASE("box shape: boxes are recognised, and nothing else", "[narrow][box]") {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.2, 0.1));
  const CollisionHull hull = makeCollisionHull(box);
  REQUIRE(hull.box);
  for (int k = 0; k < 3; ++k) {
    const Vector3d axis = box.face_normals[hull.box->plus_face[k]];
    CHECK(box.face_normals[hull.box->minus_face[k]].dot(axis) == Approx(-1));
    CHECK(hull.box->half[k] == Approx(std::abs(axis.dot(Vector3d(0.5, 0.2, 0.1)))));
    // each of the axis' four edges runs along it, at the corner its slot names
    for (int s1 = 0; s1 < 2; ++s1)
      for (int s2 = 0; s2 < 2; ++s2) {
        const auto [v0, v1] = box.edges[hull.box->edge[k][s1][s2]];
        CHECK(std::abs((box.vertices[v1] - box.vertices[v0]).normalized().dot(axis)) == Approx(1));
      }
  }
  // A box rotated in its own mesh is still a box; a sheared one, one with a corner 1e-9 of its size
  // out of place, and a tetrahedron are not.
  std::mt19937 rng(3);
  const Eigen::Isometry3d turn = randomPose(rng, 0.3);
  std::vector<Vector3d> turned, sheared, nudged;
  for (const Vector3d& v : box.vertices) {
    turned.push_back(turn * v);
    sheared.push_back(v + Vector3d(0.2 * v.z(), 0, 0));
    nudged.push_back(v);
  }
  nudged[0] += Vector3d(1e-9, 0, 0);
  std::string why;
  const ConvexPiece turned_box = *convexHull(turned, &why), sheared_box = *convexHull(sheared, &why),
                    nudged_box = *convexHull(nudged, &why);
  CHECK(makeCollisionHull(turned_box).box);
  CHECK_FALSE(makeCollisionHull(sheared_box).box);
  CHECK_FALSE(makeCollisionHull(nudged_box).box);
  const ConvexPiece tetra = *convexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, &why);
  CHECK_FALSE(makeCollisionHull(tetra).box);
}

TEST_CASE("box edge query: the same axis, edges and separation as the Gauss-map query", "[narrow][box]") {
  const ConvexPiece plank = makeBox(Vector3d(0.6, 0.1, 0.03)), cube = makeBox(Vector3d(0.2, 0.2, 0.2));
  const CollisionHull a = makeCollisionHull(plank), b = makeCollisionHull(cube);
  REQUIRE(a.box);
  REQUIRE(b.box);
  std::mt19937 rng(7);
  const MovedView native(a, Eigen::Isometry3d::Identity());
  int compared = 0, with_edges = 0;
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 4000; ++trial) {
    // Half at random, half nearly aligned (a stack: tilts from 1e-9 to 1e-3 rad about a random
    // axis, and a quarter turn about a box axis), where the edge axes lie close to face planes.
    Eigen::Isometry3d rel = randomPose(rng, 0.7);
    if (trial % 2) {
      const double tilt = std::pow(10.0, -9 + 6 * (0.5 + 0.5 * u(rng)));
      rel.linear() = (Eigen::AngleAxisd(tilt, Vector3d(u(rng), u(rng), u(rng)).normalized()) *
                      Eigen::AngleAxisd(M_PI / 2 * (trial % 4 == 1), Vector3d::UnitZ())).toRotationMatrix();
      rel.translation() = Vector3d(0.3 * u(rng), 0.1 * u(rng), 0.23 + 0.01 * u(rng));
    }
    const MovedView moved(b, rel);
    const narrow::AxisQuery general = narrow::queryEdges(native.view, moved.view, INFINITY);
    const narrow::AxisQuery boxes = narrow::queryBoxEdges(native.view, *a.box, moved.view, *b.box, INFINITY);
    ++compared;
    REQUIRE(std::isfinite(general.separation) == std::isfinite(boxes.separation));
    if (!std::isfinite(general.separation)) continue;
    ++with_edges;
    INFO("trial " << trial << ": general " << general.separation << " at " << general.index_a << "," << general.index_b
                  << "; boxes " << boxes.separation << " at " << boxes.index_a << "," << boxes.index_b);
    CHECK(boxes.separation == Approx(general.separation).margin(1e-12 * 1.2));
    CHECK(boxes.index_a == general.index_a);
    CHECK(boxes.index_b == general.index_b);
  }
  CHECK(with_edges > compared / 2);
}

TEST_CASE("box edge query: boxes sharing an axis leave their edge axes to the faces", "[narrow][box]") {
  // Turned about z only: every edge pair is either parallel or meets in a face plane, where the
  // general query's Gauss-map test is strict. Neither query gives an edge axis.
  const ConvexPiece cube = makeBox(Vector3d(0.2, 0.2, 0.2));
  const CollisionHull h = makeCollisionHull(cube);
  Eigen::Isometry3d rel = Eigen::Isometry3d::Identity();
  rel.linear() = Eigen::AngleAxisd(0.4, Vector3d::UnitZ()).toRotationMatrix();
  rel.translation() = Vector3d(0.1, 0.05, 0.399);
  const MovedView native(h, Eigen::Isometry3d::Identity()), moved(h, rel);
  CHECK(narrow::queryEdges(native.view, moved.view, INFINITY).separation == -INFINITY);
  CHECK(narrow::queryBoxEdges(native.view, *h.box, moved.view, *h.box, INFINITY).separation == -INFINITY);
}

TEST_CASE("box face separation: a box's support radius gives its deepest corner's gap", "[narrow][box]") {
  // faceSeparation takes a box's lowest point along the face normal from its centre and half
  // extents; here against the lowest of its eight corners, for a box face and for a general hull's.
  const ConvexPiece plank = makeBox(Vector3d(0.6, 0.1, 0.03)), cube = makeBox(Vector3d(0.2, 0.2, 0.2));
  std::string why;
  const ConvexPiece wedge = *convexHull({{0, 0, 0}, {0.5, 0, 0}, {0, 0.4, 0}, {0, 0, 0.3}, {0.2, 0.3, 0.25}}, &why);
  const CollisionHull b = makeCollisionHull(cube);
  REQUIRE(b.box);
  std::mt19937 rng(11);
  for (const ConvexPiece* ref_piece : {&plank, &wedge}) {
    const CollisionHull a = makeCollisionHull(*ref_piece);
    const MovedView native(a, Eigen::Isometry3d::Identity());
    for (int trial = 0; trial < 500; ++trial) {
      const MovedView moved(b, randomPose(rng, 0.7));
      for (int f = 0; f < native.view.faceCount(); ++f) {
        double lowest = INFINITY;
        for (const Vector3d& v : moved.vertices) lowest = std::min(lowest, native.view.normals[f].dot(v));
        CHECK(narrow::faceSeparation(native.view, f, moved.view) ==
              Approx(lowest - native.view.offsets[f]).margin(1e-12 * 1.2));
      }
    }
  }
}
