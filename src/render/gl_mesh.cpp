#include "render/gl_mesh.h"

#include <algorithm>
#include <string>
#include <vector>

#include "base/error.h"
#include "render/instance_data.h"

namespace tumble::render {

namespace {

// Interleaved position + normal per corner, and a Surface mesh's texture coordinates (zero where
// it has none: the 1x1 white texture then reads the same everywhere).
constexpr GLsizei kVertexFloats = 6, kSurfaceVertexFloats = 8;

std::vector<float> interleavedVertices(const DrawMesh& mesh) {
  const bool surface = mesh.shading == MeshShading::Surface;
  std::vector<float> v;
  v.reserve(mesh.positions.size() * (surface ? kSurfaceVertexFloats : kVertexFloats));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    const Eigen::Vector3f& n = mesh.smooth() ? mesh.normals[i] : mesh.normals[i / 3];
    v.insert(v.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()});
    if (!surface) continue;
    const Eigen::Vector2f uv = mesh.uvs.empty() ? Eigen::Vector2f::Zero() : mesh.uvs[i];
    v.insert(v.end(), {uv.x(), uv.y()});
  }
  return v;
}

void validate(const DrawMesh& mesh) {
  if (mesh.positions.size() % 3 != 0 ||
      (mesh.normals.size() != mesh.positions.size() / 3 && mesh.normals.size() != mesh.positions.size())) {
    throw Error(ExitCode::BadInput,
                "render mesh needs 3 positions and 1 normal per triangle or per position, got " +
                    std::to_string(mesh.positions.size()) + " positions and " +
                    std::to_string(mesh.normals.size()) + " normals");
  }
  for (const auto& p : mesh.positions) {
    if (!p.allFinite()) throw Error(ExitCode::BadInput, "render mesh has a non-finite vertex");
  }
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
    throw Error(ExitCode::BadInput, "render mesh needs 1 texture coordinate per position, got " +
                                        std::to_string(mesh.uvs.size()) + " for " +
                                        std::to_string(mesh.positions.size()) + " positions");
}

}  // namespace

GlMesh::GlMesh(const DrawMesh& mesh) {
  validate(mesh);
  vertex_count_ = static_cast<GLsizei>(mesh.positions.size());
  shading_ = mesh.shading;
  texture_ = mesh.texture;
  if (!mesh.positions.empty()) {
    // Centre of the bounding box, then the farthest corner: a sphere close enough to tight for
    // convex pieces, and cheaper to reason about than a minimal sphere.
    Eigen::Vector3f lo = mesh.positions[0], hi = mesh.positions[0];
    for (const auto& p : mesh.positions) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    bound_centre_ = 0.5f * (lo + hi);
    for (const auto& p : mesh.positions) {
      bound_radius_ = std::max(bound_radius_, (p - bound_centre_).norm());
    }
  }

  const std::vector<float> vertices = interleavedVertices(mesh);
  const bool surface = shading_ == MeshShading::Surface;
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
               vertices.data(), GL_STATIC_DRAW);
  const GLsizei stride = (surface ? kSurfaceVertexFloats : kVertexFloats) * sizeof(float);
  glEnableVertexAttribArray(kPositionLocation);
  glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(kNormalLocation);
  glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  if (surface) {
    glEnableVertexAttribArray(kTexCoordLocation);
    glVertexAttribPointer(kTexCoordLocation, 2, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(6 * sizeof(float)));
  }
  for (GLuint c = 0; c < 4; ++c) {
    glEnableVertexAttribArray(kModelColumn0Location + c);
    glVertexAttribDivisor(kModelColumn0Location + c, 1);
  }
  glEnableVertexAttribArray(kColourLocation);
  glVertexAttribDivisor(kColourLocation, 1);
  glBindVertexArray(0);
}

GlMesh::~GlMesh() {
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

void GlMesh::bindWithInstances(GLuint instance_buffer, std::size_t first) const {
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer);
  const GLsizei stride = kInstanceFloats * sizeof(float);
  const std::size_t base = first * kInstanceFloats * sizeof(float);
  for (GLuint c = 0; c < 4; ++c) {
    glVertexAttribPointer(kModelColumn0Location + c, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(base + 4 * c * sizeof(float)));
  }
  glVertexAttribPointer(kColourLocation, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(base + 16 * sizeof(float)));
}

}  // namespace tumble::render
