// The principal frame of an inertia tensor, made unique: the same tensor always gives the same
// rotation, bit for bit, and a tensor that is already diagonal gives the axes it came with.
#include <Eigen/Geometry>  // cross products
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/mass_properties.h"

namespace tumble {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Off-diagonal terms below this fraction of the largest entry are rounding: a box modelled along
// the axes gives products of inertia of ~1e-17 of its moments, and must keep its axes.
constexpr double kDiagonalTol = 1e-12;
// Moments closer than this fraction are equal: their eigenvectors are then only defined as a
// plane, and the solver's choice within it would flip with the last bits of the input. A gap of
// 1e-9 makes the axes precess at 1e-9 of the spin rate, invisible in any animation.
constexpr double kEqualMomentTol = 1e-9;

// Each of the first two axes points along the positive side of its largest component; the third
// is their cross product, so the frame is always a proper rotation.
void fixSigns(Matrix3d& r) {
  for (int k = 0; k < 2; ++k) {
    Eigen::Index largest = 0;
    r.col(k).cwiseAbs().maxCoeff(&largest);
    if (r(largest, k) < 0) r.col(k) = -r.col(k);
  }
  r.col(2) = r.col(0).cross(r.col(1));
}

// A diagonal tensor: the axes are the coordinate axes, sorted by moment (stable, so equal moments
// keep their x, y, z order and a cube gives the identity).
PrincipalFrame diagonalFrame(const Matrix3d& inertia) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return inertia(a, a) < inertia(b, b); });
  PrincipalFrame frame;
  for (int k = 0; k < 3; ++k) {
    frame.rotation.col(k) = Vector3d::Unit(order[k]);
    frame.moments[k] = inertia(order[k], order[k]);
  }
  fixSigns(frame.rotation);
  return frame;
}

// Fills columns `a` and `b` with a basis of the plane normal to `unique`, starting from the
// coordinate axis most normal to it: a choice that depends on the tensor, not on the solver.
void planeBasis(Matrix3d& r, int unique, int a, int b) {
  const Vector3d u = r.col(unique);
  Eigen::Index k = 0;
  u.cwiseAbs().minCoeff(&k);
  const Vector3d first = (Vector3d::Unit(k) - u[k] * u).normalized();
  // Both (first, u x first, u) and (u, first, u x first) are right-handed.
  r.col(a) = first;
  r.col(b) = u.cross(first);
}

}  // namespace

PrincipalFrame principalFrame(const Eigen::Matrix3d& inertia) {
  const Matrix3d sym = 0.5 * (inertia + inertia.transpose());
  const double scale = sym.cwiseAbs().maxCoeff();
  const Matrix3d off = sym - Matrix3d(sym.diagonal().asDiagonal());
  if (scale == 0 || off.cwiseAbs().maxCoeff() <= kDiagonalTol * scale) return diagonalFrame(sym);

  Eigen::SelfAdjointEigenSolver<Matrix3d> solver(sym);  // eigenvalues ascending
  PrincipalFrame frame;
  frame.moments = solver.eigenvalues();
  frame.rotation = solver.eigenvectors();
  const Vector3d& m = frame.moments;
  const bool low_pair = m[1] - m[0] <= kEqualMomentTol * scale;
  const bool high_pair = m[2] - m[1] <= kEqualMomentTol * scale;
  if (low_pair && high_pair) {
    frame.rotation.setIdentity();  // isotropic: every frame is principal
  } else if (low_pair) {
    planeBasis(frame.rotation, 2, 0, 1);
  } else if (high_pair) {
    planeBasis(frame.rotation, 0, 1, 2);
  }
  fixSigns(frame.rotation);
  return frame;
}

}  // namespace tumble
