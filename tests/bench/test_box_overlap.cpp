#include <catch2/catch.hpp>
#include <cmath>

#include "bench/box_overlap.h"

using tumble::bench::BoxPose;
using tumble::bench::boxOverlap;
using tumble::bench::groundDepth;

namespace {

BoxPose cube(const Eigen::Vector3d& x, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  return {Eigen::Vector3d::Constant(0.5), x, R};
}

Eigen::Matrix3d aboutZ(double rad) { return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

}  // namespace

TEST_CASE("box overlap is the smallest projection overlap of two boxes") {
  CHECK(boxOverlap(cube({0, 0, 0}), cube({0.9, 0, 0})) == Approx(0.1));
  CHECK(boxOverlap(cube({0, 0, 0}), cube({0.9, 0.95, 0})) == Approx(0.05));
  CHECK(boxOverlap(cube({0, 0, 0}), cube({1.0001, 0, 0})) == 0);
  // A cube turned 45 degrees reaches sqrt(1/2) along x: its corner enters the other by 0.2071.
  CHECK(boxOverlap(cube({0, 0, 0}), cube({1.0, 0, 0}, aboutZ(M_PI / 4))) == Approx(std::sqrt(0.5) - 0.5));
  // Touching stacked cubes do not overlap.
  CHECK(boxOverlap(cube({0, 0, 0.5}), cube({0, 0, 1.5})) == Approx(0).margin(1e-15));
}

TEST_CASE("ground depth is how far the lowest corner is below z = 0") {
  CHECK(groundDepth(cube({0, 0, 0.5})) == 0);
  CHECK(groundDepth(cube({0, 0, 0.49})) == Approx(0.01));
  const Eigen::Matrix3d tilted = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  CHECK(groundDepth(cube({0, 0, 0.7}, tilted)) == Approx(std::sqrt(0.5) - 0.7));
}
