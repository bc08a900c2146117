// A contact's stiffness from the two bodies' materials, when the scene gives none.
//
// Hertz's law for two elastic bodies touching at a point (K. L. Johnson, "Contact Mechanics",
// 1985, section 4.2): F = K δ^1.5 with K = 4/3 E* sqrt(R*), where
//   1/E* = (1 - ν_a²)/E_a + (1 - ν_b²)/E_b   and   1/R* = 1/R_a + 1/R_b,
// R the radius of curvature of each surface at the point. The linear laws use the stiffness of a
// flat punch of that radius, k = 2 E* R* (Johnson, section 3.8).
//
// What R is at a point: a rounded piece's (a sphere's, a capsule's, a cylinder's side) is its
// radius; a ground plane's is infinite. A polyhedron's face is flat and its vertices and edges are
// sharp, so Hertz's theory gives it no radius at all: each point of a polyhedral manifold is taken
// as the tip of a sphere of half the piece's thinnest width, the stiffness of a body that size. A
// box face on a plane is then four such tips (its manifold's corners), each carrying its share.
#pragma once

#include "dynamics/rigid_body.h"
#include "dynamics/settings.h"

namespace tumble {

// E* of the pair (Pa).
double effectiveModulus(const RigidBody& a, const RigidBody& b);
// R* from the two surfaces' radii at the point (m; infinity for a flat surface on both sides).
double effectiveRadius(double radius_a, double radius_b);
// The law's stiffness for E* and R*: N/m^1.5 for the Hertz-type laws, N/m for the linear ones.
double materialStiffness(NormalForceLaw law, double e_star, double r_star);

}  // namespace tumble
