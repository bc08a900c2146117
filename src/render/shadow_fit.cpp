#include "render/shadow_fit.h"

#include <algorithm>
#include <cmath>

#include "render/camera_matrices.h"

namespace tumble::render {

namespace {

// 1 mm: keeps the projection invertible for a single point-like body.
constexpr float kMinRadius = 1e-3f;
// Steps of 2^(1/8) (about 9 %): coarse enough that a settling pile keeps one size for many
// frames, fine enough that the box is never more than 9 % larger than needed.
constexpr float kRadiusStepsPerOctave = 8;

float quantiseRadius(float r) {
  r = std::max(r, kMinRadius);
  return std::exp2(std::ceil(std::log2(r) * kRadiusStepsPerOctave) / kRadiusStepsPerOctave);
}

}  // namespace

std::optional<BoundingSphere> boundInstances(const std::vector<DrawInstance>& instances,
                                             const std::vector<BoundingSphere>& mesh_bounds) {
  if (instances.empty()) return std::nullopt;
  std::vector<BoundingSphere> world;
  world.reserve(instances.size());
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(INFINITY), hi = -lo;
  for (const DrawInstance& inst : instances) {
    const BoundingSphere& b = mesh_bounds[static_cast<std::size_t>(inst.mesh)];
    // Largest column norm of the linear part bounds how much the model stretches a radius
    // (1 for the rigid poses the simulator produces).
    const float scale = inst.model.linear().colwise().norm().maxCoeff();
    const BoundingSphere w{inst.model * b.centre, b.radius * scale};
    lo = lo.cwiseMin(w.centre - Eigen::Vector3f::Constant(w.radius));
    hi = hi.cwiseMax(w.centre + Eigen::Vector3f::Constant(w.radius));
    world.push_back(w);
  }
  // Centre of the boxes around the spheres, then the radius that reaches every sphere: not the
  // minimal sphere, but within a factor sqrt(3) of it and exact for a single body.
  BoundingSphere all{0.5f * (lo + hi), 0};
  for (const BoundingSphere& w : world) {
    all.radius = std::max(all.radius, (w.centre - all.centre).norm() + w.radius);
  }
  return all;
}

ShadowFit fitShadow(const Eigen::Vector3f& direction, const BoundingSphere& bound, int map_size) {
  // A light frame that depends on the direction only (eye at the origin), so snapping the box
  // to texels below is stable while the bodies move.
  const Eigen::Matrix4f view = lookAt(Eigen::Vector3f::Zero(), direction.normalized(),
                                      Eigen::Vector3f::UnitZ());
  const float size = static_cast<float>(map_size);
  // Half-width with two texels of slack for the snap (which moves the centre by < 1 texel):
  // half * (1 - 2 / size) = r  =>  half - r = 2 * half / size = 2 texels.
  const float half = quantiseRadius(bound.radius) * size / (size - 2.0f);
  const float texel = 2.0f * half / size;

  const Eigen::Vector4f c = view * bound.centre.homogeneous();
  const float cx = std::floor(c.x() / texel) * texel;
  const float cy = std::floor(c.y() / texel) * texel;
  // Eye-space z is negative in front of the light; depth range just covers the sphere. Receivers
  // beyond it (the ground under the bodies) are clamped to the far plane in the shader, so they
  // still compare as behind every caster.
  const float depth = -c.z();
  const float pad = 2.0f * texel;
  ShadowFit fit;
  fit.view_projection = ortho(cx - half, cx + half, cy - half, cy + half,
                              depth - half - pad, depth + half + pad) * view;
  fit.texel_m = texel;
  return fit;
}

}  // namespace tumble::render
