#include "dynamics/joints/joint_rows.h"

#include <cmath>

#include "dynamics/contact_jacobian.h"
#include "dynamics/lcp/dantzig_solver.h"

namespace tumble {
namespace {

// The world axes, so that a ball's rows need no frame of their own (deterministic, and the rows of
// one joint are orthogonal).
const Eigen::Vector3d kAxes[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};

JointRow rowOf(const Joint& j, int index) {
  JointRow r;
  r.a = j.a;
  r.b = j.b;
  r.joint = index;
  return r;
}

// 3 rows holding the anchors together: C = e . (p_b - p_a), p = x + R r; the bias is the
// centripetal acceleration of the anchor points, w x (w x r), along e.
void addPointRows(const Joint& j, int index, const JointSide& sa, const JointSide& sb, std::vector<JointRow>& rows) {
  const Eigen::Vector3d ra = sa.R * j.anchor_a, rb = sb.R * j.anchor_b;
  const Eigen::Vector3d gap = (sb.x + rb) - (sa.x + ra);
  const Eigen::Vector3d centripetal = sb.w.cross(sb.w.cross(rb)) - sa.w.cross(sa.w.cross(ra));
  for (const Eigen::Vector3d& e : kAxes) {
    JointRow r = rowOf(j, index);
    r.lin_a = -e;
    r.ang_a = -ra.cross(e);
    r.lin_b = e;
    r.ang_b = rb.cross(e);
    r.error = e.dot(gap);
    r.bias = e.dot(centripetal);
    rows.push_back(r);
  }
}

// An angular row along the world direction n: J v = n . (w_b - w_a). For an n carried by body a
// (a hinge's cross directions) its rate adds (w_a x n) . (w_b - w_a) to the acceleration.
JointRow angularRow(const Joint& j, int index, const Eigen::Vector3d& n, const JointSide& sa,
                    const JointSide& sb, bool carried_by_a) {
  JointRow r = rowOf(j, index);
  r.ang_a = -n;
  r.ang_b = n;
  if (carried_by_a) r.bias = sa.w.cross(n).dot(sb.w - sa.w);
  return r;
}

void addHingeRows(const World& world, const Joint& j, int index, const JointSide& sa, const JointSide& sb,
                  const RowChoice& choice, std::vector<JointRow>& rows) {
  const Eigen::Vector3d axis_a = sa.R * j.axis_a, axis_b = sb.R * j.axis_b;
  if (choice.equality) {
    addPointRows(j, index, sa, sb, rows);
    // Across the axis: the axes' misalignment a x b (the small turn that would bring b's axis onto
    // a's, to first order) along each direction across a's axis.
    const Eigen::Vector3d n1 = sa.R * j.cross_a, n2 = axis_a.cross(n1);
    for (const Eigen::Vector3d& n : {n1, n2}) {
      JointRow r = angularRow(j, index, n, sa, sb, true);
      r.error = n.dot(axis_a.cross(axis_b));
      rows.push_back(r);
    }
  }
  if (choice.limits && j.limited) {
    const double theta = hingeAngle(world, j);
    // Lower: C = theta - lo >= 0, J = +axis; upper: C = hi - theta >= 0, J = -axis. A force f >= 0
    // along either turns the hinge back inside.
    for (double sign : {1.0, -1.0}) {
      const double c = sign > 0 ? theta - j.lower_rad : j.upper_rad - theta;
      if (c > choice.limit_slop) continue;
      JointRow r = angularRow(j, index, sign * axis_a, sa, sb, true);
      r.kind = JointRow::Kind::Limit;
      r.error = c;
      r.lo = 0;
      rows.push_back(r);
    }
  }
  if (choice.motors && j.motor.kind == JointMotor::Kind::Velocity) {
    JointRow r = angularRow(j, index, axis_a, sa, sb, true);
    r.kind = JointRow::Kind::Motor;
    r.target_velocity = j.motor.target_velocity_rad_s;
    r.hi = j.motor.max_torque_n_m * choice.motor_torque_scale;
    r.lo = -r.hi;
    rows.push_back(r);
  }
}

// The relative orientation's error as a world rotation vector: the turn from where b should be
// (q_a times the kept relative orientation) to where it is.
Eigen::Vector3d orientationError(const World& world, const Joint& j) {
  const Eigen::Quaterniond qa = j.a < 0 ? Eigen::Quaterniond::Identity() : world.bodies[j.a].q;
  const Eigen::Quaterniond qb = j.b < 0 ? Eigen::Quaterniond::Identity() : world.bodies[j.b].q;
  Eigen::Quaterniond e = qb * (qa * j.relative).conjugate();
  if (e.w() < 0) e.coeffs() = -e.coeffs();
  const double s = e.vec().norm();
  if (s < 1e-300) return Eigen::Vector3d::Zero();
  return (2 * std::atan2(s, e.w()) / s) * e.vec();
}

}  // namespace

void buildJointRows(const World& world, const RowChoice& choice, std::vector<JointRow>& rows) {
  rows.clear();
  for (std::size_t k = 0; k < world.joints.size(); ++k) {
    const Joint& j = world.joints[k];
    const int index = static_cast<int>(k);
    const JointSide sa = jointSide(world, j.a), sb = jointSide(world, j.b);
    if (!sa.moves() && !sb.moves()) continue;   // nothing to hold
    switch (j.type) {
      case JointType::Ball:
        if (choice.equality) addPointRows(j, index, sa, sb, rows);
        break;
      case JointType::Hinge: addHingeRows(world, j, index, sa, sb, choice, rows); break;
      case JointType::Fixed:
        if (choice.equality) {
          addPointRows(j, index, sa, sb, rows);
          const Eigen::Vector3d error = orientationError(world, j);
          for (const Eigen::Vector3d& e : kAxes) {
            JointRow r = angularRow(j, index, e, sa, sb, false);
            r.error = e.dot(error);
            rows.push_back(r);
          }
        }
        break;
    }
  }
}

double jointRowVelocity(const World& world, const JointRow& row) {
  const JointSide sa = jointSide(world, row.a), sb = jointSide(world, row.b);
  return row.lin_a.dot(sa.v) + row.ang_a.dot(sa.w) + row.lin_b.dot(sb.v) + row.ang_b.dot(sb.w);
}

Eigen::MatrixXd jointDelassus(const World& world, const std::vector<JointRow>& rows) {
  const int n = static_cast<int>(rows.size());
  // M^-1 J^T per row and side: the velocity change a unit impulse along the row gives each body.
  std::vector<Eigen::Vector3d> la(n), aa(n), lb(n), ab(n);
  std::vector<Eigen::Matrix3d> inv_inertia(world.bodies.size());
  std::vector<char> known(world.bodies.size(), 0);
  auto invInertia = [&](int body) -> const Eigen::Matrix3d& {
    if (!known[body]) {
      inv_inertia[body] = inverseInertiaWorld(world.bodies[body]);
      known[body] = 1;
    }
    return inv_inertia[body];
  };
  auto moving = [&](int body) { return body >= 0 && !world.bodies[body].is_static; };
  for (int i = 0; i < n; ++i) {
    const JointRow& r = rows[i];
    la[i] = aa[i] = lb[i] = ab[i] = Eigen::Vector3d::Zero();
    if (moving(r.a)) {
      la[i] = world.bodies[r.a].inv_mass * r.lin_a;
      aa[i] = invInertia(r.a) * r.ang_a;
    }
    if (moving(r.b)) {
      lb[i] = world.bodies[r.b].inv_mass * r.lin_b;
      ab[i] = invInertia(r.b) * r.ang_b;
    }
  }
  // Row i's velocity change from a unit impulse on row k, on the bodies the two share.
  auto effect = [&](const JointRow& ri, int k) {
    const JointRow& rk = rows[k];
    double s = 0;
    if (ri.a >= 0 && ri.a == rk.a) s += ri.lin_a.dot(la[k]) + ri.ang_a.dot(aa[k]);
    if (ri.a >= 0 && ri.a == rk.b) s += ri.lin_a.dot(lb[k]) + ri.ang_a.dot(ab[k]);
    if (ri.b >= 0 && ri.b == rk.a) s += ri.lin_b.dot(la[k]) + ri.ang_b.dot(aa[k]);
    if (ri.b >= 0 && ri.b == rk.b) s += ri.lin_b.dot(lb[k]) + ri.ang_b.dot(ab[k]);
    return s;
  };
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= i; ++k) A(i, k) = A(k, i) = effect(rows[i], k);
  return A;
}

