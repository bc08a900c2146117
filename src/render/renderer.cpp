// The OSMesa renderer: owns the context and GL objects, and runs the frame as
//   shadow pass (bodies' depth from the shadow light) -> lit pass (faceted bodies, bodies drawn as
//   their files hold them, ground) -> overlay marks, if any -> resolve.
#include "render/renderer.h"

#include <optional>
#include <string>

#include "base/error.h"
#include "render/camera_matrices.h"
#include "render/gl_check.h"
#include "render/gl_mesh.h"
#include "render/gl_program.h"
#include "render/gl_texture.h"
#include "render/instance_data.h"
#include "render/lighting.h"
#include "render/marks_pass.h"
#include "render/osmesa_context.h"
#include "render/pixel_convert.h"
#include "render/render_targets.h"
#include "render/shader_programs.h"
#include "render/shadow_map.h"

namespace tumble {

namespace {

using namespace tumble::render;

class GlRenderer final : public Renderer {
 public:
  explicit GlRenderer(const RenderConfig& config);
  ~GlRenderer() override;

  int addTexture(const DrawTexture& texture) override;
  int addMesh(const DrawMesh& mesh) override;
  void draw(const DrawFrame& frame) override;
  void readBack(RgbImage& out) override;
  std::string glRenderer() override;

 private:
  void createGround();
  void drawShadowPass(const FrameLighting& lit);
  void drawGround(const DrawFrame& frame, const FrameLighting& lit,
                  const Eigen::Matrix4f& view_proj);
  void drawBodies(const DrawFrame& frame, const FrameLighting& lit,
                  const Eigen::Matrix4f& view_proj);
  void drawSurfaces(const DrawFrame& frame, const FrameLighting& lit, const Eigen::Matrix4f& view_proj);
  // Draws the batches whose mesh has the given shading (all of them when none is given).
  void drawBatches(std::optional<MeshShading> only = std::nullopt) const;
  bool hasBatches(MeshShading shading) const;

