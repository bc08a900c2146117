#include "render/camera_matrices.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "base/error.h"

namespace tumble::render {

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up) {
  const Eigen::Vector3f f = (target - eye).normalized();
  Eigen::Vector3f s = f.cross(up);
  // 1e-6 of |up|: below this the cross product is mostly rounding and s would point anywhere.
  if (s.squaredNorm() < 1e-12f * up.squaredNorm() || s.squaredNorm() == 0) {
    const Eigen::Vector3f other =
        std::abs(f.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
    s = f.cross(other);
  }
  s.normalize();
  const Eigen::Vector3f u = s.cross(f);

  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4f perspective(float fov_y_rad, float aspect, float near_m, float far_m) {
  const float g = 1.0f / std::tan(0.5f * fov_y_rad);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = g / aspect;
  m(1, 1) = g;
  m(2, 2) = (far_m + near_m) / (near_m - far_m);
  m(2, 3) = 2.0f * far_m * near_m / (near_m - far_m);
  m(3, 2) = -1.0f;
  return m;
}

Eigen::Matrix4f ortho(float left, float right, float bottom, float top, float near_m,
                      float far_m) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 2.0f / (right - left);
  m(1, 1) = 2.0f / (top - bottom);
  m(2, 2) = -2.0f / (far_m - near_m);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  m(2, 3) = -(far_m + near_m) / (far_m - near_m);
  return m;
}

Eigen::Matrix4f cameraViewProjection(const DrawCamera& camera, float aspect) {
  const bool fov_ok = camera.fov_y_deg > 0 && camera.fov_y_deg < 180;
  const bool depth_ok = camera.near_m > 0 && camera.far_m > camera.near_m;
  const bool eye_ok = (camera.target - camera.eye).squaredNorm() > 0 && camera.up.squaredNorm() > 0;
  if (!fov_ok || !depth_ok || !eye_ok || !camera.eye.allFinite() || !camera.target.allFinite()) {
    std::ostringstream msg;
    msg << "camera is degenerate: need 0 < fov_y_deg < 180 (got " << camera.fov_y_deg
        << "), 0 < near_m < far_m (got " << camera.near_m << ", " << camera.far_m
        << "), eye != target and a non-zero up vector";
    throw Error(ExitCode::BadInput, msg.str());
  }
  const float fov = camera.fov_y_deg * (std::numbers::pi_v<float> / 180.0f);
  return perspective(fov, aspect, camera.near_m, camera.far_m) *
         lookAt(camera.eye, camera.target, camera.up);
}

}  // namespace tumble::render
