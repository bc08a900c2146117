// View and projection matrices in OpenGL's conventions (right-handed eye space looking down -z,
// clip depth in [-1, 1]), written out so there is no hidden dependency on GLU or GLM.
#pragma once

#include <Eigen/Core>

#include "render/draw_list.h"

namespace tumble::render {

// World -> eye. If `up` is (nearly) parallel to the view direction another axis is used, so a
// camera looking straight down the z axis still gets a valid frame.
Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up);

// Symmetric perspective frustum; fov_y in radians, aspect = width / height.
Eigen::Matrix4f perspective(float fov_y_rad, float aspect, float near_m, float far_m);

// Orthographic box [l, r] x [b, t] x [-n, -f] in eye space.
Eigen::Matrix4f ortho(float left, float right, float bottom, float top, float near_m,
                      float far_m);

// projection * view for a DrawCamera; throws Error(BadInput) for a degenerate camera.
Eigen::Matrix4f cameraViewProjection(const DrawCamera& camera, float aspect);

}  // namespace tumble::render
