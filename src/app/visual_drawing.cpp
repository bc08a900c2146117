#include "app/visual_drawing.h"

#include "base/error.h"
#include "geometry/visual_mesh_import.h"
#include "io/texture_image.h"

namespace tumble {
namespace {

// The file's coordinates -> the body's principal frame. The scene places the file's origin at
// `position_m` turned by `orientation`, and the body's frame at x turned by q, so a file point p
// sits at q^-1 (orientation p + position - x) in the body's frame.
Eigen::Affine3d fileToBody(const BodySpec& spec, const RigidBody& body) {
  const Eigen::Affine3d world_from_file = Eigen::Translation3d(spec.position_m) * spec.orientation;
  const Eigen::Affine3d world_from_body = Eigen::Translation3d(body.x) * body.q;
  return world_from_body.inverse(Eigen::Isometry) * world_from_file;
}

DrawTexture decode(const TextureRef& ref) {
  if (!ref.raw_rgba.empty()) return DrawTexture{ref.raw_width, ref.raw_height, ref.raw_rgba};
  if (!ref.encoded.empty()) return decodeTexture(ref.encoded, ref.label);
  return readTextureFile(ref.file);
}

// The drawing's texture for `ref`, decoded once per label; -1 with a warning when it cannot be.
int textureIndex(const TextureRef& ref, const BodySpec& spec, SceneDrawing& d) {
  if (auto it = d.texture_of_label.find(ref.label); it != d.texture_of_label.end()) return it->second;
  int index = -1;
  try {
    d.textures.push_back(decode(ref));
    index = static_cast<int>(d.textures.size()) - 1;
  } catch (const Error& e) {
    d.warnings.push_back("body \"" + spec.name + "\": texture " + e.what() + "; drawn in its material's colour");
  }
  d.texture_of_label.emplace(ref.label, index);
  return index;
}

DrawMesh drawMeshOf(const VisualPart& part, const Eigen::Affine3d& to_body, int texture) {
  DrawMesh mesh;
  mesh.shading = MeshShading::Surface;
  const Eigen::Affine3f m = to_body.cast<float>();
  for (const Eigen::Vector3f& p : part.positions) mesh.positions.push_back(m * p);
  for (const Eigen::Vector3f& n : part.normals) mesh.normals.push_back(m.linear() * n);
  if (texture >= 0) {
    mesh.uvs = part.uvs;
    mesh.texture = texture;
  }
  return mesh;
}

// The file's meshes as draw meshes, made once per file and scale.
std::vector<FilePartDrawing> filePartsOf(const BodySpec& spec, const RigidBody& body, SceneDrawing& d) {
  const VisualMesh visual = importVisualMesh(spec.mesh, spec.mesh_scale);
  const Eigen::Affine3d to_body = fileToBody(spec, body);
  std::vector<FilePartDrawing> parts;
  for (const VisualPart& part : visual.parts) {
    const int texture = !spec.colour_given && part.texture ? textureIndex(*part.texture, spec, d) : -1;
    parts.push_back({static_cast<int>(d.meshes.size()), part.base_colour});
    d.meshes.push_back(drawMeshOf(part, to_body, texture));
  }
  return parts;
}

}  // namespace

void appendVisualParts(const BodySpec& spec, const RigidBody& body, SceneDrawing& d,
                       std::vector<DrawnPart>& parts) {
  // Bodies of one file and scale share their meshes (their principal frames sit alike in the
  // file, as their pieces are the same): a pile of one mesh is one instanced draw per part. Only
  // whether the scene's colour drops the file's textures can differ, so it is in the key, as the
  // scale's sign.
  const std::pair<std::string, double> key{spec.mesh.string(), spec.colour_given ? -spec.mesh_scale : spec.mesh_scale};
  auto it = d.visual_parts_of_file.find(key);
  if (it == d.visual_parts_of_file.end()) it = d.visual_parts_of_file.emplace(key, filePartsOf(spec, body, d)).first;
  const Eigen::Vector3f body_colour = srgbToLinear(spec.colour_srgb);
  for (const FilePartDrawing& part : it->second)
    parts.push_back({part.mesh, spec.colour_given ? body_colour : part.file_colour.value_or(body_colour)});
}

}  // namespace tumble
