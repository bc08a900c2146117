#include "dynamics/joints/joint.h"

#include <cmath>

#include "dynamics/world.h"

namespace tumble {

bool JointSide::moves() const { return body && !body->is_static; }

JointSide jointSide(const World& world, int index) {
  JointSide s;
  if (index < 0) return s;
  const RigidBody& body = world.bodies[index];
  s.body = &body;
  s.R = body.rotation();
  s.x = body.x;
  if (!body.is_static) {
    s.v = body.velocity();
    s.w = body.angularVelocity();
  }
  return s;
}

namespace {

// A unit vector across `axis`, from the world axis least in line with it (deterministic).
Eigen::Vector3d acrossOf(const Eigen::Vector3d& axis) {
  Eigen::Index least;
  axis.cwiseAbs().minCoeff(&least);
  return axis.cross(Eigen::Vector3d::Unit(least)).normalized();
}

}  // namespace

Joint makeJoint(const World& world, JointType type, int a, int b, const Eigen::Vector3d& anchor,
                const Eigen::Vector3d& axis) {
  Joint j;
  j.type = type;
  j.a = a;
  j.b = b;
  const JointSide sa = jointSide(world, a), sb = jointSide(world, b);
  const Eigen::Vector3d unit = axis.normalized(), across = acrossOf(unit);
  j.anchor_a = sa.R.transpose() * (anchor - sa.x);
  j.anchor_b = sb.R.transpose() * (anchor - sb.x);
  j.axis_a = sa.R.transpose() * unit;
  j.axis_b = sb.R.transpose() * unit;
  j.cross_a = sa.R.transpose() * across;
  j.cross_b = sb.R.transpose() * across;
  const Eigen::Quaterniond qa = a < 0 ? Eigen::Quaterniond::Identity() : world.bodies[a].q;
  const Eigen::Quaterniond qb = b < 0 ? Eigen::Quaterniond::Identity() : world.bodies[b].q;
  j.relative = (qa.conjugate() * qb).normalized();
  return j;
}

double hingeAngle(const World& world, const Joint& j) {
  const JointSide sa = jointSide(world, j.a), sb = jointSide(world, j.b);
  const Eigen::Vector3d axis = sa.R * j.axis_a, ca = sa.R * j.cross_a, cb = sb.R * j.cross_b;
  return std::atan2(axis.dot(ca.cross(cb)), ca.dot(cb));
}

double hingeRate(const World& world, const Joint& j) {
  const JointSide sa = jointSide(world, j.a), sb = jointSide(world, j.b);
  return (sa.R * j.axis_a).dot(sb.w - sa.w);
}

double anchorGap(const World& world, const Joint& j) {
  const JointSide sa = jointSide(world, j.a), sb = jointSide(world, j.b);
  return ((sb.x + sb.R * j.anchor_b) - (sa.x + sa.R * j.anchor_a)).norm();
}

bool hasMotors(const std::vector<Joint>& joints) {
  for (const Joint& j : joints)
    if (j.motor.kind != JointMotor::Kind::None) return true;
  return false;
}

}  // namespace tumble