  RenderConfig config_;
  OsmesaContext context_;  // first member: GL objects below are deleted while it still exists
  std::unique_ptr<RenderTargets> targets_;
  std::unique_ptr<ShadowMap> shadow_map_;
  std::unique_ptr<ShaderPrograms> programs_;
  std::unique_ptr<MarksPass> marks_;    // made on the first frame with overlay marks
  std::vector<std::unique_ptr<GlMesh>> meshes_;
  std::vector<std::unique_ptr<GlTexture>> textures_;
  std::unique_ptr<GlTexture> white_;    // the albedo map of Surface meshes without a texture
  std::vector<BoundingSphere> mesh_bounds_;
  GLuint instance_buffer_ = 0, ground_vao_ = 0, ground_vbo_ = 0;
  PackedInstances packed_;              // reused each frame to avoid reallocating
  std::vector<std::uint8_t> rgba_;
  bool has_frame_ = false;
};

GlRenderer::GlRenderer(const RenderConfig& config) : config_(config) {
  targets_ = std::make_unique<RenderTargets>(config.width, config.height, config.samples);
  shadow_map_ = std::make_unique<ShadowMap>(config.shadow_map_size);
  programs_ = std::make_unique<ShaderPrograms>(config.shader_dir);
  glGenBuffers(1, &instance_buffer_);
  createGround();
  white_ = std::make_unique<GlTexture>(DrawTexture{1, 1, {255, 255, 255, 255}});
  throwIfGlError("setting up the renderer");
}

GlRenderer::~GlRenderer() {
  try {
    context_.makeCurrent();
  } catch (const Error&) {
    return;  // the context is unusable; destroying it releases its objects anyway
  }
  glDeleteBuffers(1, &instance_buffer_);
  glDeleteBuffers(1, &ground_vbo_);
  glDeleteVertexArrays(1, &ground_vao_);
  marks_.reset();
  meshes_.clear();
  textures_.clear();
  white_.reset();
  programs_.reset();
  shadow_map_.reset();
  targets_.reset();
}

void GlRenderer::createGround() {
  // Two counter-clockwise triangles seen from above (+z), over [-1, 1]^2.
  const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  glGenVertexArrays(1, &ground_vao_);
  glGenBuffers(1, &ground_vbo_);
  glBindVertexArray(ground_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, ground_vbo_);
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glBindVertexArray(0);
}

int GlRenderer::addTexture(const DrawTexture& texture) {
  context_.makeCurrent();
  textures_.push_back(std::make_unique<GlTexture>(texture));
  throwIfGlError("uploading a texture");
  return static_cast<int>(textures_.size()) - 1;
}

int GlRenderer::addMesh(const DrawMesh& mesh) {
  context_.makeCurrent();
  if (mesh.texture >= static_cast<int>(textures_.size()) || mesh.texture < -1)
    throw Error(ExitCode::BadInput, "render mesh refers to texture " + std::to_string(mesh.texture) + " but only " +
                                        std::to_string(textures_.size()) + " textures were added");
  auto gl_mesh = std::make_unique<GlMesh>(mesh);
  mesh_bounds_.push_back({gl_mesh->boundCentre(), gl_mesh->boundRadius()});
  meshes_.push_back(std::move(gl_mesh));
  throwIfGlError("uploading a mesh");
  return static_cast<int>(meshes_.size()) - 1;
}

void GlRenderer::draw(const DrawFrame& frame) {
  context_.makeCurrent();
  const float aspect = static_cast<float>(config_.width) / static_cast<float>(config_.height);
  const Eigen::Matrix4f view_proj = cameraViewProjection(frame.camera, aspect);
  packInstances(frame.instances, static_cast<int>(meshes_.size()), frame.camera.eye, packed_);
  const FrameLighting lit =
      frameLighting(frame, boundInstances(frame.instances, mesh_bounds_), config_.shadow_map_size);

  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(packed_.data.size() * sizeof(float)),
               packed_.data.data(), GL_STREAM_DRAW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (lit.shadows) drawShadowPass(lit);

  targets_->beginPass();
  // The background is linear like every colour in the draw list; encode it as the shaders do.
  glClearColor(encodeSrgb(frame.background.x()), encodeSrgb(frame.background.y()),
               encodeSrgb(frame.background.z()), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  shadow_map_->bindTexture(GL_TEXTURE0);
  // Bodies first: the ground behind them then fails the depth test instead of being shaded.
  drawBodies(frame, lit, view_proj);
  drawSurfaces(frame, lit, view_proj);
  if (frame.ground.present) drawGround(frame, lit, view_proj);
  if (!frame.marks.empty()) {
    if (!marks_) marks_ = std::make_unique<MarksPass>();
    marks_->draw(frame.marks, view_proj, config_.width, config_.height, programs_->marks());
  }
  targets_->resolve();
  // llvmpipe queues the work and rasterises on its own threads; finishing here makes draw() own
  // the rendering time and readBack() only the copy, so the summary's split is honest.
  glFinish();
  throwIfGlError("drawing a frame");
  has_frame_ = true;
}

void GlRenderer::drawShadowPass(const FrameLighting& lit) {
  shadow_map_->beginPass();
  // Meshes are closed and counter-clockwise from outside, so the faces turned towards the light
  // are the whole outline: culling the others halves the fill of this pass.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  const GlProgram& program = programs_->shadow();
  program.use();
  glUniformMatrix4fv(program.uniform("u_light_view_proj"), 1, GL_FALSE,
                     lit.shadow.view_projection.data());
  drawBatches();
  shadow_map_->endPass();
}

void GlRenderer::drawGround(const DrawFrame& frame, const FrameLighting& lit,
                           const Eigen::Matrix4f& view_proj) {
  glDisable(GL_CULL_FACE);  // seen from below it should still hide what is under it
  // One shadow lookup per pixel is cheap enough to spend on the whole ground; drawing only the
  // shadows' reach with them and the rest without was measured no faster.
  const GlProgram& p = programs_->ground(lit.variant());
  p.use();
  applyLighting(p, frame, lit);
  const DrawGround& g = frame.ground;
  glUniformMatrix4fv(p.uniform("u_view_proj"), 1, GL_FALSE, view_proj.data());
  glUniform1f(p.uniform("u_ground_extent"), g.extent_m);
  glUniform1f(p.uniform("u_ground_height"), g.height);
  glUniform3fv(p.uniform("u_colour_a"), 1, g.colour_a.data());
  glUniform3fv(p.uniform("u_colour_b"), 1, g.colour_b.data());
  glUniform1f(p.uniform("u_checker_m"), g.checker_m);
  glBindVertexArray(ground_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

void GlRenderer::drawBodies(const DrawFrame& frame, const FrameLighting& lit,
                            const Eigen::Matrix4f& view_proj) {
  if (!hasBatches(MeshShading::Facets)) return;
  // Triangles are counter-clockwise seen from outside, so back faces are never visible on
  // closed bodies: culling them halves the fragment work.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  const GlProgram& program = programs_->lit(lit.variant());
  program.use();
  applyLighting(program, frame, lit);
  glUniformMatrix4fv(program.uniform("u_view_proj"), 1, GL_FALSE, view_proj.data());
  drawBatches(MeshShading::Facets);
}

// Meshes as imported: their own program, and each batch's albedo texture on unit 1 (unit 0 holds
// the shadow map). Back faces are culled as for the bodies: files give closed meshes
// counter-clockwise from outside (glTF requires it, OBJ and others follow it).
void GlRenderer::drawSurfaces(const DrawFrame& frame, const FrameLighting& lit,
                              const Eigen::Matrix4f& view_proj) {
  if (!hasBatches(MeshShading::Surface)) return;
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  const GlProgram& program = programs_->surface(lit.variant());
  program.use();
  applyLighting(program, frame, lit);
  glUniformMatrix4fv(program.uniform("u_view_proj"), 1, GL_FALSE, view_proj.data());
  glUniform1i(program.uniform("u_albedo_map"), 1);
  for (const InstanceBatch& batch : packed_.batches) {
    const GlMesh& mesh = *meshes_[static_cast<std::size_t>(batch.mesh)];
    if (mesh.shading() != MeshShading::Surface || mesh.vertexCount() == 0) continue;
    (mesh.texture() >= 0 ? *textures_[static_cast<std::size_t>(mesh.texture())] : *white_).bind(GL_TEXTURE1);
    mesh.bindWithInstances(instance_buffer_, batch.first);
    glDrawArraysInstanced(GL_TRIANGLES, 0, mesh.vertexCount(), static_cast<GLsizei>(batch.count));
  }
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
}

bool GlRenderer::hasBatches(MeshShading shading) const {
  for (const InstanceBatch& batch : packed_.batches)
    if (meshes_[static_cast<std::size_t>(batch.mesh)]->shading() == shading) return true;
  return false;
}

void GlRenderer::drawBatches(std::optional<MeshShading> only) const {
  for (const InstanceBatch& batch : packed_.batches) {
    const GlMesh& mesh = *meshes_[static_cast<std::size_t>(batch.mesh)];
    if (mesh.vertexCount() == 0 || (only && mesh.shading() != *only)) continue;
    mesh.bindWithInstances(instance_buffer_, batch.first);
    glDrawArraysInstanced(GL_TRIANGLES, 0, mesh.vertexCount(),
                          static_cast<GLsizei>(batch.count));
  }
  glBindVertexArray(0);
}

void GlRenderer::readBack(RgbImage& out) {
  if (!has_frame_) {
    throw Error(ExitCode::Software, "Renderer::readBack called before any draw");
  }
  context_.makeCurrent();
  targets_->readRgba(rgba_);
  throwIfGlError("reading the frame back");
  rgbaBottomUpToRgbTopDown(rgba_, config_.width, config_.height, out);
}

std::string GlRenderer::glRenderer() {
  context_.makeCurrent();
  const GLubyte* name = glGetString(GL_RENDERER);
  return name ? reinterpret_cast<const char*>(name) : "unknown";
}

}  // namespace

std::unique_ptr<Renderer> Renderer::create(const RenderConfig& config) {
  return std::make_unique<GlRenderer>(config);
}

}  // namespace tumble
