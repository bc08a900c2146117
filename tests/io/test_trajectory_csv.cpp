#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include "base/error.h"
#include "error_code.h"
#include "io/trajectory_csv.h"
#include "temp_dir.h"

using namespace tumble;
namespace fs = std::filesystem;
using test::codeOf;

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

}  // namespace

TEST_CASE("trajectory CSV round trip is bit-exact", "[io][csv]") {
  test::TempDir dir;
  const double tricky[13] = {0.1, 1e-300, -0.0, 1.0 / 3, 5e-324,
                             std::numeric_limits<double>::max(), -2.5, 1e300, 0.0,
                             123456789.0123, std::nextafter(1.0, 2.0), -1e-7, 0.30000000000000004};
  const std::vector<std::string> names = {"cube", "a,b", "say \"hi\"", "two\nlines"};
  {
    CsvTrajectoryWriter writer(dir / "t.csv", false);
    for (std::size_t i = 0; i < names.size(); ++i) writer.row(0.1 * i, names[i], tricky);
    writer.close();
  }
  std::vector<TrajectoryRow> rows = readTrajectoryCsv(dir / "t.csv");
  REQUIRE(rows.size() == names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    CHECK(rows[i].body == names[i]);
    CHECK(sameBits(rows[i].time, 0.1 * i));
    for (int k = 0; k < 13; ++k) CHECK(sameBits(rows[i].v[k], tricky[k]));
  }
  std::string text = slurp(dir / "t.csv");
  CHECK(text.rfind("time,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n"
                   "0,cube,0.1,1e-300,-0,", 0) == 0);
  CHECK(text.find("\"a,b\"") != std::string::npos);
  CHECK(text.find("\"say \"\"hi\"\"\"") != std::string::npos);
}

TEST_CASE("trajectory CSV is written atomically and refuses to overwrite", "[io][csv]") {
  test::TempDir dir;
  const double zeros[13] = {};
  {
    CsvTrajectoryWriter writer(dir / "t.csv", false);
    writer.row(0, "a", zeros);
    CHECK_FALSE(fs::exists(dir / "t.csv"));
  }   // never closed: nothing remains
  CHECK(fs::is_empty(dir.path()));
  CsvTrajectoryWriter first(dir / "t.csv", false);
  first.close();
  CHECK(codeOf([&] { CsvTrajectoryWriter(dir / "t.csv", false); }) == ExitCode::CantCreate);
  CHECK(codeOf([&] { CsvTrajectoryWriter(dir / "missing/t.csv", true); }) == ExitCode::CantCreate);
  CsvTrajectoryWriter again(dir / "t.csv", true);
  again.row(1, "b", zeros);
  again.close();
  CHECK(readTrajectoryCsv(dir / "t.csv").size() == 1);
}

// A device or pipe is a stream: written in place. Renaming a finished temporary file onto its name,
// as for files, replaced /dev/full with a regular file (root may write in /dev), and would replace
// the /dev/stdout link.
TEST_CASE("a trajectory to a device or a link to one is streamed in place, the device kept", "[io][csv]") {
  test::TempDir dir;
  const double zeros[13] = {};
  fs::create_symlink("/dev/null", dir / "link.csv");   // as /dev/stdout links to /proc/self/fd/1
  for (fs::path target : {fs::path("/dev/null"), dir / "link.csv"}) {
    INFO(target);
    CsvTrajectoryWriter writer(target, /*overwrite*/ false);   // a stream is not a file to keep
    writer.row(0, "a", zeros);
    writer.close();
  }
  CHECK(fs::is_character_file(fs::symlink_status("/dev/null")));
  CHECK(fs::is_symlink(fs::symlink_status(dir / "link.csv")));
  CHECK(fs::read_symlink(dir / "link.csv") == "/dev/null");
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);   // no temp left
}

TEST_CASE("a full device is a clear error naming it, and stays a device", "[io][csv]") {
  if (!fs::is_character_file("/dev/full")) {
    WARN("skipped: no /dev/full on this machine");
    return;
  }
  const double zeros[13] = {};
  CsvTrajectoryWriter writer("/dev/full", true);
  writer.row(0, "a", zeros);
  try {
    writer.close();
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::CantCreate);
    CHECK_THAT(e.what(), Catch::StartsWith("cannot write /dev/full: No space left on device"));
  }
  CHECK(fs::is_character_file(fs::symlink_status("/dev/full")));
}

TEST_CASE("an output name taken by a folder is refused before writing, even with overwrite", "[io][csv]") {
  test::TempDir dir;
  fs::create_directory(dir / "t.csv");
  try {
    CsvTrajectoryWriter writer(dir / "t.csv", true);
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::CantCreate);
    CHECK_THAT(e.what(), Catch::EndsWith("t.csv: it is a folder, not a file; tumble replaces only files (choose another name)"));
  }
  CHECK(fs::is_directory(dir / "t.csv"));
}

TEST_CASE("reading a malformed trajectory CSV names the line", "[io][csv]") {
  test::TempDir dir;
  CHECK(codeOf([&] { readTrajectoryCsv(dir / "none.csv"); }) == ExitCode::MissingInput);
  std::ofstream(dir / "bad.csv") << "time,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n"
                                 << "0,a,1,2,3,1,0,0,0,0,0,0,0,0,0\n"
                                 << "0,a,1,x,3,1,0,0,0,0,0,0,0,0,0\n";
  CHECK(codeOf([&] { readTrajectoryCsv(dir / "bad.csv"); }) == ExitCode::BadInput);
  CHECK_THROWS_WITH(readTrajectoryCsv(dir / "bad.csv"), Catch::Contains("bad.csv:3:"));
}
