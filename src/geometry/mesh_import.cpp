// Mesh files through assimp, one convex piece per mesh instance in the file's node tree.
#include "geometry/mesh_import.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "base/error.h"
#include "geometry/convex_hull.h"
#include "geometry/mesh_convexity.h"

namespace tumble {
namespace {

using Eigen::Vector3d;

// One node's triangle meshes, which make one piece: its name, its vertices in file coordinates
// (node transforms applied, times `scale`) and its triangles.
struct MeshInstance {
  std::string name;
  std::vector<Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
};

void checkReadable(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    throw Error(ExitCode::MissingInput, file.string() + ": no such file");
  }
  if (std::filesystem::is_directory(file, ec)) {
    throw Error(ExitCode::MissingInput, file.string() + ": is a directory, not a mesh file");
  }
  if (!std::ifstream(file, std::ios::binary)) {
    throw Error(ExitCode::MissingInput, file.string() + ": cannot be read (check its permissions)");
  }
}

// assimp 5.2 never returns from a PLY file whose header lacks its `end_header` line (a file cut
// short while being written or copied: seen in our tests), so such a file is refused before
// assimp sees it. A header longer than 1 MB is not a mesh we want either.
void refuseTruncatedPly(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply") return;
  std::streamoff read = 0;
  while (std::getline(in, line) && read < (1 << 20)) {
    if (line.rfind("end_header", 0) == 0) return;
    read += std::streamoff(line.size()) + 1;
  }
  throw Error(ExitCode::BadInput,
              file.string() + ": the PLY header never ends (no end_header line); is the file "
                              "truncated?");
}

// Appends one aiMesh, placed by `to_file`, to a piece's points and triangles.
void append(const aiMesh& mesh, const aiMatrix4x4& to_file, double scale, MeshInstance& out) {
  const int base = int(out.points.size());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D p = to_file * mesh.mVertices[i];
    out.points.emplace_back(scale * double(p.x), scale * double(p.y), scale * double(p.z));
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines: sorted out, but never trusted
    out.triangles.push_back({base + int(face.mIndices[0]), base + int(face.mIndices[1]),
                             base + int(face.mIndices[2])});
  }
}

// Walks the node tree, accumulating transforms; each node with triangles is one piece. A node,
// not an aiMesh, because assimp splits one object into an aiMesh per material (OBJ `usemtl`,
// glTF primitives): a box with a differently coloured lid is still one convex piece. And a walk
// of our own rather than aiProcess_PreTransformVertices, because that step joins meshes that
// share a material: it would fuse the separate pieces of a body into one non-convex mesh.
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, double scale,
             std::vector<MeshInstance>& out) {
  const aiMatrix4x4 to_file = parent * node.mTransformation;
  MeshInstance piece;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    if (piece.name.empty()) piece.name = node.mNumMeshes == 1 ? mesh.mName.C_Str() : "";
    append(mesh, to_file, scale, piece);
  }
  if (piece.name.empty()) piece.name = node.mName.C_Str();
  if (!piece.points.empty()) out.push_back(std::move(piece));
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collect(scene, *node.mChildren[c], to_file, scale, out);
  }
}

std::vector<MeshInstance> readMeshes(const std::filesystem::path& file, double scale) {
  Assimp::Importer importer;
  // Points and lines carry no volume: sort them into their own meshes and drop those.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // Triangulate: the convexity check and the hull want triangles. JoinIdenticalVertices: STL and
  // others repeat each vertex per triangle; the hull does not care, but it is cheaper. Validate:
  // a file assimp half understood is refused instead of read as garbage. No normals, UVs or
  // tangents are generated: the hull makes its own normals.
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                         aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFile(file.string(), flags);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
    const std::string why = scene ? "the file describes no complete scene" : importer.GetErrorString();
    throw Error(ExitCode::BadInput, file.string() + ": assimp could not read it: " + why);
  }
  std::vector<MeshInstance> meshes;
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, meshes);
  return meshes;
}

}  // namespace

ImportedPieces importConvexPieces(const std::filesystem::path& file, double scale) {
  const std::string name = file.string();
  checkReadable(file);
  if (!(std::isfinite(scale) && scale > 0)) {
    std::ostringstream msg;
    msg << name << ": scale must be a positive number, got " << scale;
    throw Error(ExitCode::BadInput, msg.str());
  }
  refuseTruncatedPly(file);
  const std::vector<MeshInstance> meshes = readMeshes(file, scale);
  if (meshes.empty()) {
    throw Error(ExitCode::BadInput,
                name + ": holds no triangle mesh (only points, lines or nothing); a body needs "
                       "at least one closed mesh");
  }
  ImportedPieces out;
  for (size_t k = 0; k < meshes.size(); ++k) {
    const MeshInstance& mesh = meshes[k];
    for (const Vector3d& p : mesh.points) {
      if (!p.allFinite()) {
        throw Error(ExitCode::BadInput,
                    "mesh '" + mesh.name + "' in " + name + " has a NaN or infinite coordinate");
      }
    }
    std::optional<ConvexPiece> hull = convexHull(mesh.points, nullptr);
    if (!hull) {
      throw Error(ExitCode::BadInput, "mesh '" + mesh.name + "' in " + name +
                                          " spans no volume (all points coplanar); a convex "
                                          "piece needs volume");
    }
    if (!isConvexMesh(mesh.points, mesh.triangles, *hull)) {
      out.warnings.push_back("mesh '" + mesh.name + "' (" + std::to_string(k + 1) + " of " +
                             std::to_string(meshes.size()) + ") in " + name +
                             " is not convex; using its convex hull");
    }
    hull->name = mesh.name;
    out.pieces.push_back(std::move(*hull));
  }
  return out;
}

}  // namespace tumble
