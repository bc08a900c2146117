#include "app/scene_drawing.h"

#include <algorithm>
#include <cmath>

#include "app/smooth_drawing.h"
#include "app/visual_drawing.h"

namespace tumble {
namespace {

// Polygon faces become triangle fans (they are convex); each triangle keeps the face normal, so
// every convex face shades flat. A body of rounded pieces (spheres, capsules) is drawn smooth
// instead, its normals per corner; a body mixing the two draws its flat faces with a normal per
// corner too.
DrawMesh meshOf(const RigidBody& body, int subdivisions) {
  DrawMesh mesh;
  const bool smooth = std::any_of(body.pieces.begin(), body.pieces.end(), [](const ConvexPiece& p) { return p.smooth(); });
  for (const ConvexPiece& piece : body.pieces) {
    if (piece.rounded()) {
      appendRoundedMesh(piece, subdivisions, mesh);
      continue;
    }
    if (piece.revolved()) {
      appendRevolvedMesh(piece, subdivisions, mesh);
      continue;
    }
    for (std::size_t f = 0; f < piece.faces.size(); ++f) {
      const std::vector<int>& face = piece.faces[f];
      for (std::size_t k = 1; k + 1 < face.size(); ++k) {
        mesh.positions.push_back(piece.vertices[face[0]].cast<float>());
        mesh.positions.push_back(piece.vertices[face[k]].cast<float>());
        mesh.positions.push_back(piece.vertices[face[k + 1]].cast<float>());
        for (int corner = 0; corner < (smooth ? 3 : 1); ++corner)
          mesh.normals.push_back(piece.face_normals[f].cast<float>());
      }
    }
  }
  return mesh;
}

}  // namespace

Eigen::Vector3f srgbToLinear(const Eigen::Vector3d& srgb) {
  Eigen::Vector3f out;
  for (int i = 0; i < 3; ++i) {
    double c = srgb[i];
    out[i] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return out;
}

SceneDrawing prepareDrawing(const Scene& scene, const World& world) {
  SceneDrawing d;
  for (const DirectionalLightSpec& l : scene.lighting.directional) {
    DirectionalLight light;
    light.direction = l.direction.normalized().cast<float>();
    light.colour = srgbToLinear(l.colour_srgb);
    light.intensity = static_cast<float>(l.intensity);
    light.casts_shadows = l.shadows;
    d.frame.lights.push_back(light);
  }
  d.frame.ambient = srgbToLinear(scene.lighting.ambient_srgb) * float(scene.lighting.ambient_intensity);
  d.frame.background = srgbToLinear(scene.render.background_srgb);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& body = world.bodies[i];
    std::vector<DrawnPart>& parts = d.parts_of_body.emplace_back();
    if (body.shape == ShapeKind::Plane) {
      d.frame.ground.present = true;
      d.frame.ground.height = static_cast<float>(body.x.z());
      d.frame.ground.colour_a = srgbToLinear(body.colour_srgb);
      d.frame.ground.colour_b = d.frame.ground.colour_a * 0.72f;
      continue;
    }
    // the world's bodies are the scene's, in order (world_builder.h)
    const BodySpec* spec = i < scene.bodies.size() ? &scene.bodies[i] : nullptr;
    if (spec && spec->shape == ShapeKind::Mesh && spec->draw.value_or(scene.render.draw) == BodyDraw::Visual) {
      appendVisualParts(*spec, body, d, parts);
      continue;
    }
    parts.push_back({static_cast<int>(d.meshes.size()), srgbToLinear(body.colour_srgb)});
    d.meshes.push_back(meshOf(body, spec ? spec->subdivisions : 3));
  }
  for (const std::vector<DrawnPart>& parts : d.parts_of_body)
    for (const DrawnPart& part : parts) {
      DrawInstance inst;
      inst.colour = part.colour;
      d.frame.instances.push_back(inst);
    }
  return d;
}

std::vector<double> bodyRadii(const SceneDrawing& d) {
  std::vector<double> radii;
  for (const std::vector<DrawnPart>& parts : d.parts_of_body) {
    double r = 0;
    for (const DrawnPart& part : parts)
      for (const Eigen::Vector3f& p : d.meshes[static_cast<std::size_t>(part.mesh)].positions)
        r = std::max(r, static_cast<double>(p.norm()));
    radii.push_back(r);
  }
  return radii;
}

std::vector<int> uploadDrawing(Renderer& renderer, const SceneDrawing& d) {
  std::vector<int> texture_ids, mesh_ids;
  for (const DrawTexture& t : d.textures) texture_ids.push_back(renderer.addTexture(t));
  for (const DrawMesh& m : d.meshes) {
    if (m.texture < 0) {
      mesh_ids.push_back(renderer.addMesh(m));
      continue;
    }
    DrawMesh uploaded = m;
    uploaded.texture = texture_ids[static_cast<std::size_t>(m.texture)];
    mesh_ids.push_back(renderer.addMesh(uploaded));
  }
  return mesh_ids;
}

void poseInstances(SceneDrawing& d, const std::vector<BodySample>& samples,
                   const std::vector<int>& uploaded_mesh_ids) {
  std::size_t next = 0;
  for (std::size_t b = 0; b < samples.size(); ++b) {
    const Eigen::Affine3f model(Eigen::Translation3f(samples[b].x.cast<float>()) * samples[b].q.cast<float>());
    for (const DrawnPart& part : d.parts_of_body[b]) {
      DrawInstance& inst = d.frame.instances[next++];
      inst.mesh = uploaded_mesh_ids[static_cast<std::size_t>(part.mesh)];
      inst.model = model;
    }
  }
}

}  // namespace tumble
