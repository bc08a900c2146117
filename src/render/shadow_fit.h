// Where the shadow map looks: an orthographic box along the shadow light, fitted to a sphere
// around all instances, so the map's texels are spent on the bodies and nothing else. GL-free.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "render/draw_list.h"

namespace tumble::render {

struct BoundingSphere {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float radius = 0;  // m
};

// A sphere around every instance, each instance bounded by its mesh's sphere (given in mesh
// coordinates, indexed by mesh) carried through the instance's model matrix. nullopt if there
// are no instances.
std::optional<BoundingSphere> boundInstances(const std::vector<DrawInstance>& instances,
                                             const std::vector<BoundingSphere>& mesh_bounds);

struct ShadowFit {
  Eigen::Matrix4f view_projection;  // world -> light clip space
  float texel_m = 0;                // edge of one shadow texel in world units, for biasing
};

// `direction` is the way the light travels. The box is snapped to whole texels in a frame fixed
// to the light, and its size rounded up to steps of 2^(1/8), so that as bodies move the texel grid
// stays put for most frames and shadow edges do not shimmer in animations.
ShadowFit fitShadow(const Eigen::Vector3f& direction, const BoundingSphere& bound, int map_size);

}  // namespace tumble::render
