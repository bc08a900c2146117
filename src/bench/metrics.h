// The metrics of docs/bench/scenes.md, computed from the box states an engine reports after every
// step. One collector per scene kind; all engines go through the same code.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bench/bench_scene.h"
#include "bench/box_overlap.h"
#include "bench/engine.h"

namespace tumble::bench {

struct Metric {
  std::string name;
  double value = 0;
};

class MetricCollector {
 public:
  virtual ~MetricCollector() = default;
  // After step k (k = 0 is the initial state) at time t = k dt.
  virtual void observe(const std::vector<BodyState>& s, int k, double t) = 0;
  // The metrics after the last observed state (the run may have been cut short).
  virtual std::vector<Metric> finish() = 0;
  // Whether observe() needs every step or only the first and last (piles measure at the end).
  virtual bool needsEveryStep() const { return true; }
};

std::unique_ptr<MetricCollector> makeCollector(const BenchScene& scene, double dt);

// The one error each scene is plotted by (a metric name from its collector, or "sc_err").
std::string headlineMetric(SceneKind kind);
// The plots' y-axis title for it: the metric, what it measures and its unit.
std::string headlineAxisTitle(SceneKind kind);

// Shared helpers for the collectors.
BoxPose poseOf(const BoxBody& box, const BodyState& s);
// Deepest overlap of any moving box with the ground, a wall or another moving box (m).
double scenePenetration(const BenchScene& scene, const std::vector<BodyState>& s);

}  // namespace tumble::bench
