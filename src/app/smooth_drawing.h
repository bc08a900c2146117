// Smooth draw meshes of pieces with no facets (a sphere, a capsule, a cylinder, a cone): the
// picture is tessellated here, with normals from the exact surface.
#pragma once

#include "geometry/convex_piece.h"
#include "render/draw_list.h"

namespace tumble {

// Appends the piece's surface (body frame) to `mesh`, whose normals must be per position.
// `subdivisions` (1..6) sets the fineness: 8 * 2^s segments around, 2 * 2^s rings per half-sphere.
void appendRoundedMesh(const ConvexPiece& piece, int subdivisions, DrawMesh& mesh);
// A cylinder, a tube or a cone: its sides smooth, its flat ends flat; 8 * 2^s segments around.
void appendRevolvedMesh(const ConvexPiece& piece, int subdivisions, DrawMesh& mesh);

}  // namespace tumble