Eigen::VectorXd solveJointRows(const std::vector<JointRow>& rows, const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const int n = static_cast<int>(rows.size());
  if (n == 0) return Eigen::VectorXd();
  lcp::LcpProblem p;
  p.A = A;
  p.b = b;
  p.lo.resize(n);
  p.hi.resize(n);
  for (int i = 0; i < n; ++i) {
    p.lo[i] = rows[i].lo;
    p.hi[i] = rows[i].hi;
  }
  lcp::LcpResult r = lcp::solveDantzig(p);
  // A failed solve (inconsistent rows: a closed loop whose joints disagree) takes no force rather
  // than a wrong one; the projection then keeps the joints together.
  if (r.status == lcp::LcpStatus::Failed || !r.f.allFinite()) return Eigen::VectorXd::Zero(n);
  return r.f;
}

void applyJointImpulses(World& world, const std::vector<JointRow>& rows, const Eigen::VectorXd& p) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const JointRow& r = rows[i];
    if (r.a >= 0 && !world.bodies[r.a].is_static) {
      world.bodies[r.a].P += p[i] * r.lin_a;
      world.bodies[r.a].L += p[i] * r.ang_a;
    }
    if (r.b >= 0 && !world.bodies[r.b].is_static) {
      world.bodies[r.b].P += p[i] * r.lin_b;
      world.bodies[r.b].L += p[i] * r.ang_b;
    }
  }
}

}  // namespace tumble
