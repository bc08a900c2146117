// libFuzzer target: any bytes as one mesh, after assimp has read it (float coordinates and
// triangles), turned into a convex piece as the importer does (convexPieceOf: checks, quickhull,
// convexity test), then its mass properties. Each input must give a valid convex piece with finite,
// positive mass properties, or a tumble::Error; anything else is a finding.
//
// Layout: byte 0 = number of points n (1..64); then n points of three little-endian float32
// (as assimp stores them); then triangles of three bytes each, indices taken modulo n.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "base/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_import.h"
#include "piece_validity.h"

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_mesh_pieces: %s\n", what.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t n = std::size_t(data[0] % 64) + 1;
  if (size < 1 + 12 * n) return 0;
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < n; ++i) {
    float xyz[3];
    std::memcpy(xyz, data + 1 + 12 * i, sizeof xyz);
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t at = 1 + 12 * n; at + 3 <= size; at += 3)
    triangles.push_back({int(data[at] % n), int(data[at + 1] % n), int(data[at + 2] % n)});
  try {
    std::string warning;
    tumble::ConvexPiece piece = tumble::convexPieceOf("fuzz", points, triangles, "fuzz.obj", &warning);
    if (std::string problem = tumble::test::convexPieceProblem(piece); !problem.empty())
      finding("invalid piece: " + problem);
    tumble::MassProperties mp = tumble::massProperties(piece, 1000);
    if (!(std::isfinite(mp.mass) && mp.mass > 0) || !mp.center.allFinite() || !mp.inertia.allFinite())
      finding("mass properties not finite and positive");
    tumble::PrincipalFrame frame = tumble::principalFrame(mp.inertia);
    if (!frame.rotation.allFinite() || !(frame.moments.minCoeff() > 0)) finding("bad principal frame");
  } catch (const tumble::Error& e) {
    if (std::string(e.what()).find("fuzz.obj") == std::string::npos) finding(std::string("unnamed error: ") + e.what());
  }
  return 0;
}
