// Mesh files through assimp. Each object in the file (an assimp node with triangles: an OBJ `o`,
// a glTF node, an STL solid; all its materials together) is one convex piece of the body ("convex
// decomposition assumed"); one that is not convex is replaced by its hull, with a warning.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/convex_piece.h"

namespace tumble {

struct ImportedPieces {
  std::vector<ConvexPiece> pieces;     // in the file's coordinates (node transforms applied), metres
  std::vector<std::string> warnings;   // e.g. "mesh 'Handle' is not convex; using its convex hull"
};

// Throws tumble::Error: MissingInput when the file is absent or unreadable, BadInput when assimp
// cannot parse it, it holds no mesh, or a mesh spans no volume. Messages name the file.
// Pieces must be 1e-6 to 1e6 m across and lie within 1e9 m of the origin (as the scene's shapes).
ImportedPieces importConvexPieces(const std::filesystem::path& file, double scale = 1.0);

// One mesh of `file` (named `mesh_name`) as a convex piece, after assimp has read it: refused with
// BadInput when a coordinate is not finite, the size is out of bounds or it spans no volume; when
// the triangles (valid indices into `points`) are not already convex, `*warning` (if given) says
// it was hulled. The importer's last step, exposed for the fuzz target.
ConvexPiece convexPieceOf(const std::string& mesh_name, const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::array<int, 3>>& triangles, const std::string& file,
                          std::string* warning);

}  // namespace tumble
