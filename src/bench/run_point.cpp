#include "bench/run_point.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

namespace tumble::bench {
namespace {

using Clock = std::chrono::steady_clock;
using Positions = std::vector<Eigen::Vector3f>;   // floats: the trace only feeds a distance

struct OneRun {
  double step_seconds = 0, simulated = 0;
  double head_seconds = -1;         // stepping time when the head of the run was reached
  bool cut = false;
  std::vector<Metric> metrics;
  std::string note;
};

// One fresh run. With `trace` set, the centres after each step up to `trace_steps` are kept.
OneRun runOnce(const BenchScene& scene, const EngineSetting& setting, double dt, double cap_s,
               long head_steps, std::vector<Positions>* trace, long trace_steps) {
  std::unique_ptr<Engine> engine = setting.make(scene, dt);
  std::unique_ptr<MetricCollector> metrics = makeCollector(scene, dt);
  const long steps = std::lround(scene.duration / dt);
  std::vector<BodyState> state;
  engine->read(state);
  metrics->observe(state, 0, 0);
  OneRun run;
  long k = 0;
  while (k < steps) {
    const Clock::time_point start = Clock::now();
    engine->step();
    run.step_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    ++k;
    if (k == head_steps) run.head_seconds = run.step_seconds;
    const bool last = k == steps || run.step_seconds > cap_s;
    if (metrics->needsEveryStep() || last || (trace && k <= trace_steps)) engine->read(state);
    if (metrics->needsEveryStep() || last) metrics->observe(state, static_cast<int>(k), k * dt);
    if (trace && k <= trace_steps) {
      Positions& p = trace->emplace_back();
      for (const BodyState& b : state) p.push_back(b.x.cast<float>());
    }
    if (last) break;
  }
  run.cut = k < steps;
  run.simulated = k * dt;
  run.metrics = metrics->finish();
  run.note = engine->note();
  return run;
}

// Self-consistency (Erez, Tassa, Todorov, ICRA 2015): the same engine at dt / ratio is taken as
// the truth up to a horizon; the error is the largest RMS distance of the box centres.
Metric selfConsistency(const BenchScene& scene, const EngineSetting& setting, double dt,
                       const RunOptions& opt, const std::vector<Positions>& trace,
                       double* horizon) {
  const double h = dt / opt.sc_ratio;
  std::unique_ptr<Engine> engine = setting.make(scene, h);
  std::vector<BodyState> state;
  double worst = 0, seconds = 0;
  long j = 0;
  const long steps = static_cast<long>(trace.size()) * opt.sc_ratio;
  while (j < steps && seconds <= opt.cap_s) {
    const Clock::time_point start = Clock::now();
    engine->step();
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
    if (++j % opt.sc_ratio) continue;
    engine->read(state);
    const Positions& p = trace[j / opt.sc_ratio - 1];
    double sum = 0;
    for (std::size_t i = 0; i < state.size(); ++i) sum += (state[i].x - p[i].cast<double>()).squaredNorm();
    worst = std::max(worst, std::sqrt(sum / static_cast<double>(state.size())));
  }
  *horizon = (j / opt.sc_ratio) * dt;
  return {"sc_err", worst};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string seconds(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

}  // namespace

double peakRssMb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      status >> kb;
      return kb / 1024;
    }
    status.ignore(1 << 20, '\n');
  }
  return -1;
}

RunResult resultFor(const BenchScene& scene, const EngineSetting& setting, double dt) {
  RunResult r;
  r.scene = scene.id;
  r.setting = setting.name;
  r.engine = setting.engine;
  r.dt = dt;
  return r;
}

RunResult runPoint(const BenchScene& scene, const EngineSetting& setting, double dt,
                   const RunOptions& opt) {
  RunResult r = resultFor(scene, setting, dt);
  const bool pile = scene.kind == SceneKind::Pile;
  std::vector<Positions> trace;
  const long trace_steps = pile ? std::lround(std::min(opt.sc_horizon_s, scene.duration) / dt) : 0;
  const long head_steps = opt.head_s > 0 ? std::lround(opt.head_s / dt) : -1;
  std::vector<double> per_sim, per_sim_head;
  OneRun first;
  for (int rep = 0; rep < opt.reps; ++rep) {
    OneRun run = runOnce(scene, setting, dt, opt.cap_s, head_steps, rep == 0 && pile ? &trace : nullptr,
                         trace_steps);
    per_sim.push_back(run.simulated > 0 ? run.step_seconds / run.simulated : NAN);
    if (run.head_seconds >= 0) per_sim_head.push_back(run.head_seconds / (head_steps * dt));
    if (rep == 0) first = std::move(run);
    if (first.cut || first.step_seconds > opt.single_run_above_s) break;
  }
  r.wall_per_sim = median(per_sim);
  r.reps = static_cast<int>(per_sim.size());
  r.simulated_s = first.simulated;
  r.cut = first.cut;
  r.metrics = std::move(first.metrics);
  if (pile) {
    // Time over the head of the run: the whole run when no head was set or it was not reached.
    const bool head = !per_sim_head.empty();
    r.metrics.push_back({"head_s", head ? head_steps * dt : r.simulated_s});
    r.metrics.push_back({"wall_per_sim_head", head ? median(per_sim_head) : r.wall_per_sim});
  }
  r.note = first.note;
  if (r.cut) r.note += (r.note.empty() ? "" : "; ") + ("cut at " + seconds(r.simulated_s) + " s of " +
                        seconds(scene.duration) + " s (wall cap " + seconds(opt.cap_s) + " s)");
  // Memory before the reference run, so it is the timed runs' peak (plus the trace kept above).
  r.peak_rss_mb = peakRssMb();
  if (pile && !trace.empty()) {
    double horizon = 0;
    r.metrics.push_back(selfConsistency(scene, setting, dt, opt, trace, &horizon));
    r.metrics.push_back({"sc_horizon_s", horizon});
  }
  return r;
}

}  // namespace tumble::bench
