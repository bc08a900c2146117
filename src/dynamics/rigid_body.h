// A rigid body: its constant properties (mass, principal inertia, convex pieces in the body frame)
// and its state (x, q, P, L) as in Yang, "Rigid Bodies and Contacts", 2020: position of the centre of mass,
// orientation, linear momentum, angular momentum, all in the world frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "geometry/convex_piece.h"
#include "geometry/shape_kind.h"

namespace tumble {

struct RigidBody {
  std::string name;
  ShapeKind shape = ShapeKind::Box;
  bool is_static = false;   // never moves: from the scene, or asleep (below)
  bool asleep = false;      // frozen by sleeping.h until something awake touches it; static meanwhile
  bool fixedByScene() const { return is_static && !asleep; }

  // constant properties
  double mass = 0, inv_mass = 0;                                   // kg, 1/kg (0 when static)
  Eigen::Vector3d inertia_body = Eigen::Vector3d::Zero();          // principal moments, kg m^2
  Eigen::Vector3d inv_inertia_body = Eigen::Vector3d::Zero();      // 1 / moments (0 when static)
  std::vector<ConvexPiece> pieces;                                 // body frame: origin at COM,
                                                                   // axes principal (empty for planes)
  double restitution = 0.5, friction = 0.5;
  // Elastic constants, read only by the penalty model's stiffness from materials.
  double youngs_modulus_pa = 1e8, poisson_ratio = 0.3;
  Eigen::Vector3d colour_srgb{0.8, 0.8, 0.8};

  // state
  Eigen::Vector3d x = Eigen::Vector3d::Zero();                     // m, centre of mass
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();           // body -> world
  Eigen::Vector3d P = Eigen::Vector3d::Zero();                     // kg m/s
  Eigen::Vector3d L = Eigen::Vector3d::Zero();                     // kg m^2/s

  // derived quantities
  Eigen::Vector3d velocity() const { return P * inv_mass; }
  Eigen::Matrix3d rotation() const { return q.toRotationMatrix(); }
  // Equal principal moments (a cube, a sphere; and a static body's zeros): the inertia is the same
  // about every axis, in every orientation, and needs no rotation.
  bool isotropic() const {
    return inv_inertia_body.x() == inv_inertia_body.y() && inv_inertia_body.y() == inv_inertia_body.z();
  }
  // omega = R I^-1 R^T L: the inverse inertia in world axes applied to L (I^-1 L when isotropic:
  // exact, where the rotation there and back rounds).
  Eigen::Vector3d angularVelocity() const { return angularVelocityOf(q, L); }
  // The same for an orientation and an angular momentum given (an integrator's stages).
  Eigen::Vector3d angularVelocityOf(const Eigen::Quaterniond& at, const Eigen::Vector3d& momentum) const {
    if (isotropic()) return inv_inertia_body.x() * momentum;
    Eigen::Matrix3d R = at.toRotationMatrix();
    return R * inv_inertia_body.cwiseProduct(R.transpose() * momentum);
  }
  double kineticEnergy() const {
    Eigen::Vector3d w = angularVelocity();
    return 0.5 * (P.dot(velocity()) + L.dot(w));
  }
};

}  // namespace tumble
