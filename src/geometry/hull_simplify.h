// Hulls with too many vertices, cut down for the narrow phase. A smooth imported mesh (a subdivided
// model, a scanned part) can hull to tens of thousands of vertices; the separating-axis test costs
// faces x vertices plus edges x edges per pair and step, so one such body makes a scene crawl.
// PhysX refuses convex meshes above 255 vertices for the same reason (PxConvexMeshDesc's
// vertexLimit) and Bullet advises under 100.
#pragma once

#include <optional>

#include "geometry/convex_piece.h"

namespace tumble {

struct SimplifiedHull {
  ConvexPiece piece;
  double deviation_m = 0;   // the farthest any vertex of the full hull lies outside the new one
};

// The hull of at most `max_vertices` of `hull`'s vertices. Half are the extreme vertices in
// directions spread evenly over the sphere (a Fibonacci lattice); the rest are added in rounds, each
// taking the vertices farthest in front of the faces so far. The result lies inside the full hull
// and touches it in every one of those directions; std::nullopt when `hull` already has few enough
// vertices. Deterministic.
std::optional<SimplifiedHull> simplifyHull(const ConvexPiece& hull, int max_vertices);

}  // namespace tumble
