#include "dynamics/position_projection.h"

#include <Eigen/QR>
#include <cmath>

#include "dynamics/contact_rows.h"

namespace tumble {
namespace {

// Turns and moves a body by a small displacement: x += dx, q = exp(dtheta) q.
void displace(RigidBody& body, const Eigen::Vector3d& dx, const Eigen::Vector3d& dtheta) {
  body.x += dx;
  const double angle = dtheta.norm();
  if (angle > 0) body.q = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, dtheta / angle)) * body.q).normalized();
}

}  // namespace

bool projectPair(World& world, const std::vector<const Contact*>& points, double tol) {
  if (points.empty()) return false;
  RigidBody& A = world.bodies[points.front()->a];
  RigidBody& B = world.bodies[points.front()->b];
  if (A.inv_mass + B.inv_mass <= 0) return false;
  ContactRows rows;   // normal rows only
  std::vector<double> lift;
  const Contact* deepest = nullptr;
  double shallowest = INFINITY;
  for (const Contact* c : points) {
    if (c->depth < -tol) continue;   // apart: free to move
    if (!deepest || c->depth > deepest->depth) deepest = c;
    shallowest = std::min(shallowest, c->depth);
    rows.addContact(world, *c, false);
    lift.push_back(c->depth - 0.5 * tol);   // every touching point to tol/2 deep
  }
  if (!deepest || deepest->depth <= tol) return false;
  if (deepest->depth - shallowest <= 2 * tol) {
    // Flush within the tolerance (a face resting a little too deep): moved straight out by its
    // deepest point to tol/2 deep, not turned. Turning by depth differences at rounding level
    // tilted the cubes of a 1000:1 stack by 1e-7 rad, and its resting LCP, near-singular with four
    // almost coplanar points per face, answered with forces of 4000 N sideways (dt = 1/60).
    const double wa = A.inv_mass, wb = B.inv_mass, push = deepest->depth - 0.5 * tol;
    A.x -= deepest->normal * (push * wa / (wa + wb));
    B.x += deepest->normal * (push * wb / (wa + wb));
    return true;
  }
  const Eigen::MatrixXd W = delassus(world, rows.rows);
  const Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(lift.data(), static_cast<Eigen::Index>(lift.size()));
  const Eigen::VectorXd p = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(W).solve(d);
  if (!p.allFinite()) return false;
  Eigen::Vector3d fa = Eigen::Vector3d::Zero(), ta = fa, fb = fa, tb = fa;
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    const Eigen::Vector3d push = p[static_cast<Eigen::Index>(i)] * rows.rows[i].dir;
    fb += push;
    tb += rows.rows[i].rb.cross(push);
    fa -= push;
    ta -= rows.rows[i].ra.cross(push);
  }
  if (!A.is_static) displace(A, A.inv_mass * fa, inverseInertiaWorld(A) * ta);
  if (!B.is_static) displace(B, B.inv_mass * fb, inverseInertiaWorld(B) * tb);
  return true;
}

}  // namespace tumble
