// Mesh files through assimp, one convex piece per mesh instance in the file's node tree.
#include "geometry/mesh_import.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "base/error.h"
#include "geometry/convex_hull.h"
#include "geometry/hull_simplify.h"
#include "geometry/mesh_import_checks.h"
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

// Pieces outside the sizes a double-precision contact solver resolves are refused: the scene's
// boxes and spheres have the same bounds, and positions stop at 1e9 m. A wrong unit or scale is the
// usual cause (millimetres read as metres), so the message points there.
constexpr double kMinSide = 1e-6, kMaxSide = 1e6, kMaxCoordinate = 1e9;   // m
// Hulls above this many vertices are simplified (hull_simplify.h): PhysX's vertex limit.
constexpr int kMaxHullVertices = 255;

struct MeshView {
  const std::string& name;
  const std::vector<Vector3d>& points;
};

void checkFiniteAndSize(const MeshView& mesh, const std::string& file) {
  Vector3d lo = Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vector3d& p : mesh.points) {
    if (!p.allFinite()) {
      throw Error(ExitCode::BadInput,
                  "mesh '" + mesh.name + "' in " + file + " has a NaN or infinite coordinate");
    }
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double side = (hi - lo).maxCoeff(), far = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if (side >= kMinSide && side <= kMaxSide && far <= kMaxCoordinate) return;
  std::ostringstream msg;
  msg << "mesh '" << mesh.name << "' in " << file << " is " << side << " m across and reaches " << far
      << " m from the origin; tumble takes pieces " << kMinSide << " to " << kMaxSide
      << " m across within " << kMaxCoordinate << " m of the origin (check the file's units and \"scale\")";
  throw Error(ExitCode::BadInput, msg.str());
}

}  // namespace

ConvexPiece convexPieceOf(const std::string& mesh_name, const std::vector<Vector3d>& points,
                          const std::vector<std::array<int, 3>>& triangles, const std::string& file,
                          std::string* warning) {
  checkFiniteAndSize(MeshView{mesh_name, points}, file);
  std::optional<ConvexPiece> hull = convexHull(points, nullptr);
  if (!hull) {
    throw Error(ExitCode::BadInput, "mesh '" + mesh_name + "' in " + file +
                                        " spans no volume (all points coplanar); a convex "
                                        "piece needs volume");
  }
  if (warning && !isConvexMesh(points, triangles, *hull)) *warning = "is not convex; using its convex hull";
  if (std::optional<SimplifiedHull> smaller = simplifyHull(*hull, kMaxHullVertices)) {
    if (warning) {
      std::ostringstream msg;
      msg << (warning->empty() ? "" : "; ") << "its hull has " << hull->vertices.size()
          << " vertices, more than the narrow phase takes (" << kMaxHullVertices << "); using the hull of "
          << smaller->piece.vertices.size() << " of them, at most " << smaller->deviation_m
          << " m inside the full hull";
      *warning += msg.str();
    }
    hull = std::move(smaller->piece);
  }
  hull->name = mesh_name;
  return std::move(*hull);
}

ImportedPieces importConvexPieces(const std::filesystem::path& file, double scale) {
  const std::string name = file.string();
  checkReadable(file);
  if (!(std::isfinite(scale) && scale > 0)) {
    std::ostringstream msg;
    msg << name << ": scale must be a positive number, got " << scale;
    throw Error(ExitCode::BadInput, msg.str());
  }
  refuseFilesAssimpHangsOn(file);
  const std::vector<MeshInstance> meshes = readMeshes(file, scale);
  if (meshes.empty()) {
    throw Error(ExitCode::BadInput,
                name + ": holds no triangle mesh (only points, lines or nothing); a body needs "
                       "at least one closed mesh");
  }
  ImportedPieces out;
  for (size_t k = 0; k < meshes.size(); ++k) {
    const MeshInstance& mesh = meshes[k];
    std::string warning;
    out.pieces.push_back(convexPieceOf(mesh.name, mesh.points, mesh.triangles, name, &warning));
    if (!warning.empty()) {
      out.warnings.push_back("mesh '" + mesh.name + "' (" + std::to_string(k + 1) + " of " +
                             std::to_string(meshes.size()) + ") in " + name + " " + warning);
    }
  }
  return out;
}

}  // namespace tumble
