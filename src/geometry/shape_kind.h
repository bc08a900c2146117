// What a body's collision shape is made of: imported mesh pieces, a box, an exact sphere, a
// capsule, a cylinder, a tube, a cone, a compound of those placed in the body's frame (a dumbbell), or the
// ground plane (a half-space, no pieces).
#pragma once

namespace tumble {

enum class ShapeKind { Mesh, Box, Sphere, Capsule, Cylinder, Tube, Cone, Compound, Plane };

}  // namespace tumble
