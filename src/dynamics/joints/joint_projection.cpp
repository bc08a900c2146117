#include "dynamics/joints/joint_projection.h"

#include <cmath>
#include <vector>

#include "dynamics/contact_jacobian.h"
#include "dynamics/integrator.h"
#include "dynamics/joints/joint_rows.h"

namespace tumble {
namespace {

// Moves each body by M^-1 J^T d: x by lin d / m, the orientation by the rotation vector I^-1 ang d.
// Momenta are kept (P and L), so only positions change.
void displace(World& world, const std::vector<JointRow>& rows, const Eigen::VectorXd& d) {
  const std::size_t n = world.bodies.size();
  std::vector<Eigen::Vector3d> lin(n, Eigen::Vector3d::Zero()), ang(n, Eigen::Vector3d::Zero());
  std::vector<char> moved(n, 0);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const JointRow& r = rows[i];
    if (r.a >= 0) {
      lin[r.a] += d[i] * r.lin_a;
      ang[r.a] += d[i] * r.ang_a;
      moved[r.a] = 1;
    }
    if (r.b >= 0) {
      lin[r.b] += d[i] * r.lin_b;
      ang[r.b] += d[i] * r.ang_b;
      moved[r.b] = 1;
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    RigidBody& body = world.bodies[k];
    if (!moved[k] || body.is_static) continue;
    body.x += body.inv_mass * lin[k];
    body.q = (rotationOver(inverseInertiaWorld(body) * ang[k], 1.0) * body.q).normalized();
  }
}

}  // namespace

namespace {

// Gravitational potential energy of the moving bodies (J, zero at the origin).
double potentialEnergy(const World& world) {
  double e = 0;
  for (const RigidBody& body : world.bodies)
    if (!body.is_static) e -= body.mass * world.gravity.dot(body.x);
  return e;
}

// A projection that lifts bodies (a joint pulled apart by a contact's correction, put back higher)
// pays for the lift from the joined bodies' kinetic energy: their momenta scaled down by one
// factor, as the contacts' correction pays for its lifts (baraff/drift_correction.h). A projection
// never adds energy.
void payForLift(World& world, double lift) {
  if (!(lift > 0)) return;
  double kinetic = 0;
  std::vector<char> joined(world.bodies.size(), 0);
  for (const Joint& j : world.joints)
    for (int k : {j.a, j.b})
      if (k >= 0 && !world.bodies[k].is_static && !joined[k]) {
        joined[k] = 1;
        kinetic += world.bodies[k].kineticEnergy();
      }
  const double scale = kinetic > lift ? std::sqrt((kinetic - lift) / kinetic) : 0.0;
  for (std::size_t k = 0; k < world.bodies.size(); ++k)
    if (joined[k]) {
      world.bodies[k].P *= scale;
      world.bodies[k].L *= scale;
    }
}

}  // namespace

JointProjection projectJointPositions(World& world, double tolerance, int max_passes) {
  JointProjection out;
  const double start_potential = potentialEnergy(world);
  std::vector<JointRow> rows;
  RowChoice choice;
  choice.limit_slop = 0;   // only hinges past a limit
  for (; out.passes < max_passes; ++out.passes) {
    buildJointRows(world, choice, rows);
    const int n = static_cast<int>(rows.size());
    Eigen::VectorXd c(n);
    out.largest_error = 0;
    for (int i = 0; i < n; ++i) {
      c[i] = rows[i].error;
      const double off = rows[i].kind == JointRow::Kind::Limit ? std::max(0.0, -c[i]) : std::abs(c[i]);
      out.largest_error = std::max(out.largest_error, off);
    }
    if (!(out.largest_error > tolerance)) break;
    // J M^-1 J^T d + C = 0 on equality rows; on limit rows C + (J M^-1 J^T d) >= 0 with d >= 0.
    displace(world, rows, solveJointRows(rows, jointDelassus(world, rows), c));
  }
  if (out.passes > 0) payForLift(world, potentialEnergy(world) - start_potential);
  return out;
}

void removeJointVelocityError(World& world) {
  std::vector<JointRow> rows;
  buildJointRows(world, RowChoice{}, rows);
  const int n = static_cast<int>(rows.size());
  if (n == 0) return;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = jointRowVelocity(world, rows[i]);
  applyJointImpulses(world, rows, solveJointRows(rows, jointDelassus(world, rows), v));
}

}  // namespace tumble
