// The visual mesh through assimp: a walk of the node tree like mesh_import.cpp's, but keeping each
// aiMesh whole (its material is per aiMesh) with normals, texture coordinates and material.
#include "geometry/visual_mesh_import.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cstring>

#include "base/error.h"

namespace tumble {
namespace {

Eigen::Vector3f toEigen(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// The material's base colour: glTF's baseColorFactor first (assimp also copies it to the diffuse
// colour, but only the base colour is the glTF value itself), else the diffuse colour (OBJ/MTL Kd,
// Collada's diffuse). assimp's stand-in for "no material" carries no colour of the file's.
std::optional<Eigen::Vector3f> baseColourOf(const aiMaterial& material) {
  if (std::strcmp(material.GetName().C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0) return std::nullopt;
  aiColor4D c;
  if (material.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || material.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
    return Eigen::Vector3f(c.r, c.g, c.b);
  return std::nullopt;
}

// The base-colour texture (glTF baseColorTexture, MTL map_Kd, Collada's diffuse texture): embedded
// in the file ("*0", or a name assimp matches to an embedded image), or a file beside it.
std::optional<TextureRef> textureOf(const aiScene& scene, const aiMaterial& material,
                                    const std::filesystem::path& file) {
  aiString path;
  if (material.GetTexture(aiTextureType_BASE_COLOR, 0, &path) != AI_SUCCESS &&
      material.GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS)
    return std::nullopt;
  TextureRef ref;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(path.C_Str())) {
    ref.label = file.string() + ": embedded texture " + path.C_Str();
    if (embedded->mHeight == 0) {   // compressed: mWidth bytes of a PNG, JPEG, ...
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
      ref.encoded.assign(bytes, bytes + embedded->mWidth);
    } else {                        // raw texels, aiTexel is BGRA
      ref.raw_width = static_cast<int>(embedded->mWidth);
      ref.raw_height = static_cast<int>(embedded->mHeight);
      for (unsigned i = 0; i < embedded->mWidth * embedded->mHeight; ++i) {
        const aiTexel& t = embedded->pcData[i];
        ref.raw_rgba.insert(ref.raw_rgba.end(), {t.r, t.g, t.b, t.a});
      }
    }
    return ref;
  }
  // MTL files written on Windows use backslashes; the texture is still meant to sit beside.
  std::string name = path.C_Str();
  for (char& ch : name)
    if (ch == '\\') ch = '/';
  ref.file = (file.parent_path() / name).lexically_normal();
  ref.label = ref.file.string();
  return ref;
}

// Appends one aiMesh placed by `to_file`. A mirroring node transform (negative determinant) turns
// the winding, so two corners are swapped to keep triangles counter-clockwise from outside.
void appendPart(const aiScene& scene, const aiMesh& mesh, const aiMatrix4x4& to_file, double scale,
                const std::filesystem::path& file, VisualMesh& out) {
  VisualPart part;
  part.name = mesh.mName.C_Str();
  aiMatrix3x3 normal_matrix(to_file);
  const bool mirrored = normal_matrix.Determinant() < 0;
  normal_matrix.Inverse().Transpose();
  const bool has_uv = mesh.HasTextureCoords(0);
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;
    unsigned corners[3] = {face.mIndices[0], face.mIndices[1], face.mIndices[2]};
    if (mirrored) std::swap(corners[1], corners[2]);
    Eigen::Vector3f p[3];
    for (int k = 0; k < 3; ++k) p[k] = toEigen(to_file * mesh.mVertices[corners[k]]) * static_cast<float>(scale);
    const Eigen::Vector3f flat = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    for (int k = 0; k < 3; ++k) {
      part.positions.push_back(p[k]);
      Eigen::Vector3f n = mesh.HasNormals() ? toEigen(normal_matrix * mesh.mNormals[corners[k]]).normalized() : flat;
      part.normals.push_back(n.allFinite() ? n : Eigen::Vector3f::UnitZ());
      if (has_uv) {
        const aiVector3D& t = mesh.mTextureCoords[0][corners[k]];
        part.uvs.emplace_back(t.x, t.y);
      }
    }
  }
  if (part.positions.empty()) return;
  if (mesh.mMaterialIndex < scene.mNumMaterials) {
    const aiMaterial& material = *scene.mMaterials[mesh.mMaterialIndex];
    part.base_colour = baseColourOf(material);
    if (has_uv) part.texture = textureOf(scene, material, file);
  }
  out.parts.push_back(std::move(part));
}

void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, double scale,
             const std::filesystem::path& file, VisualMesh& out) {
  const aiMatrix4x4 to_file = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) appendPart(scene, mesh, to_file, scale, file, out);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], to_file, scale, file, out);
}

}  // namespace

VisualMesh importVisualMesh(const std::filesystem::path& file, double scale) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // No aiProcess_GenNormals: a mesh without normals is drawn flat, per triangle, as the file's
  // author would see it with no smoothing; smooth normals are drawn only when the file has them.
  // No aiProcess_FlipUVs: assimp hands out OpenGL's convention, v = 0 at the bottom.
  const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFile(file.string(), flags);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
    const std::string why = scene ? "the file describes no complete scene" : importer.GetErrorString();
    throw Error(ExitCode::BadInput, file.string() + ": assimp could not read it: " + why);
  }
  VisualMesh out;
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, file, out);
  return out;
}

}  // namespace tumble
