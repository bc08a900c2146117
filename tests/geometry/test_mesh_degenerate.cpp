// Degenerate meshes, as hand-made files: each either becomes a valid convex piece (with a warning
// when it had to be hulled) or is refused with BadInput and a message that names the file and says
// what is wrong. None may crash or produce a piece with NaN or no volume.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_import.h"
#include "piece_validity.h"

using namespace tumble;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name, const std::string& content) {
  const fs::path dir = fs::path(TUMBLE_BINARY_DIR) / "test_mesh_degenerate_tmp";
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << content;
  return dir / name;
}

// A unit tetrahedron's faces, for the OBJ files below (vertices 1..4).
const char* kTetraFaces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string tetra(const std::string& a, const std::string& b, const std::string& c, const std::string& d) {
  return "o T\nv " + a + "\nv " + b + "\nv " + c + "\nv " + d + "\n" + kTetraFaces;
}

}  // namespace

TEST_CASE("degenerate meshes are refused with a message naming the file and the fault", "[import]") {
  struct Case {
    const char* what;
    const char* file;
    std::string text;
    const char* expected;   // a substring of the message
  };
  const Case cases[] = {
      {"an empty file", "empty.obj", "", "assimp could not read it"},
      {"an object without faces", "no_faces.obj", "o Nothing\nv 0 0 0\nv 1 0 0\n", "assimp could not read it"},
      {"a single triangle", "one_triangle.obj", "o Tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "spans no volume"},
      {"a flat square", "coplanar.obj", "o Flat\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nf 3 2 1\nf 4 3 1\n",
       "spans no volume"},
      {"collinear points", "collinear.obj", tetra("0 0 0", "1 1 1", "2 2 2", "3 3 3"), "spans no volume"},
      {"one point repeated", "coincident.obj", tetra("1 2 3", "1 2 3", "1 2 3", "1 2 3"), "is 0 m across"},
      {"a coordinate beyond float range", "overflow.obj", tetra("0 0 0", "1e39 0 0", "0 1 0", "0 0 1"),
       "NaN or infinite"},
      {"a body a billion kilometres across", "huge.obj", tetra("0 0 0", "1e12 0 0", "0 1e12 0", "0 0 1e12"),
       "across"},
      // Found by fuzzing: 3 km long, 4e-5 m thick, 1e7 m out; the hull merged it down to nothing.
      {"a sliver thinner than the hull's merge tolerance", "sliver.obj",
       tetra("9996928 0 0", "10000001 0 0", "10000000 1 0", "10000000 0 4.38690185546875e-05"), "spans no volume"},
      {"a body smaller than a micrometre", "tiny.obj", tetra("0 0 0", "1e-9 0 0", "0 1e-9 0", "0 0 1e-9"),
       "across"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const fs::path file = scratch(c.file, c.text);
    try {
      importConvexPieces(file);
      FAIL("no error");
    } catch (const Error& e) {
      CHECK(e.code() == ExitCode::BadInput);
      CHECK_THAT(e.what(), Catch::Contains(file.string()) && Catch::Contains(c.expected));
    }
  }
}

TEST_CASE("duplicate vertices and reversed winding change nothing", "[import]") {
  // Every corner written three times, once per face that uses it, as STL does; faces inside out.
  std::string text = "o Dup\n";
  const char* corners[] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
  const int faces[4][3] = {{1, 2, 3}, {1, 4, 2}, {1, 3, 4}, {2, 4, 3}};   // inward: reversed
  for (const auto& f : faces)
    for (int v : f) text += std::string("v ") + corners[v - 1] + "\n";
  for (int i = 0; i < 4; ++i)
    text += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " + std::to_string(3 * i + 3) + "\n";
  const ImportedPieces in = importConvexPieces(scratch("duplicates.obj", text));
  REQUIRE(in.pieces.size() == 1);
  CHECK(in.warnings.empty());
  CHECK(in.pieces[0].vertices.size() == 4);
  CHECK(volume(in.pieces[0]) == Approx(1.0 / 6));
  CHECK(test::convexPieceProblem(in.pieces[0]).empty());
}

TEST_CASE("a large body far from the origin still gives a valid piece", "[import]") {
  // 1000 km across, 100000 km out: float32 keeps ~7 digits, enough for a hull of this size.
  const ImportedPieces in = importConvexPieces(
      scratch("large.obj", tetra("1e8 0 0", "1.001e8 0 0", "1e8 1e6 0", "1e8 0 1e6")));
  REQUIRE(in.pieces.size() == 1);
  CHECK(test::convexPieceProblem(in.pieces[0]).empty());
  // The volume integrals lose digits 1e8 m out (products of ~1e8 coordinates); bodies are moved
  // to their centre of mass before anything else uses them.
  CHECK(volume(in.pieces[0]) == Approx(1e5 * 1e6 * 1e6 / 6).epsilon(1e-3));
}

TEST_CASE("non-manifold and non-convex meshes are hulled with a warning", "[import]") {
  // Two tetrahedra touching at one corner (a non-manifold vertex), written as one object.
  const std::string bowtie =
      "o Bowtie\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 6 5\nf 1 5 7\nf 1 7 6\nf 5 6 7\n";
  // A cube with a fin: an extra triangle through its middle (a non-manifold edge).
  const std::string fin =
      "o Fin\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\nf 1 7 5\n";
  for (const auto& [name, text] : {std::pair{"bowtie.obj", bowtie}, std::pair{"fin.obj", fin}}) {
    INFO(name);
    const ImportedPieces in = importConvexPieces(scratch(name, text));
    REQUIRE(in.pieces.size() == 1);
    REQUIRE(in.warnings.size() == 1);
    CHECK_THAT(in.warnings[0], Catch::Contains("not convex; using its convex hull"));
    CHECK(test::convexPieceProblem(in.pieces[0]).empty());
  }
}
