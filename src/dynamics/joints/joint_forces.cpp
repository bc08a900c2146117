#include "dynamics/joints/joint_forces.h"

#include "dynamics/contact_jacobian.h"
#include "dynamics/joints/joint_rows.h"
#include "dynamics/joints/pd_motor.h"

namespace tumble {

namespace {
// rad/s: a limit whose hinge turns away from it faster than this is leaving it and takes no force
// (a force would hold it back from leaving).
constexpr double kLeavingRate = 1e-9;
}  // namespace

void jointAccelerationRows(const World& world, const std::vector<Wrench>& applied, double dt, bool motors,
                           std::vector<JointRow>& rows, Eigen::VectorXd& b, JointHold hold) {
  RowChoice choice;
  choice.motors = motors;
  buildJointRows(world, choice, rows);
  std::erase_if(rows, [&](const JointRow& r) {
    return r.kind == JointRow::Kind::Limit && jointRowVelocity(world, r) > kLeavingRate;
  });
  // Each body's acceleration under the applied wrenches alone: F / m, and I^-1 (tau - w x L)
  // (d/dt of w = I^-1 L in world axes, with I turning with the body).
  const std::size_t bodies = world.bodies.size();
  thread_local std::vector<Eigen::Vector3d> lin, ang;
  lin.assign(bodies, Eigen::Vector3d::Zero());
  ang.assign(bodies, Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < bodies; ++i) {
    const RigidBody& body = world.bodies[i];
    if (body.is_static) continue;
    lin[i] = body.inv_mass * applied[i].force;
    ang[i] = inverseInertiaWorld(body) * (applied[i].torque - body.angularVelocity().cross(body.L));
  }
  const int n = static_cast<int>(rows.size());
  b.resize(n);
  for (int i = 0; i < n; ++i) {
    const JointRow& r = rows[i];
    // A velocity motor's row has its own target (below); the others hold J a + J' v = 0, or bring
    // the row's velocity to zero within the step.
    double acc = hold == JointHold::Velocity && r.kind != JointRow::Kind::Motor ? jointRowVelocity(world, r) / dt : r.bias;
    if (r.a >= 0) acc += r.lin_a.dot(lin[r.a]) + r.ang_a.dot(ang[r.a]);
    if (r.b >= 0) acc += r.lin_b.dot(lin[r.b]) + r.ang_b.dot(ang[r.b]);
    if (r.kind == JointRow::Kind::Motor) acc -= (r.target_velocity - jointRowVelocity(world, r)) / dt;
    b[i] = acc;
  }
}

void addJointForces(const World& world, std::vector<Wrench>& wrenches, double dt, bool velocity_motors,
                    JointHold hold) {
  addMotorTorques(world, wrenches);
  thread_local std::vector<JointRow> rows;
  thread_local Eigen::VectorXd b;
  jointAccelerationRows(world, wrenches, dt, velocity_motors, rows, b, hold);
  if (rows.empty()) return;
  const Eigen::VectorXd f = solveJointRows(rows, jointDelassus(world, rows), b);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const JointRow& r = rows[i];
    if (r.a >= 0 && !world.bodies[r.a].is_static) {
      wrenches[r.a].force += f[i] * r.lin_a;
      wrenches[r.a].torque += f[i] * r.ang_a;
    }
    if (r.b >= 0 && !world.bodies[r.b].is_static) {
      wrenches[r.b].force += f[i] * r.lin_b;
      wrenches[r.b].torque += f[i] * r.ang_b;
    }
  }
}

}  // namespace tumble
