// What a mesh file looks like, as opposed to what collides (mesh_import.h): every triangle mesh of
// the file with its node transforms, its normals as the file gives them, texture coordinates and
// each mesh's material (base colour and base-colour texture). GL-free and physics-free: the
// simulation never sees it; the app turns it into the renderer's draw meshes.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tumble {

// Where a material's base-colour texture lives. Decoding is left to the caller, so that a texture
// that cannot be read costs a warning there rather than the whole import.
struct TextureRef {
  std::string label;                   // for messages: the texture file, or "FILE: embedded texture *N"
  std::filesystem::path file;          // a file (relative paths resolved beside the mesh); or empty:
  std::vector<std::uint8_t> encoded;   // an embedded PNG/JPEG as stored in the mesh file, or
  int raw_width = 0, raw_height = 0;   // raw texels assimp decoded itself (RGBA8, top row first)
  std::vector<std::uint8_t> raw_rgba;
};

// One aiMesh placed by its node: a triangle soup with one material.
struct VisualPart {
  std::string name;
  std::vector<Eigen::Vector3f> positions;   // 3 per triangle, counter-clockwise from outside, metres
  std::vector<Eigen::Vector3f> normals;     // one per position, unit: the file's, or each triangle's
                                            // own (flat) where the file has none
  std::vector<Eigen::Vector2f> uvs;         // one per position, OpenGL's convention (v = 0 at the
                                            // image's bottom row); empty without coordinates
  // The material's base colour, linear RGB as glTF's baseColorFactor and OBJ's Kd are written;
  // none when the file names no material (assimp's default one).
  std::optional<Eigen::Vector3f> base_colour;
  std::optional<TextureRef> texture;        // only when the part also has texture coordinates
};

struct VisualMesh {
  std::vector<VisualPart> parts;            // in the file's node order
};

// Reads `file` with assimp, scaled by `scale` (file units -> metres). Throws tumble::Error:
// MissingInput for an unreadable file, BadInput when assimp cannot parse it. The caller has
// imported the same file for collisions already, so these are the same errors as there.
VisualMesh importVisualMesh(const std::filesystem::path& file, double scale);

}  // namespace tumble
