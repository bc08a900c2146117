// A joint between two bodies, or between a body and the world: the bilateral constraints A q̇ = 0
// that hold two material points together (ball), and also keep an axis in line (hinge) or the
// whole relative orientation (fixed). Anchors and axes are kept in each body's own frame (origin
// at its centre of mass, principal axes), so they move with the bodies; the world side of a joint
// to the world is kept in world coordinates.
//
// How the models treat joints: joint_rows.h (the rows), joint_forces.h (the constraint forces at
// the acceleration level, evaluated at every stage of the integrator: joint_integrator.h),
// contact_joint_lcp.h (joint rows solved with contact rows: the Baraff model's resting islands,
// the time-stepping model's impulses, joint_impulses.h), joint_mobility.h (impacts on joined
// bodies) and joint_projection.h (drift correction that adds no energy).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace tumble {

struct RigidBody;
struct World;

enum class JointType { Ball, Hinge, Fixed };

// A hinge's motor (the robot-control lecture's controllers):
//   Position  PD control: tau = kp (target - theta) - kd theta_dot about the axis, applied as a
//             pair of opposite torques (pd_motor.h)
//   Velocity  a row asking for the relative angular velocity `target_velocity_rad_s` about the
//             axis, its torque bounded by max_torque_n_m
struct JointMotor {
  enum class Kind { None, Position, Velocity };
  Kind kind = Kind::None;
  double target_rad = 0, kp = 0, kd = 0;                           // N m/rad, N m s/rad
  double target_velocity_rad_s = 0, max_torque_n_m = 0;
};

struct Joint {
  std::string name;
  JointType type = JointType::Ball;
  int a = -1, b = -1;                                               // body indices; -1: the world
  Eigen::Vector3d anchor_a = Eigen::Vector3d::Zero(), anchor_b = Eigen::Vector3d::Zero();
  // Hinge: the axis, and a unit vector across it; both bodies' cross vectors agree in the world at
  // the start, so the hinge angle is zero there and grows with b turning about the axis relative
  // to a (right-handed).
  Eigen::Vector3d axis_a = Eigen::Vector3d::UnitZ(), axis_b = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d cross_a = Eigen::Vector3d::UnitX(), cross_b = Eigen::Vector3d::UnitX();
  // Fixed: the relative orientation q_a^-1 q_b the joint keeps (the one at the start).
  Eigen::Quaterniond relative = Eigen::Quaterniond::Identity();
  bool limited = false;
  double lower_rad = 0, upper_rad = 0;
  JointMotor motor;
};

// A joint of `type` between bodies a and b (-1: the world) at the world point `anchor` with the
// world axis `axis` (unit; hinges only), made from the bodies' present poses.
Joint makeJoint(const World& world, JointType type, int a, int b, const Eigen::Vector3d& anchor,
                const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ());

// The world-frame view of one side of a joint (the world: identity pose, at rest).
struct JointSide {
  const RigidBody* body = nullptr;                                  // null: the world
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  bool moves() const;                                               // a body that is not static
};
JointSide jointSide(const World& world, int body);

// The hinge angle (rad, in (-pi, pi]) and its rate (rad/s): b's turn about the axis relative to a.
double hingeAngle(const World& world, const Joint& j);
double hingeRate(const World& world, const Joint& j);

// The distance between the two anchor points (m): what a ball, hinge or fixed joint holds at zero.
double anchorGap(const World& world, const Joint& j);

// Whether a joint has a motor, which does work: a scene with one is not passive (fault_check.h).
bool hasMotors(const std::vector<Joint>& joints);

}  // namespace tumble
