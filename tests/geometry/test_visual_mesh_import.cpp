// The visual mesh is the file as its author made it: every mesh with its node transforms, its own
// normals (or flat ones), texture coordinates and each material's base colour and texture.
#include <catch2/catch.hpp>

#include <filesystem>

#include "base/error.h"
#include "geometry/visual_mesh_import.h"

using namespace tumble;

namespace {

const std::filesystem::path kAssets = std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests" / "assets";

const VisualPart* partNamed(const VisualMesh& mesh, const Eigen::Vector3f& colour) {
  for (const VisualPart& p : mesh.parts)
    if (p.base_colour && p.base_colour->isApprox(colour, 1e-5f)) return &p;
  return nullptr;
}

}  // namespace

TEST_CASE("a glTF mesh keeps its node transforms, normals, texture coordinates and embedded texture", "[visual]") {
  const VisualMesh mesh = importVisualMesh(kAssets / "textured_box.gltf", 2.0);
  REQUIRE(mesh.parts.size() == 1);
  const VisualPart& box = mesh.parts[0];
  CHECK(box.positions.size() == 36);   // 6 faces of 2 triangles
  REQUIRE(box.normals.size() == 36);
  REQUIRE(box.uvs.size() == 36);
  // The parent node raises the 0.6 m box by 0.1 m; the scale doubles both.
  float lo = 1e9f, hi = -1e9f;
  for (const Eigen::Vector3f& p : box.positions) lo = std::min(lo, p.z()), hi = std::max(hi, p.z());
  CHECK(lo == Approx(-0.4));
  CHECK(hi == Approx(0.8));
  REQUIRE(box.base_colour);
  CHECK(box.base_colour->isApprox(Eigen::Vector3f(1.0f, 0.9f, 0.9f)));
  REQUIRE(box.texture);
  CHECK(box.texture->file.empty());
  CHECK(box.texture->encoded.size() > 50);   // the PNG held in the file's data URI
  CHECK_THAT(box.texture->label, Catch::Contains("textured_box.gltf: embedded texture"));
  // glTF's v runs down the image; assimp hands out OpenGL's, up: the top face's corner at -x,-y
  // was written (0, 1) in the file and reads (0, 0).
  for (std::size_t i = 0; i < box.positions.size(); ++i)
    if (box.normals[i].z() > 0.5f && box.positions[i].x() < 0 && box.positions[i].y() < 0)
      CHECK(box.uvs[i].isApprox(Eigen::Vector2f(0, 0)));
}

TEST_CASE("an OBJ mesh has one part per MTL material, with Kd and a map_Kd file beside it", "[visual]") {
  const VisualMesh mesh = importVisualMesh(kAssets / "mtl_box.obj", 1.0);
  REQUIRE(mesh.parts.size() == 3);
  const VisualPart* striped = partNamed(mesh, {1, 1, 1});
  const VisualPart* top = partNamed(mesh, {0.05f, 0.2f, 0.8f});
  REQUIRE(striped);
  REQUIRE(top);
  CHECK(top->positions.size() == 6);
  CHECK(striped->positions.size() == 24);
  REQUIRE(striped->texture);
  CHECK(striped->texture->file == (kAssets / "stripes.png").lexically_normal());
  CHECK_FALSE(top->texture);
}

TEST_CASE("smooth normals in a file stay smooth, and a file without normals is drawn flat", "[visual]") {
  const VisualMesh torus = importVisualMesh(kAssets / "torus.obj", 1.0);
  REQUIRE(torus.parts.size() == 1);
  CHECK_FALSE(torus.parts[0].base_colour);   // no material: the body's colour is used
  const auto& n = torus.parts[0].normals;
  bool differ_within_a_triangle = false;
  for (std::size_t t = 0; t + 2 < n.size(); t += 3)
    differ_within_a_triangle |= !n[t].isApprox(n[t + 1], 1e-4f);
  CHECK(differ_within_a_triangle);

  const VisualMesh flat = importVisualMesh(kAssets / "bad_texture.obj", 1.0);   // no vn lines
  for (const VisualPart& part : flat.parts)
    for (std::size_t t = 0; t + 2 < part.normals.size(); t += 3) {
      CHECK(part.normals[t].isApprox(part.normals[t + 1]));
      CHECK(part.normals[t].isApprox(part.normals[t + 2]));
      const Eigen::Vector3f face =
          (part.positions[t + 1] - part.positions[t]).cross(part.positions[t + 2] - part.positions[t]).normalized();
      CHECK(part.normals[t].isApprox(face));   // outward: the winding is counter-clockwise
    }
}

TEST_CASE("a file assimp cannot read is a named error", "[visual]") {
  try {
    importVisualMesh(kAssets / "not_an_image.png", 1.0);
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::Contains("not_an_image.png"));
  }
}
