// principalFrame: proper rotation, ascending moments, and one answer per tensor.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <random>

#include "geometry/mass_properties.h"

using namespace tumble;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

// The contract: R proper, moments ascending, R diag(m) R^T = I (1e-12 relative: the symmetric
// QR iteration is backward stable to a few ulps of the largest moment), axis signs by the rule.
void checkFrame(const Matrix3d& inertia, const PrincipalFrame& f) {
  CHECK(f.rotation.determinant() == Approx(1).epsilon(1e-12));
  CHECK((f.rotation.transpose() * f.rotation - Matrix3d::Identity()).norm() <= 1e-12);
  CHECK(f.moments[0] <= f.moments[1]);
  CHECK(f.moments[1] <= f.moments[2]);
  const Matrix3d back = f.rotation * f.moments.asDiagonal() * f.rotation.transpose();
  CHECK((back - inertia).cwiseAbs().maxCoeff() <= 1e-12 * inertia.cwiseAbs().maxCoeff());
  for (int k = 0; k < 2; ++k) {
    Eigen::Index i = 0;
    f.rotation.col(k).cwiseAbs().maxCoeff(&i);
    CHECK(f.rotation(i, k) > 0);
  }
}

}  // namespace

TEST_CASE("a diagonal ascending tensor gives exactly the identity", "[frame]") {
  const Matrix3d inertia = Vector3d(1, 2, 3).asDiagonal();
  const PrincipalFrame f = principalFrame(inertia);
  CHECK(f.rotation == Matrix3d::Identity());
  CHECK(f.moments == Vector3d(1, 2, 3));
}

TEST_CASE("a cube (all moments equal) gives the identity, even with rounding noise", "[frame]") {
  Matrix3d inertia = Matrix3d::Identity() * 0.4;
  CHECK(principalFrame(inertia).rotation == Matrix3d::Identity());
  inertia(0, 1) = inertia(1, 0) = 1e-17;  // what a rotated cube's integration leaves behind
  CHECK(principalFrame(inertia).rotation == Matrix3d::Identity());
}

TEST_CASE("a diagonal tensor out of order gives a signed permutation", "[frame]") {
  const Matrix3d inertia = Vector3d(3, 1, 2).asDiagonal();
  const PrincipalFrame f = principalFrame(inertia);
  checkFrame(inertia, f);
  CHECK(f.moments == Vector3d(1, 2, 3));
  CHECK(f.rotation.cwiseAbs().sum() == 3);  // entries are 0 and +-1 only
}

TEST_CASE("random tensors: proper, ascending, reconstructing, deterministic", "[frame]") {
  std::mt19937 rng(GENERATE(1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u));
  std::uniform_real_distribution<double> u(0.1, 5);
  const Matrix3d r = randomRotation(rng);
  const Matrix3d inertia = r * Vector3d(u(rng), u(rng), u(rng)).asDiagonal() * r.transpose();
  const PrincipalFrame f = principalFrame(inertia);
  checkFrame(inertia, f);
  const PrincipalFrame again = principalFrame(inertia);
  CHECK(again.rotation == f.rotation);  // bit for bit
  CHECK(again.moments == f.moments);
}

TEST_CASE("two equal moments: the axis plane is resolved from the tensor alone", "[frame]") {
  // A square prism turned about its long axis: any basis of the square's plane is principal;
  // the frame must not depend on the turn's sign or the solver's whim.
  std::mt19937 rng(11);
  const Matrix3d turn = randomRotation(rng);
  const Matrix3d inertia = turn * Vector3d(1, 1, 2).asDiagonal() * turn.transpose();
  const PrincipalFrame f = principalFrame(inertia);
  checkFrame(inertia, f);
  CHECK(std::abs(f.rotation.col(2).dot(turn.col(2))) == Approx(1).epsilon(1e-12));
  // A low-order perturbation far below the equality tolerance gives the same frame to 1e-9.
  Matrix3d nudged = inertia;
  nudged(0, 0) += 1e-14;
  CHECK((principalFrame(nudged).rotation - f.rotation).norm() <= 1e-9);
}
