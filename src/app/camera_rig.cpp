#include "app/camera_rig.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.h"
#include "scene/suggest.h"

namespace tumble {
namespace {

using Eigen::Vector3d;

DrawCamera fixedCamera(const CameraSpec& spec) {
  DrawCamera cam;
  cam.eye = spec.position_m.cast<float>();
  if (spec.orientation) {
    // The camera looks along its own -z with +y up (the OpenGL and Blender camera convention).
    Eigen::Matrix3d R = spec.orientation->toRotationMatrix();
    cam.target = (spec.position_m - R.col(2)).cast<float>();
    cam.up = R.col(1).cast<float>();
  } else {
    cam.target = spec.look_at_m->cast<float>();
    cam.up = spec.up.normalized().cast<float>();
  }
  cam.fov_y_deg = static_cast<float>(spec.fov_y_deg);
  return cam;
}

DrawCamera lookingAt(const CameraSpec& spec, const Vector3d& eye, const Vector3d& target) {
  DrawCamera cam;
  cam.eye = eye.cast<float>();
  cam.target = target.cast<float>();
  cam.up = spec.up.normalized().cast<float>();
  cam.fov_y_deg = static_cast<float>(spec.fov_y_deg);
  // Far enough for the target and the ground beyond it at any distance the scene allows.
  cam.far_m = static_cast<float>(std::max(500.0, 4 * (eye - target).norm()));
  return cam;
}

// Unit vector from the target to the camera (scene.h: yaw 0 on the -y side, counter-clockwise).
Vector3d fromAngles(double yaw_deg, double pitch_deg) {
  const double yaw = yaw_deg * M_PI / 180, pitch = pitch_deg * M_PI / 180;
  return {std::sin(yaw) * std::cos(pitch), -std::cos(yaw) * std::cos(pitch), std::sin(pitch)};
}

int bodyIndex(const Trajectory& t, const std::string& name) {
  const auto it = std::find(t.body_names.begin(), t.body_names.end(), name);
  if (it == t.body_names.end())   // the loader checked every name a camera gives
    throw Error(ExitCode::Software, "camera: no body \"" + name + "\" in the trajectory");
  return static_cast<int>(it - t.body_names.begin());
}

// A camera that keeps `offset` from the body and looks at it. Its position chases the goal
// g = x_body + offset as a critically damped spring of time constant tau (omega = 1 / tau):
// e'' = -omega^2 e - 2 omega e' for the error e = p - g, whose exact solution over a step h with
// g held at the step's end is
//   e(h) = (e0 + (v0 + omega e0) h) exp(-omega h),   v(h) = (v0 - omega (v0 + omega e0) h) exp(-omega h).
// Exact, so the lag does not depend on the frame rate's step, and it never overshoots.
std::vector<DrawCamera> followPath(const CameraSpec& spec, const Trajectory& t) {
  const int body = bodyIndex(t, spec.follow_body);
  std::vector<DrawCamera> path;
  Vector3d p = t.frames.front()[body].x + spec.offset_m, v = Vector3d::Zero();
  for (std::size_t k = 0; k < t.frames.size(); ++k) {
    const Vector3d centre = t.frames[k][body].x, goal = centre + spec.offset_m;
    const double h = k == 0 ? 0 : t.times[k] - t.times[k - 1];
    if (spec.smoothing_s <= 0) {
      p = goal;
    } else if (h > 0) {
      const double omega = 1 / spec.smoothing_s, decay = std::exp(-omega * h);
      const Vector3d e0 = p - goal, a = v + omega * e0;
      p = goal + (e0 + a * h) * decay;
      v = (v - omega * a * h) * decay;
    }
    path.push_back(lookingAt(spec, p, centre));
  }
  return path;
}

std::vector<DrawCamera> orbitPath(const CameraSpec& spec, const Trajectory& t) {
  const int body = spec.target_body.empty() ? -1 : bodyIndex(t, spec.target_body);
  const Vector3d direction = fromAngles(spec.yaw_deg, spec.pitch_deg);
  std::vector<DrawCamera> path;
  for (const std::vector<BodySample>& frame : t.frames) {
    const Vector3d target = body < 0 ? spec.target_m : frame[body].x;
    path.push_back(lookingAt(spec, target + spec.distance_m * direction, target));
  }
  return path;
}

// One camera for the whole clip: the box around every named body at every frame (each as a sphere
// of its radius about its centre of mass), its bounding sphere seen from the spec's yaw and pitch
// at the distance where that sphere just fits the narrower of the two fields of view.
std::vector<DrawCamera> fitPath(const CameraSpec& spec, const Trajectory& t, const std::vector<double>& radius,
                                double aspect) {
  std::vector<int> bodies;
  for (const std::string& name : spec.fit_bodies) bodies.push_back(bodyIndex(t, name));
  if (bodies.empty())
    for (std::size_t b = 0; b < radius.size(); ++b)
      if (radius[b] > 0) bodies.push_back(static_cast<int>(b));   // the ground has no radius
  Vector3d lo = Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const std::vector<BodySample>& frame : t.frames)
    for (int b : bodies) {
      lo = lo.cwiseMin(frame[b].x - Vector3d::Constant(radius[b]));
      hi = hi.cwiseMax(frame[b].x + Vector3d::Constant(radius[b]));
    }
  if (bodies.empty()) lo = hi = spec.target_m;
  const Vector3d centre = 0.5 * (lo + hi);
  const double r = std::max(0.5 * (hi - lo).norm(), 1e-3);
  const double half_y = 0.5 * spec.fov_y_deg * M_PI / 180;
  const double half = std::min(half_y, std::atan(aspect * std::tan(half_y)));
  const DrawCamera cam = lookingAt(spec, centre + r / std::sin(half) * fromAngles(spec.yaw_deg, spec.pitch_deg), centre);
  return std::vector<DrawCamera>(t.frames.size(), cam);
}

}  // namespace

std::vector<DrawCamera> cameraPath(const CameraSpec& spec, const Trajectory& trajectory,
                                   const std::vector<double>& body_radius_m, double aspect) {
  switch (spec.form) {
    case CameraSpec::Form::Follow: return followPath(spec, trajectory);
    case CameraSpec::Form::Orbit: return orbitPath(spec, trajectory);
    case CameraSpec::Form::Fit: return fitPath(spec, trajectory, body_radius_m, aspect);
    case CameraSpec::Form::Fixed: break;
  }
  return std::vector<DrawCamera>(trajectory.frames.size(), fixedCamera(spec));
}

const char* cameraFormName(CameraSpec::Form form) {
  switch (form) {
    case CameraSpec::Form::Orbit: return "orbit";
    case CameraSpec::Form::Follow: return "follow";
    case CameraSpec::Form::Fit: return "fit";
    case CameraSpec::Form::Fixed: break;
  }
  return "fixed";
}

const CameraSpec& pickCamera(const Scene& scene, const std::string& name) {
  if (name.empty()) return scene.camera;
  std::vector<std::string> names;
  for (const CameraSpec& c : scene.cameras) {
    if (c.name == name) return c;
    names.push_back(c.name);
  }
  std::string message = "--camera: the scene has no camera named \"" + name + "\"";
  if (names.empty()) message += " (it has no \"cameras\")";
  if (const std::string near = closestMatch(name, names); !near.empty()) message += "; did you mean \"" + near + "\"?";
  throw Error(ExitCode::Usage, message);
}

}  // namespace tumble
