// How large a body is, for the bounds that scale with it (the tunnelling bound, the drift
// correction's reach, the fault check's limits): computed once per body, since a piece's
// thickness costs faces x vertices.
#pragma once

#include <limits>
#include <vector>

#include "dynamics/world.h"

namespace tumble {

struct BodyExtent {
  double radius = 0;                                          // m: farthest vertex from the centre of mass
  double thinnest = std::numeric_limits<double>::infinity();  // m: thinnest piece (inf: a plane)
};

BodyExtent extentOf(const RigidBody& body);
std::vector<BodyExtent> extentsOf(const World& world);

// How far each body's points can travel within a step (m; 0 for static bodies): the speculative
// margin the detector adds for it, so that every pair that can touch during the step is a contact
// at its start (the time-stepping and penalty models): (|v| + |g| dt + |w| r) dt, with r the
// body's radius about its centre of mass.
// `spin` (if given) holds each body's angular velocity (bodySpins), read instead of worked out.
void bodyReach(const World& world, const std::vector<double>& body_radius, double dt, std::vector<double>& reach,
               const std::vector<Eigen::Vector3d>* spin = nullptr);

// Each body's angular velocity (zero for a static body), once: a step reads it per contact and per
// pair, and each reading is a rotation matrix and two products (2 % of a pile's step).
void bodySpins(const World& world, std::vector<Eigen::Vector3d>& spin);

}  // namespace tumble
