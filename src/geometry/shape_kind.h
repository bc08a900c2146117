// What a body's collision shape is made of: imported mesh pieces, a box, an exact sphere, a
// capsule, or the ground plane (a half-space, no pieces).
#pragma once

namespace tumble {

enum class ShapeKind { Mesh, Box, Sphere, Capsule, Plane };

}  // namespace tumble
