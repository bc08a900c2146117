// Trajectories as CSV, one row per body per sample, for plots, diffs and benchmarks:
//   time,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz
// Numbers are the shortest text that reads back to the same double (std::to_chars), so a written
// trajectory reads back bit for bit and two equal trajectories give byte-identical files.
// Body names are quoted (RFC 4180) only when they hold a comma, a quote or a line break.
// Lines before the header that start with '#' are comments (tumble writes one saying which scene
// the motion came from; pandas reads past them with comment='#').
#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace tumble {

class CsvTrajectoryWriter {
 public:
  static constexpr int kValues = 13;   // px py pz, qw qx qy qz, vx vy vz, wx wy wz

  // Opens a temporary file next to `path`; close() renames it onto `path`. Without `overwrite`
  // an existing file is Error(CantCreate). A stream ("-" for standard output, a device, a pipe:
  // isStreamOutput) is written in place instead. Errors name `path`.
  // `comments` go first, each as a line "# TEXT".
  CsvTrajectoryWriter(const std::filesystem::path& path, bool overwrite,
                      const std::vector<std::string>& comments = {});
  ~CsvTrajectoryWriter();   // without close(), removes the temporary file: no half a CSV
  CsvTrajectoryWriter(const CsvTrajectoryWriter&) = delete;
  CsvTrajectoryWriter& operator=(const CsvTrajectoryWriter&) = delete;

  void row(double time, const std::string& body, const double values[kValues]);
  void close();

 private:
  void flush();   // writes the buffer to the file

  std::filesystem::path path_, temp_;   // temp_ is empty when writing a stream in place
  bool overwrite_;
  std::FILE* file_ = nullptr;
  std::string buffer_;
};

struct TrajectoryRow {
  double time = 0;
  std::string body;
  std::array<double, CsvTrajectoryWriter::kValues> v{};
};

struct TrajectoryCsv {
  std::vector<std::string> comments;   // the text after "# " of each leading comment line
  std::vector<TrajectoryRow> rows;
};

// Reads a file written by CsvTrajectoryWriter. Throws Error(MissingInput) when absent, and
// Error(BadInput) "PATH:LINE: reason" for a malformed header or row.
TrajectoryCsv readTrajectoryCsvFile(const std::filesystem::path& path);
// The rows alone.
std::vector<TrajectoryRow> readTrajectoryCsv(const std::filesystem::path& path);

}  // namespace tumble
