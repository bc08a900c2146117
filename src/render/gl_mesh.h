// One uploaded DrawMesh: a vertex buffer of triangles (a flat triangle's normal copied to its three
// corners, since GL has no per-primitive attributes; a Surface mesh's texture coordinates beside
// them) in its own vertex array object.
#pragma once

#include <Eigen/Core>

#include "render/draw_list.h"
#include "render/gl_api.h"

namespace tumble::render {

// Vertex attribute locations shared by every program (the `layout(location=...)` in shaders/).
enum AttributeLocation : GLuint {
  kPositionLocation = 0,
  kNormalLocation = 1,
  kModelColumn0Location = 2,  // per instance: 4 columns of the model matrix, locations 2..5
  kColourLocation = 6,        // per instance: linear RGB albedo
  kTexCoordLocation = 7,      // Surface meshes: texture coordinates
};

class GlMesh {
 public:
  // Throws Error(BadInput) if the normals do not match the triangle count, or the texture
  // coordinates the positions.
  explicit GlMesh(const DrawMesh& mesh);
  ~GlMesh();
  GlMesh(const GlMesh&) = delete;
  GlMesh& operator=(const GlMesh&) = delete;

  // Binds the VAO and points the per-instance attributes at `instance_buffer`, starting at
  // instance `first` (GL 3.3 has no base-instance draw, so the offset goes in the pointers).
  void bindWithInstances(GLuint instance_buffer, std::size_t first) const;
  GLsizei vertexCount() const { return vertex_count_; }
  MeshShading shading() const { return shading_; }
  int texture() const { return texture_; }   // Renderer::addTexture index, -1 for none

  // A sphere around the mesh in mesh coordinates, for fitting the shadow map.
  const Eigen::Vector3f& boundCentre() const { return bound_centre_; }
  float boundRadius() const { return bound_radius_; }

 private:
  GLuint vao_ = 0, vbo_ = 0;
  GLsizei vertex_count_ = 0;
  MeshShading shading_ = MeshShading::Facets;
  int texture_ = -1;
  Eigen::Vector3f bound_centre_ = Eigen::Vector3f::Zero();
  float bound_radius_ = 0;
};

}  // namespace tumble::render
