// Mesh files through assimp. Each object in the file (an assimp node with triangles: an OBJ `o`,
// a glTF node, an STL solid; all its materials together) is one convex piece of the body ("convex
// decomposition assumed"); one that is not convex is replaced by its hull, with a warning.
#pragma once

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
ImportedPieces importConvexPieces(const std::filesystem::path& file, double scale = 1.0);

}  // namespace tumble
