// Test helper: LCP matrices of resting contacts from real contact Jacobians (the A and b of
// D. Baraff, "Fast contact force computation for nonpenetrating rigid bodies", SIGGRAPH 1994).
// A contact row with direction d (a normal, or a tangent for friction) at world point p
// acting on body a (and with the opposite sign on body b) is, per body, [dᵀ, ((p − x)×d)ᵀ]: the
// rate of the separation along d from the body's linear and angular acceleration. Then
//   A = J M⁻¹ Jᵀ,   b = J M⁻¹ F_ext   (+ velocity terms, zero for bodies at rest).
#pragma once

#include "dynamics/lcp/lcp_problem.h"

#include <vector>

namespace tumble::lcp::test {

struct Body {
  double mass = 1;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity() / 6;  // world frame, about the COM
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
};

struct ContactRow {
  int a = 0;        // body pushed along +dir
  int b = -1;       // body pushed along −dir, or −1 for the static ground
  Eigen::Vector3d point, dir;
  int friction_of = -1;  // row index of the normal this friction row belongs to
  double mu = 0;
};

struct ContactSystem {
  std::vector<Body> bodies;
  std::vector<ContactRow> rows;
  Eigen::Vector3d gravity{0, 0, -9.81};

  Eigen::MatrixXd jacobian() const;       // rows × 6·bodies
  Eigen::MatrixXd inverseMass() const;    // 6·bodies square, block diagonal
  Eigen::VectorXd externalForce() const;  // gravity on every body, no torque
  LcpProblem problem() const;             // normal rows: f ≥ 0; friction rows: ±mu f_n
  // Generalised accelerations (linear, angular per body) under the contact forces f.
  Eigen::VectorXd accelerations(const Eigen::VectorXd& f) const;
};

// Corners of the face z = zFace of a box with half extents (hx, hy) centred at (cx, cy).
std::vector<Eigen::Vector3d> rectangleCorners(double cx, double cy, double hx, double hy, double zFace);

// Adds a normal row (+z) at each point between body a and body b (−1: ground); returns the first row.
int addNormalContacts(ContactSystem& s, int a, int b, const std::vector<Eigen::Vector3d>& points);

// Two signed friction rows (x, then y) per existing normal row, after all normals: the box-shaped
// friction pyramid |f_x| ≤ mu f_n, |f_y| ≤ mu f_n.
void addFrictionRows(ContactSystem& s, double mu);

// A stack of n unit cubes (mass 1, inertia 1/6) on the ground: 4 corner contacts per interface.
ContactSystem cubeStack(int n, bool friction, double mu = 0.5);

}  // namespace tumble::lcp::test
