// The renderer's GL-free parts: matrices, shadow fitting, instance packing, pixel conversion.
#include <catch2/catch.hpp>

#include "base/error.h"
#include "box_mesh.h"
#include "render/camera_matrices.h"
#include "render/instance_data.h"
#include "render/pixel_convert.h"
#include "render/shadow_fit.h"

using namespace tumble;
using namespace tumble::render;

namespace {

Eigen::Vector3f project(const Eigen::Matrix4f& m, const Eigen::Vector3f& p) {
  const Eigen::Vector4f c = m * p.homogeneous();
  return c.head<3>() / c.w();
}

}  // namespace

TEST_CASE("lookAt puts the eye at the origin and the target on -z", "[render]") {
  const Eigen::Vector3f eye(6, -8, 4), target(0, 0, 0.5f);
  const Eigen::Matrix4f v = lookAt(eye, target, Eigen::Vector3f::UnitZ());
  CHECK((v * eye.homogeneous()).head<3>().norm() < 1e-5f);
  const Eigen::Vector3f t = (v * target.homogeneous()).head<3>();
  CHECK(std::abs(t.x()) < 1e-5f);
  CHECK(std::abs(t.y()) < 1e-5f);
  CHECK(t.z() == Approx(-(target - eye).norm()));
  // World up stays up on screen.
  CHECK((v * Eigen::Vector4f(0, 0, 1, 0)).y() > 0);
}

TEST_CASE("lookAt straight down still gives a rotation", "[render]") {
  const Eigen::Matrix4f v = lookAt({0, 0, 5}, {0, 0, 0}, Eigen::Vector3f::UnitZ());
  const Eigen::Matrix3f r = v.block<3, 3>(0, 0);
  CHECK((r * r.transpose() - Eigen::Matrix3f::Identity()).norm() < 1e-5f);
}

TEST_CASE("perspective maps near to -1 and far to +1", "[render]") {
  const Eigen::Matrix4f p = perspective(0.8f, 1.5f, 0.1f, 100.0f);
  CHECK(project(p, {0, 0, -0.1f}).z() == Approx(-1).margin(1e-5));
  CHECK(project(p, {0, 0, -100.0f}).z() == Approx(1).margin(1e-4));
}

TEST_CASE("the shadow box holds the bodies' bounding sphere", "[render]") {
  const DrawMesh box = test::boxMesh({0.5f, 0.5f, 0.5f});
  std::vector<DrawInstance> instances(2);
  instances[0].model.translation() = Eigen::Vector3f(-2, 0, 1);
  instances[1].model.translation() = Eigen::Vector3f(3, 1, 0.5f);
  const float r = std::sqrt(0.75f);
  const auto bound = boundInstances(instances, {{Eigen::Vector3f::Zero(), r}});
  REQUIRE(bound);
  const ShadowFit fit = fitShadow({-0.4f, 0.3f, -1}, *bound, 1024);
  for (const auto& inst : instances) {
    for (const auto& p : box.positions) {
      const Eigen::Vector3f c = project(fit.view_projection, inst.model * p);
      CHECK(c.cwiseAbs().maxCoeff() <= 1.0f);
    }
  }
  // Tight: the box is at most ~9 % (radius rounding) + 2 texels wider than the sphere.
  CHECK(fit.texel_m * 1024 / 2 < bound->radius * 1.1f);
}

TEST_CASE("instances are grouped by mesh, stably", "[render]") {
  std::vector<DrawInstance> instances(3);
  instances[0].mesh = 1;
  instances[0].colour = {1, 0, 0};
  instances[1].mesh = 0;
  instances[2].mesh = 1;
  instances[2].colour = {0, 0, 1};
  PackedInstances packed;
  packInstances(instances, 2, Eigen::Vector3f::Zero(), packed);
  REQUIRE(packed.batches.size() == 2);
  CHECK(packed.batches[1].mesh == 1);
  CHECK(packed.batches[1].first == 1);
  CHECK(packed.batches[1].count == 2);
  CHECK(packed.data[1 * kInstanceFloats + 16] == 1.0f);  // red instance first
  CHECK(packed.data[2 * kInstanceFloats + 18] == 1.0f);  // then the blue one

  instances[0].mesh = 5;
  CHECK_THROWS_AS(packInstances(instances, 2, Eigen::Vector3f::Zero(), packed), Error);
}

TEST_CASE("read-back pixels are flipped to top-first RGB", "[render]") {
  // 1x2 RGBA, bottom row first as GL returns it.
  const std::vector<std::uint8_t> rgba = {1, 2, 3, 255, 4, 5, 6, 255};
  RgbImage img;
  rgbaBottomUpToRgbTopDown(rgba, 1, 2, img);
  CHECK(img.pixels == std::vector<std::uint8_t>{4, 5, 6, 1, 2, 3});
}

TEST_CASE("sRGB encoding matches the standard's reference points", "[render]") {
  CHECK(encodeSrgb(0.0f) == 0.0f);
  CHECK(encodeSrgb(1.0f) == Approx(1.0f));
  CHECK(encodeSrgb(0.5f) == Approx(0.7354f).margin(1e-3));
  CHECK(encodeSrgb(0.002f) == Approx(0.02584f).margin(1e-5));
}
