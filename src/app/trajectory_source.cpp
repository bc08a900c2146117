#include "app/trajectory_source.h"

#include <map>

#include "base/error.h"
#include "io/trajectory_csv.h"
#include "scene/motion_hash.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMark = "tumble trajectory";

// "tumble trajectory; a=1; b=2" -> {a: 1, b: 2}; empty when the line is not tumble's.
std::map<std::string, std::string> fieldsOf(const std::string& comment) {
  std::map<std::string, std::string> fields;
  if (comment.rfind(kMark, 0) != 0) return fields;
  std::size_t pos = comment.find("; ");
  while (pos != std::string::npos) {
    std::size_t next = comment.find("; ", pos + 2);
    std::string item = comment.substr(pos + 2, next == std::string::npos ? std::string::npos : next - pos - 2);
    if (std::size_t eq = item.find('='); eq != std::string::npos) fields[item.substr(0, eq)] = item.substr(eq + 1);
    pos = next;
  }
  return fields;
}

[[noreturn]] void refuse(const fs::path& file, const std::string& why, const Scene& scene) {
  throw Error(ExitCode::BadInput, file.string() + ": " + why + "; write it again with 'tumble simulate " +
                                      scene.file.string() + " --trajectory " + file.string() + "'");
}

BodySample sampleFromRow(const TrajectoryRow& row) {
  const auto& v = row.v;
  return {{v[0], v[1], v[2]}, Eigen::Quaterniond(v[3], v[4], v[5], v[6]), {v[7], v[8], v[9]}, {v[10], v[11], v[12]}};
}

}  // namespace

std::string trajectoryComment(const Scene& scene, bool every_step) {
  return std::string(kMark) + "; motion-hash=" + motionHash(scene) + "; rows=" + (every_step ? "step" : "frame") +
         "; scene=" + scene.file.filename().string();
}

Trajectory readTrajectoryFor(const Scene& scene, const std::vector<std::string>& body_names, const fs::path& file,
                             int last_frame) {
  TrajectoryCsv csv = readTrajectoryCsvFile(file);
  std::map<std::string, std::string> header;
  for (const std::string& c : csv.comments)
    if (header.empty()) header = fieldsOf(c);
  if (header.empty() || !header.count("motion-hash"))
    refuse(file, "no '# tumble trajectory; motion-hash=...' line, so nothing says which scene it shows", scene);
  if (header["rows"] != "frame") refuse(file, "written with --every-step; rendering needs one row per body per frame", scene);
  const std::string hash = motionHash(scene);
  if (header["motion-hash"] != hash)
    refuse(file, "simulated from another scene than " + scene.file.string() + " (or with other --fps, --dt, "
                 "--time-scale, --integrator, --contact-model or --no-sleep): its motion hash is " + header["motion-hash"] +
                 ", this scene's " + hash, scene);
  const std::size_t bodies = body_names.size();
  if (bodies == 0) throw Error(ExitCode::BadInput, scene.file.string() + ": the scene has no bodies to draw");
  Trajectory trajectory;
  trajectory.body_names = body_names;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const TrajectoryRow& row = csv.rows[r];
    if (row.body != body_names[r % bodies])
      refuse(file, "data row " + std::to_string(r + 1) + " is body \"" + row.body + "\" where the scene has \"" +
                       body_names[r % bodies] + "\"", scene);
    if (r % bodies == 0) {
      trajectory.times.push_back(row.time);
      trajectory.frames.emplace_back();
    }
    trajectory.frames.back().push_back(sampleFromRow(row));
  }
  const int held = csv.rows.size() % bodies == 0 ? static_cast<int>(trajectory.frames.size())
                                                 : static_cast<int>(trajectory.frames.size()) - 1;
  if (last_frame > held)
    refuse(file, "it holds frames 1.." + std::to_string(held) + ", and frame " + std::to_string(last_frame) +
                     " is needed (simulate as long as you render: same --duration)", scene);
  trajectory.frames.resize(static_cast<std::size_t>(last_frame));
  trajectory.times.resize(static_cast<std::size_t>(last_frame));
  return trajectory;
}

}  // namespace tumble
