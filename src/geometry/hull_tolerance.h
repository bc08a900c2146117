// Tolerances of the hull code, all relative to the size of the point cloud, so that a shape gives
// the same topology whether it is modelled in millimetres or kilometres, at the origin or far away.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace tumble {

struct HullTolerance {
  // m: a point closer than this to a face plane counts as on it (never becomes a hull vertex).
  // 1e-9 of the cloud's diagonal is ~1e7 ulps of double for a cloud at the origin: far above the
  // rounding of a plane distance (a few ulps of the coordinates), far below any feature a contact
  // solver could resolve. The second term covers clouds far from the origin, where the rounding of
  // the coordinates themselves (~eps |x|) dominates: 1e2 eps |x|max bounds the error of p - a and of
  // the cross products that make the normals.
  double plane = 0;
  // m: adjacent hull triangles whose vertices all lie within this of a common plane are merged
  // into one polygon. Meshes arrive as float32 (assimp), which rounds coordinates at 6e-8
  // relative, so a flat quad of a tilted box is flat only to ~1e-7 of its size; 1e-6 of the
  // diagonal merges such faces, yet it is ~40 times below the sagitta of a level-6 icosphere
  // (edge 0.017 r, sagitta 4e-5 r), so real curvature is never flattened.
  double merge = 0;
  // m: containsAll's slack: a merged face may be off its own best-fit plane by up to `merge`.
  double contain = 0;
};

HullTolerance hullTolerance(const std::vector<Eigen::Vector3d>& points);

}  // namespace tumble
