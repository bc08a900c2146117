// Mesh import: the shipped assets in every format we use, non-convex meshes, and the errors a
// user can cause.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_import.h"
#include "piece_checks.h"

using namespace tumble;
namespace fs = std::filesystem;

namespace {

// Mesh files store float32: coordinates are rounded at 2^-24 ~ 6e-8 relative, so a volume (three
// coordinates multiplied) is good to ~2e-7; 1e-6 leaves a margin without hiding a real error.
constexpr double kFloat = 1e-6;

fs::path asset(const std::string& name) { return fs::path(TUMBLE_SOURCE_DIR) / "assets" / name; }

fs::path scratch(const std::string& name, const std::string& content) {
  const fs::path dir = fs::path(TUMBLE_BINARY_DIR) / "test_geometry_tmp";
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << content;
  return dir / name;
}

ExitCode codeOf(const fs::path& file) {
  try {
    importConvexPieces(file);
  } catch (const Error& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find(file.string()) != std::string::npos);  // names the file
    return e.code();
  }
  return ExitCode::Ok;
}

std::string messageOf(const fs::path& file) {
  try {
    importConvexPieces(file);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("assets: t_handle.obj is two boxes", "[import]") {
  const ImportedPieces in = importConvexPieces(asset("t_handle.obj"));
  REQUIRE(in.pieces.size() == 2);
  CHECK(in.warnings.empty());
  CHECK(in.pieces[0].name == "Crossbar");
  CHECK(in.pieces[1].name == "Shaft");
  CHECK(volume(in.pieces[0]) == Approx(0.8 * 0.1 * 0.1).epsilon(kFloat));
  CHECK(volume(in.pieces[1]) == Approx(0.1 * 0.1 * 0.5).epsilon(kFloat));
  for (const ConvexPiece& p : in.pieces) {
    CHECK(p.faces.size() == 6);
    test::checkConvexPiece(p);
  }
  // Three distinct principal moments: the intermediate-axis instability can show.
  const PrincipalFrame f = principalFrame(massProperties(in.pieces, 1000).inertia);
  // Moments 0.399, 0.442, 0.819 kg m^2 at 1000 kg/m^3: a spin about the middle axis flips at
  // a rate sqrt((I2 - I1)(I3 - I2) / (I1 I3)) ~ 0.22 of the spin rate.
  CHECK(f.moments[1] - f.moments[0] > 0.05 * f.moments[2]);
  CHECK(f.moments[2] - f.moments[1] > 0.05 * f.moments[2]);
}

TEST_CASE("assets: every other shipped mesh loads as one convex piece", "[import]") {
  struct Case { const char* file; double volume; size_t vertices, faces; };
  const Case c = GENERATE(Case{"tetra.stl", 0.007, 4, 4}, Case{"wedge.obj", 0.015, 6, 5},
                          Case{"gem.ply", 0.003427277761408572, 20, 36},
                          Case{"pyramid.gltf", 0.016, 5, 5});
  INFO(c.file);
  const ImportedPieces in = importConvexPieces(asset(c.file));
  REQUIRE(in.pieces.size() == 1);
  CHECK(in.warnings.empty());
  CHECK(volume(in.pieces[0]) == Approx(c.volume).epsilon(kFloat));
  CHECK(in.pieces[0].vertices.size() == c.vertices);
  CHECK(in.pieces[0].faces.size() == c.faces);
  test::checkConvexPiece(in.pieces[0]);
}

TEST_CASE("glTF node transforms are applied and scale multiplies lengths", "[import]") {
  // The pyramid sits at x = 0.5 by its node's translation; its centroid is a quarter of the
  // height (0.3 m, glTF's +y) above the base.
  const MassProperties mp = massProperties(importConvexPieces(asset("pyramid.gltf")).pieces, 1);
  CHECK(mp.center.x() == Approx(0.5).epsilon(kFloat));
  CHECK(mp.center.y() == Approx(0.075).epsilon(kFloat));
  const ImportedPieces twice = importConvexPieces(asset("t_handle.obj"), 2.0);
  CHECK(volume(twice.pieces[1]) == Approx(8 * 0.005).epsilon(kFloat));
}

TEST_CASE("an object with two materials is still one piece", "[import]") {
  // assimp splits it into one aiMesh per material; the piece is the object.
  const fs::path file = scratch("two_materials.obj", R"(o Lidded
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
v 0 0 1
v 1 0 1
v 0 1 1
v 1 1 1
usemtl body
f 1 5 7 3
f 2 4 8 6
f 1 2 6 5
f 3 7 8 4
f 1 3 4 2
usemtl lid
f 5 6 8 7
)");
  const ImportedPieces in = importConvexPieces(file);
  REQUIRE(in.pieces.size() == 1);
  CHECK(in.warnings.empty());
  CHECK(in.pieces[0].name == "Lidded");
  CHECK(volume(in.pieces[0]) == Approx(1.0).epsilon(kFloat));
}

TEST_CASE("a non-convex mesh is hulled, with a warning", "[import]") {
  // An L-shaped prism 0.2 m deep: squares (0,0)-(2,1) and (0,1)-(1,2) in xz, in decimetres.
  const fs::path file = scratch("l_shape.obj", R"(o Ell
v 0 0 0
v 0.2 0 0
v 0.2 0 0.1
v 0.1 0 0.1
v 0.1 0 0.2
v 0 0 0.2
v 0 0.2 0
v 0.2 0.2 0
v 0.2 0.2 0.1
v 0.1 0.2 0.1
v 0.1 0.2 0.2
v 0 0.2 0.2
f 1 2 3 4 5 6
f 7 12 11 10 9 8
f 1 7 8 2
f 2 8 9 3
f 3 9 10 4
f 4 10 11 5
f 5 11 12 6
f 6 12 7 1
)");
  const ImportedPieces in = importConvexPieces(file);
  REQUIRE(in.pieces.size() == 1);
  REQUIRE(in.warnings.size() == 1);
  CHECK(in.warnings[0] == "mesh 'Ell' (1 of 1) in " + file.string() +
                              " is not convex; using its convex hull");
  // The hull fills in the notch's triangle (0.1 x 0.1 / 2) along the 0.2 m depth.
  CHECK(volume(in.pieces[0]) == Approx(0.2 * (0.03 + 0.005)).epsilon(kFloat));
  test::checkConvexPiece(in.pieces[0]);
}

TEST_CASE("import errors carry the exit code and name the file", "[import]") {
  CHECK(codeOf(asset("no_such_mesh.obj")) == ExitCode::MissingInput);
  CHECK(messageOf(asset("no_such_mesh.obj")).find("no such file") != std::string::npos);
  CHECK(codeOf(fs::path(TUMBLE_SOURCE_DIR) / "assets") == ExitCode::MissingInput);
  CHECK(codeOf(scratch("garbage.stl", std::string("\x01\x02 definitely not a mesh \xff", 27))) ==
        ExitCode::BadInput);
  CHECK(codeOf(scratch("garbage.obj", "hello world\nthis is not an obj\n")) == ExitCode::BadInput);
  // A PLY header cut short: assimp 5.2 alone would never return.
  CHECK(codeOf(scratch("garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\n")) ==
        ExitCode::BadInput);
  CHECK(codeOf(scratch("cut.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                                  "property float x\n")) == ExitCode::BadInput);
  const fs::path triangle = scratch("triangle.obj", "o Tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(codeOf(triangle) == ExitCode::BadInput);
  CHECK(messageOf(triangle) == "mesh 'Tri' in " + triangle.string() +
                                   " spans no volume (all points coplanar); a convex piece "
                                   "needs volume");
  CHECK(codeOf(scratch("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n")) ==
        ExitCode::BadInput);
  CHECK(codeOf(scratch("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 1\nf 1 2 3\nf 1 2 4\n"
                                  "f 1 3 4\nf 2 3 4\n")) == ExitCode::BadInput);
}

TEST_CASE("a non-positive scale is refused", "[import]") {
  CHECK_THROWS_AS(importConvexPieces(asset("tetra.stl"), 0.0), Error);
  CHECK_THROWS_AS(importConvexPieces(asset("tetra.stl"), -1.0), Error);
}
