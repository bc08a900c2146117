#include "dynamics/contact_jacobian.h"

#include <cmath>

#include "dynamics/joints/joint_mobility.h"
#include "dynamics/joints/joint_projection.h"

namespace tumble {

namespace {
// Whether a JointsHoldImpulses scope is open on this thread.
thread_local bool joints_hold = false;
}  // namespace

ContactRow rowAlong(const World& world, const Contact& c, const Eigen::Vector3d& dir) {
  ContactRow row;
  row.a = c.a;
  row.b = c.b;
  row.dir = dir;
  row.ra = c.point - world.bodies[c.a].x;
  row.rb = c.point - world.bodies[c.b].x;
  row.ca = row.ra - c.radius_a * c.normal;   // A's core lies behind its surface, against the normal
  row.cb = row.rb + c.radius_b * c.normal;
  row.rounded_a = c.radius_a > 0;
  row.rounded_b = c.radius_b > 0;
  return row;
}

void tangentsOf(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k])) k = i;
  t1 = n.cross(Eigen::Vector3d::Unit(k)).normalized();
  t2 = n.cross(t1);
}

Eigen::Matrix3d inverseInertiaWorld(const RigidBody& body) {
  if (body.is_static) return Eigen::Matrix3d::Zero();
  if (body.isotropic()) return body.inv_inertia_body.x() * Eigen::Matrix3d::Identity();
  Eigen::Matrix3d R = body.rotation();
  return R * body.inv_inertia_body.asDiagonal() * R.transpose();
}

Eigen::Vector3d pointVelocity(const RigidBody& body, const Eigen::Vector3d& p) {
  if (body.is_static) return Eigen::Vector3d::Zero();
  return pointVelocity(body, body.angularVelocity(), p);
}

Eigen::Vector3d pointVelocity(const RigidBody& body, const Eigen::Vector3d& spin, const Eigen::Vector3d& p) {
  if (body.is_static) return Eigen::Vector3d::Zero();
  return body.velocity() + spin.cross(p - body.x);
}

double rowVelocity(const World& world, const ContactRow& row) {
  const RigidBody& A = world.bodies[row.a];
  const RigidBody& B = world.bodies[row.b];
  return row.dir.dot(pointVelocity(B, B.x + row.rb) - pointVelocity(A, A.x + row.ra));
}

namespace {

// M^-1 J_i^T restricted to one body: the linear and angular velocity change of that body per unit
// force along row i (sign +1 for B, -1 for A).
struct BodyResponse {
  int body = -1;
  Eigen::Vector3d linear = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero();
  Eigen::Vector3d arm = Eigen::Vector3d::Zero();   // r x dir (signed): J_i's angular part
};

BodyResponse responseOf(const RigidBody& body, int index, const Eigen::Matrix3d& inv_inertia,
                        const Eigen::Vector3d& r, const Eigen::Vector3d& dir, double sign) {
  BodyResponse out;
  if (body.is_static) return out;
  out.body = index;
  out.arm = sign * r.cross(dir);
  out.linear = sign * dir * body.inv_mass;
  out.angular = inv_inertia * out.arm;
  return out;
}

double dotResponse(const BodyResponse& ji, const Eigen::Vector3d& dir_j_signed, const BodyResponse& rj) {
  if (ji.body < 0 || ji.body != rj.body) return 0;
  return dir_j_signed.dot(ji.linear) + rj.arm.dot(ji.angular);
}

}  // namespace

Eigen::MatrixXd delassus(const World& world, const std::vector<ContactRow>& rows) {
  Eigen::MatrixXd A;
  delassus(world, rows, A);
  return A;
}

void delassus(const World& world, const std::vector<ContactRow>& rows, Eigen::MatrixXd& A) {
  const int n = static_cast<int>(rows.size());
  // Per row, not per body of the world: an island of a few contacts in a pile of thousands.
  thread_local std::vector<BodyResponse> ra, rb;
  ra.resize(n);
  rb.resize(n);
  for (int i = 0; i < n; ++i) {
    const ContactRow& r = rows[i];
    const RigidBody &A_body = world.bodies[r.a], &B_body = world.bodies[r.b];
    ra[i] = responseOf(A_body, r.a, inverseInertiaWorld(A_body), r.ra, r.dir, -1);
    rb[i] = responseOf(B_body, r.b, inverseInertiaWorld(B_body), r.rb, r.dir, +1);
  }
  A.setZero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) {
      // A_ij = sum over bodies in both rows of J_i(body) M^-1 J_j(body)^T
      double v = 0;
      for (const BodyResponse* bi : {&ra[i], &rb[i]})
        for (const BodyResponse* bj : {&ra[j], &rb[j]}) {
          double sign_j = bj == &ra[j] ? -1 : 1;
          v += dotResponse(*bi, sign_j * rows[j].dir, *bj);
        }
      A(i, j) = A(j, i) = v;
    }
  }
  if (joints_hold && !world.joints.empty()) A = constrainedDelassus(world, rows, A);
}

void applyAlongRows(World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> f) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ContactRow& r = rows[i];
    Eigen::Vector3d push = f[i] * r.dir;
    RigidBody& A = world.bodies[r.a];
    RigidBody& B = world.bodies[r.b];
    if (!A.is_static) {
      A.P -= push;
      A.L -= r.ra.cross(push);
    }
    if (!B.is_static) {
      B.P += push;
      B.L += r.rb.cross(push);
    }
  }
  if (joints_hold && !world.joints.empty()) removeJointVelocityError(world);
}

JointsHoldImpulses::JointsHoldImpulses(bool on) : previous_(joints_hold) { joints_hold = joints_hold || on; }
JointsHoldImpulses::~JointsHoldImpulses() { joints_hold = previous_; }

}  // namespace tumble
