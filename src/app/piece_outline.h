// The lines that outline a body's convex pieces in its own frame (m, origin at the centre of
// mass): the back_step overlay draws them at each pose bisection tried. A polyhedron's hull edges;
// a rounded piece's core with three great circles about each of its ends (a sphere: three rings;
// a capsule: its ends' rings and four lines along its side); a solid of revolution's rims and four
// lines along its side. Made once per body: only the poses change from frame to frame.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "dynamics/rigid_body.h"

namespace tumble {

using OutlineSegment = std::pair<Eigen::Vector3d, Eigen::Vector3d>;

std::vector<OutlineSegment> bodyOutline(const RigidBody& body);

}  // namespace tumble
