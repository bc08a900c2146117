#include "dynamics/position_projection.h"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <cmath>
#include <optional>

#include "dynamics/contact_rows.h"

namespace tumble {
namespace {

// Moves the pair straight out along the deepest point's normal, in inverse proportion to mass,
// until that point is tol/2 deep; never turns them.
void pushOut(RigidBody& A, RigidBody& B, const Contact& deepest, double tol) {
  const double wa = A.inv_mass, wb = B.inv_mass, push = deepest.depth - 0.5 * tol;
  A.x -= deepest.normal * (push * wa / (wa + wb));
  B.x += deepest.normal * (push * wb / (wa + wb));
}

// Whether moving a body by dx and turning it by dtheta moves its points farther than lifting one
// of its points by `lift` needs: a turn about an axis at least half its thinnest piece from that
// point moves no point by more than lift (r / (thinnest / 2) + 1), r the body's radius.
bool reachesTooFar(const RigidBody& body, const BodyExtent& extent, const Eigen::Vector3d& dx,
                   const Eigen::Vector3d& dtheta, double lift) {
  if (body.is_static) return false;
  const double r = extent.radius;
  return dx.norm() + dtheta.norm() * r > lift * (r / (0.5 * extent.thinnest) + 1);
}

struct Displacement {
  Eigen::Vector3d dx_a, dtheta_a, dx_b, dtheta_b;
};

// The least-norm displacement (weighted by mass and inertia) that moves each row's point by its
// lift along the row: M^-1 J^T p with p the least-squares, least-norm solution of J M^-1 J^T p = lift.
std::optional<Displacement> leastNormDisplacement(const World& world, const RigidBody& A, const RigidBody& B,
                                                  const ContactRows& rows, const std::vector<double>& lift) {
  const Eigen::MatrixXd W = delassus(world, rows.rows);
  const Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(lift.data(), static_cast<Eigen::Index>(lift.size()));
  const Eigen::VectorXd p = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(W).solve(d);
  if (!p.allFinite()) return std::nullopt;
  Eigen::Vector3d fa = Eigen::Vector3d::Zero(), ta = fa, fb = fa, tb = fa;
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    const Eigen::Vector3d push = p[static_cast<Eigen::Index>(i)] * rows.rows[i].dir;
    fb += push;
    tb += rows.rows[i].rb.cross(push);
    fa -= push;
    ta -= rows.rows[i].ra.cross(push);
  }
  return Displacement{A.inv_mass * fa, inverseInertiaWorld(A) * ta, B.inv_mass * fb, inverseInertiaWorld(B) * tb};
}

}  // namespace

bool projectPair(World& world, const std::vector<const Contact*>& points, double tol,
                 const std::vector<BodyExtent>& extents) {
  if (points.empty()) return false;
  RigidBody& A = world.bodies[points.front()->a];
  RigidBody& B = world.bodies[points.front()->b];
  const BodyExtent &extent_a = extents[points.front()->a], &extent_b = extents[points.front()->b];
  if (A.inv_mass + B.inv_mass <= 0) return false;
  ContactRows rows, deep_rows;   // normal rows only: of every touching point; of the too-deep ones
  std::vector<double> lift, deep_lift;
  const Contact* deepest = nullptr;
  double shallowest = INFINITY;
  for (const Contact* c : points) {
    if (c->depth < -tol) continue;   // apart: free to move
    if (!deepest || c->depth > deepest->depth) deepest = c;
    shallowest = std::min(shallowest, c->depth);
    rows.addContact(world, *c, false);
    lift.push_back(c->depth - 0.5 * tol);   // every touching point to tol/2 deep
    if (c->depth <= tol) continue;
    deep_rows.addContact(world, *c, false);
    deep_lift.push_back(c->depth - 0.5 * tol);
  }
  if (!deepest || deepest->depth <= tol) return false;
  if (deepest->depth - shallowest <= 2 * tol) {
    // Flush within the tolerance (a face resting a little too deep): moved straight out by its
    // deepest point to tol/2 deep, not turned. Turning by depth differences at rounding level
    // tilted the cubes of a 1000:1 stack by 1e-7 rad, and its resting LCP, near-singular with four
    // almost coplanar points per face, answered with forces of 4000 N sideways (dt = 1/60).
    pushOut(A, B, *deepest, tol);
    return true;
  }
  // Nearly dependent rows with targets that disagree (two touching points close together, one to
  // be lifted, the other held at tol/2) make the least-norm displacement large: a 1.4 um lift of a
  // spike's corner turned it 9 mm into the ground. Such a displacement is no correction: then only
  // the too-deep points are lifted (the others left free), and failing that the pair is pushed
  // straight out.
  const double deepest_lift = deepest->depth - 0.5 * tol;
  auto proportionate = [&](const Displacement& m) {
    return !reachesTooFar(A, extent_a, m.dx_a, m.dtheta_a, deepest_lift) &&
           !reachesTooFar(B, extent_b, m.dx_b, m.dtheta_b, deepest_lift);
  };
  std::optional<Displacement> move = leastNormDisplacement(world, A, B, rows, lift);
  if (!move) return false;
  if (!proportionate(*move)) move = leastNormDisplacement(world, A, B, deep_rows, deep_lift);
  if (!move || !proportionate(*move)) {
    pushOut(A, B, *deepest, tol);
    return true;
  }
  if (!A.is_static) displaceBody(A, move->dx_a, move->dtheta_a);
  if (!B.is_static) displaceBody(B, move->dx_b, move->dtheta_b);
  return true;
}

void displaceBody(RigidBody& body, const Eigen::Vector3d& dx, const Eigen::Vector3d& dtheta) {
  body.x += dx;
  const double angle = dtheta.norm();
  if (angle > 0) body.q = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, dtheta / angle)) * body.q).normalized();
}

}  // namespace tumble
