#include "app/back_step_marks.h"

#include <algorithm>

#include "app/overlay_marks.h"

namespace tumble {
namespace {

constexpr float kFirstAlpha = 0.2f, kLastAlpha = 0.65f;   // the earliest trial's ghost, the latest's
constexpr float kFoundAlpha = 0.95f;

// The trial the search ended on: the last one not too deep at the time found.
std::size_t foundTrial(const BackStepMark& m) {
  std::size_t found = m.trials.size();
  for (std::size_t k = 0; k < m.trials.size(); ++k)
    if (!m.trials[k].too_deep && m.trials[k].t == m.found) found = k;
  return found;
}

}  // namespace

void addBackStepMarks(const FrameRecord& record, const std::vector<std::vector<OutlineSegment>>& outlines,
                      DrawMarks& marks) {
  using namespace overlay_colour;
  for (const BackStepMark& m : record.back_steps) {
    const std::size_t found = foundTrial(m);
    const std::size_t n = m.trials.size();
    for (std::size_t k = 0; k < n; ++k) {
      const BackStepTrial& trial = m.trials[k];
      const float share = n > 1 ? static_cast<float>(k) / static_cast<float>(n - 1) : 1.0f;
      const float alpha = k == found ? kFoundAlpha : kFirstAlpha + (kLastAlpha - kFirstAlpha) * share;
      const Eigen::Vector3f colour = k == found ? kFirstContact : trial.too_deep ? kTrialDeep : kTrialApart;
      for (std::size_t i = 0; i < m.bodies.size() && i < trial.poses.size(); ++i) {
        const auto body = static_cast<std::size_t>(m.bodies[i]);
        if (body >= outlines.size()) continue;
        const TrialPose& pose = trial.poses[i];
        const Eigen::Matrix3d R = pose.q.toRotationMatrix();
        for (const OutlineSegment& e : outlines[body])
          marks.faint.push_back({(pose.x + R * e.first).cast<float>(), (pose.x + R * e.second).cast<float>(), colour, alpha});
      }
    }
  }
}

std::vector<BackStepLabel> backStepLabels(const FrameRecord& record) {
  std::vector<BackStepLabel> out;
  for (const BackStepMark& m : record.back_steps)
    out.push_back({m.point, std::to_string(m.iterations) + (m.iterations == 1 ? " iteration" : " iterations")});
  return out;
}

}  // namespace tumble
