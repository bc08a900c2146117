// The camera of each frame: a follow camera chases its body critically damped (no overshoot, the
// exact lag of the closed form), an orbit camera sits where its angles say, a fit camera keeps
// every named body in view over the whole clip, and --camera names a camera that exists.
#include <catch2/catch.hpp>

#include <cmath>

#include "app/camera_rig.h"
#include "base/error.h"

using namespace tumble;
using Eigen::Vector3d;

namespace {

// Two bodies, the ground (0) and a ball (1) whose centre is `x(k)` at frame k, at `fps`.
template <class F>
Trajectory ballTrajectory(int frames, double fps, F x) {
  Trajectory t;
  t.body_names = {"ground", "ball"};
  for (int k = 0; k < frames; ++k) {
    t.times.push_back(k / fps);
    BodySample ground{Vector3d::Zero(), Eigen::Quaterniond::Identity(), Vector3d::Zero(), Vector3d::Zero()};
    BodySample ball = ground;
    ball.x = x(k);
    t.frames.push_back({ground, ball});
  }
  return t;
}

CameraSpec follow(double smoothing_s) {
  CameraSpec spec;
  spec.form = CameraSpec::Form::Follow;
  spec.follow_body = "ball";
  spec.offset_m = {0, -4, 1};
  spec.smoothing_s = smoothing_s;
  return spec;
}

Vector3d eye(const DrawCamera& c) { return c.eye.cast<double>(); }

}  // namespace

TEST_CASE("a follow camera without smoothing keeps its offset and looks at the body", "[camera]") {
  const Trajectory t = ballTrajectory(20, 30, [](int k) { return Vector3d(0.3 * k, 0, 1 + 0.01 * k * k); });
  const std::vector<DrawCamera> path = cameraPath(follow(0), t, {0, 0.5}, 4.0 / 3);
  REQUIRE(path.size() == 20);
  for (int k = 0; k < 20; ++k) {
    CHECK((eye(path[k]) - (t.frames[k][1].x + Vector3d(0, -4, 1))).norm() < 1e-5);
    CHECK((path[k].target.cast<double>() - t.frames[k][1].x).norm() < 1e-5);
  }
}

TEST_CASE("a follow camera lags a jump by the critically damped closed form, without overshoot", "[camera]") {
  // The ball jumps 10 m along x after the first frame and stays.
  const double fps = 30, tau = 0.3;
  const Trajectory t = ballTrajectory(120, fps, [](int k) { return Vector3d(k == 0 ? 0 : 10, 0, 1); });
  const std::vector<DrawCamera> path = cameraPath(follow(tau), t, {0, 0.5}, 4.0 / 3);
  double last = eye(path[0]).x();
  CHECK(last == Approx(0).margin(1e-6));
  for (int k = 1; k < 120; ++k) {
    const double time = k / fps, expected = 10 - 10 * (1 + time / tau) * std::exp(-time / tau);
    CHECK(eye(path[k]).x() == Approx(expected).margin(1e-4));
    CHECK(eye(path[k]).x() >= last);          // monotone: critically damped
    CHECK(eye(path[k]).x() <= 10 + 1e-5);     // never past the goal
    last = eye(path[k]).x();
  }
  CHECK(last == Approx(10).margin(1e-3));
}

TEST_CASE("an orbit camera sits at its distance, yaw and pitch from its target", "[camera]") {
  const Trajectory t = ballTrajectory(3, 30, [](int k) { return Vector3d(k, 0, 1); });
  CameraSpec spec;
  spec.form = CameraSpec::Form::Orbit;
  spec.target_m = {1, 2, 3};
  spec.distance_m = 5;
  spec.yaw_deg = 0;
  spec.pitch_deg = 0;
  CHECK((eye(cameraPath(spec, t, {0, 0.5}, 1)[0]) - Vector3d(1, -3, 3)).norm() < 1e-5);   // front: -y side
  spec.yaw_deg = 90;   // counter-clockwise seen from above: to +x
  CHECK((eye(cameraPath(spec, t, {0, 0.5}, 1)[0]) - Vector3d(6, 2, 3)).norm() < 1e-5);
  spec.yaw_deg = 0;
  spec.pitch_deg = 30;
  CHECK((eye(cameraPath(spec, t, {0, 0.5}, 1)[0]) - Vector3d(1, 2 - 5 * std::cos(M_PI / 6), 3 + 2.5)).norm() < 1e-5);
  spec.target_body = "ball";   // about a moving body
  const std::vector<DrawCamera> path = cameraPath(spec, t, {0, 0.5}, 1);
  CHECK((path[2].target.cast<double>() - Vector3d(2, 0, 1)).norm() < 1e-6);
}

TEST_CASE("a fit camera keeps every body of the clip inside its view at every frame", "[camera]") {
  const Trajectory t = ballTrajectory(30, 30, [](int k) { return Vector3d(-3 + 0.25 * k, 0.1 * k, 1 + 0.05 * k); });
  CameraSpec spec;
  spec.form = CameraSpec::Form::Fit;
  spec.fov_y_deg = 40;
  const double aspect = 16.0 / 9, radius = 0.5;
  const std::vector<DrawCamera> path = cameraPath(spec, t, {0, radius}, aspect);
  const double half = 20 * M_PI / 180;   // the narrower half angle: vertical, for a wide frame
  for (std::size_t k = 0; k < path.size(); ++k) {
    CHECK((eye(path[k]) - eye(path[0])).norm() == 0);   // one camera for the clip
    const Vector3d view = (path[k].target - path[k].eye).cast<double>().normalized();
    for (const std::vector<BodySample>& frame : t.frames) {
      const Vector3d to = frame[1].x - eye(path[k]);
      const double off_axis = std::acos(std::clamp(view.dot(to.normalized()), -1.0, 1.0));
      CHECK(off_axis + std::asin(radius / to.norm()) <= half + 1e-6);
    }
  }
}

TEST_CASE("render picks a named camera with --camera, or says which there are", "[camera]") {
  Scene scene;
  scene.cameras.push_back(CameraSpec{});
  scene.cameras.back().name = "follow";
  CHECK(&pickCamera(scene, "") == &scene.camera);
  CHECK(&pickCamera(scene, "follow") == &scene.cameras[0]);
  try {
    pickCamera(scene, "folow");
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::Usage);
    CHECK(std::string(e.what()) == "--camera: the scene has no camera named \"folow\"; did you mean \"follow\"?");
  }
}
