// The contact Jacobian J and the Delassus matrix A = J M^-1 J^T: how a unit force (or impulse)
// along one contact direction changes the relative acceleration (or velocity) along another. Both
// the impulse solve (colliding contacts) and the force solve (resting contacts) are LCPs in A
// (the impulse formula of Yang, "Rigid Bodies and Contacts", 2020; Baraff's a = A f + b, 1994).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// One row of J: a direction at a contact point. A force f along it pushes B by +f dir, A by -f dir.
struct ContactRow {
  int a = -1, b = -1;
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();
  Eigen::Vector3d ra = Eigen::Vector3d::Zero(), rb = Eigen::Vector3d::Zero();   // p - x_a, p - x_b
  // The material points whose motion the contact follows, as offsets from x_a and x_b: p itself
  // on a polyhedron; on a rounded piece (a sphere, a capsule) its core point behind p, since the
  // surface rolls over the contact (a rolling ball's lowest material point accelerates upwards,
  // its contact does not). Only accelerations differ (baraff/resting_forces.cpp).
  Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
  bool rounded_a = false, rounded_b = false;
};

ContactRow rowAlong(const World& world, const Contact& c, const Eigen::Vector3d& dir);
// Two unit tangents completing the normal to a right-handed frame, chosen from the world axis
// least aligned with n (so a horizontal contact gets the world's x and y: deterministic, and the
// friction pyramid is exact for motion along those axes).
void tangentsOf(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2);

// World-frame inverse inertia R I^-1 R^T (zero for static bodies).
Eigen::Matrix3d inverseInertiaWorld(const RigidBody& body);
// Velocity of the material point of `body` at world point p.
Eigen::Vector3d pointVelocity(const RigidBody& body, const Eigen::Vector3d& p);
// The same with the body's angular velocity given (body_extent.h, bodySpins).
Eigen::Vector3d pointVelocity(const RigidBody& body, const Eigen::Vector3d& spin, const Eigen::Vector3d& p);
// J_row v: relative velocity of B with respect to A along the row's direction.
double rowVelocity(const World& world, const ContactRow& row);

// A = J M^-1 J^T for the given rows (symmetric positive semi-definite).
Eigen::MatrixXd delassus(const World& world, const std::vector<ContactRow>& rows);
// The same into A, reusing its storage when it has the size already.
void delassus(const World& world, const std::vector<ContactRow>& rows, Eigen::MatrixXd& A);
// Applies impulses (N s) along the rows: P and L of both bodies change at once.
void applyAlongRows(World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> f);

// While one is alive (on this thread), a world's joints hold through every impulse: delassus()
// gives J W J^T with the joints' constrained mobility W (joints/joint_mobility.h) and
// applyAlongRows() follows each impulse with the joints' reaction. The Baraff model's collide stage
// opens one for a world with joints, so an impact on a joined body is solved with the joint as one
// problem. Scopes nest; `on` false changes nothing.
class JointsHoldImpulses {
 public:
  explicit JointsHoldImpulses(bool on);
  ~JointsHoldImpulses();
  JointsHoldImpulses(const JointsHoldImpulses&) = delete;
  JointsHoldImpulses& operator=(const JointsHoldImpulses&) = delete;

 private:
  bool previous_;
};

}  // namespace tumble
