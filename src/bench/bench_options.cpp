#include "bench/bench_options.h"

#include <algorithm>

namespace tumble::bench {

void applyQuick(BenchOptions& o) {
  o.hz = {60, 240};
  if (o.scenes.empty()) o.scenes = {"S1", "S2a", "S2b", "S3", "S4", "S5", "S6_100", "S7", "S8", "S8ccd"};
  o.pile_duration_s = std::min(o.pile_duration_s, 0.3);
  o.run.reps = 1;
  o.run.cap_s = std::min(o.run.cap_s, 2.0);
  o.run.sc_horizon_s = std::min(o.run.sc_horizon_s, 0.1);
}

std::vector<BenchScene> plannedScenes(const BenchOptions& o) {
  std::vector<double> dts;
  for (double h : o.hz) dts.push_back(1 / h);
  std::vector<BenchScene> out;
  for (const std::string& id : o.scenes.empty() ? allSceneIds() : o.scenes) {
    BenchScene s = makeScene(id, dts);
    if (s.kind == SceneKind::Pile) s.duration = o.pile_duration_s;
    // Quick: long scenes are cut to 1 s; S1 and S2 keep their 2 s (the bounce needs ~0.7 s).
    else if (o.quick && s.duration > 2) s.duration = 1;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace tumble::bench
