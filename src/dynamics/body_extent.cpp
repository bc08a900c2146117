#include "dynamics/body_extent.h"

#include <algorithm>

namespace tumble {

BodyExtent extentOf(const RigidBody& body) {
  BodyExtent e;
  for (const ConvexPiece& piece : body.pieces) {
    e.thinnest = std::min(e.thinnest, piece.thickness());
    for (const Eigen::Vector3d& v : piece.vertices) e.radius = std::max(e.radius, v.norm() + piece.radius_m + piece.disc_radius_m);
  }
  return e;
}

std::vector<BodyExtent> extentsOf(const World& world) {
  std::vector<BodyExtent> out;
  out.reserve(world.bodies.size());
  for (const RigidBody& body : world.bodies) out.push_back(extentOf(body));
  return out;
}

void bodyReach(const World& world, const std::vector<double>& body_radius, double dt, std::vector<double>& reach,
               const std::vector<Eigen::Vector3d>* spin) {
  reach.assign(world.bodies.size(), 0.0);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.is_static) continue;
    const double turning = spin ? (*spin)[i].norm() : b.angularVelocity().norm();
    reach[i] = (b.velocity().norm() + world.gravity.norm() * dt + turning * body_radius[i]) * dt;
  }
}

void bodySpins(const World& world, std::vector<Eigen::Vector3d>& spin) {
  spin.resize(world.bodies.size());
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    spin[i] = b.is_static ? Eigen::Vector3d::Zero() : b.angularVelocity();
  }
}

}  // namespace tumble
