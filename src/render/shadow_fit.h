// Where the shadow map looks: an orthographic box along the shadow light, fitted to a sphere
// around all instances, so the map's texels are spent on the bodies and nothing else. GL-free.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
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
  Eigen::Vector3f direction = -Eigen::Vector3f::UnitZ();  // unit, the way the light travels
  Eigen::Matrix3f light_rotation = Eigen::Matrix3f::Identity();  // world -> light frame
  Eigen::AlignedBox2f box;          // the map's extent across the light, light frame, m
};

// `direction` is the way the light travels. The box is snapped to whole texels in a frame fixed
// to the light, and its size rounded up to steps of 2^(1/8), so that as bodies move the texel grid
// stays put for most frames and shadow edges do not shimmer in animations.
ShadowFit fitShadow(const Eigen::Vector3f& direction, const BoundingSphere& bound, int map_size);

// The part of the plane z = height that the shadow map's box reaches, as a rectangle in world xy
// (the bounding box of the parallelogram where the box's prism along the light meets the plane):
// outside it nothing can be in shadow. nullopt when the light does not travel downwards, so no
// shadow falls on the plane.
std::optional<Eigen::AlignedBox2f> shadowFootprint(const ShadowFit& fit, float height);

}  // namespace tumble::render
