// The back_step overlay (README, "Overlays"): for each back-step the Baraff model made since the
// frame before (FrameRecord::back_steps), the outlines of its bodies at every time bisection tried,
// as faint lines: blue where the pairs were still apart (the bracket's lower end), red where they
// were too deep (its upper end), fainter the earlier the trial, and white at the first contact it
// found; and a label near the impact with the number of trials it took. The bracket halves at each
// trial, so the first few ghosts spread over the sub-step's path and the last ones sit on the
// contact pose.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "app/piece_outline.h"
#include "dynamics/frame_record.h"
#include "render/draw_list.h"

namespace tumble {

// `outlines`: bodyOutline of every body of the world, by index.
void addBackStepMarks(const FrameRecord& record, const std::vector<std::vector<OutlineSegment>>& outlines,
                      DrawMarks& marks);

struct BackStepLabel {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();   // m, world: the impact's too-deep point
  std::string text;                               // "17 iterations"
};
std::vector<BackStepLabel> backStepLabels(const FrameRecord& record);

}  // namespace tumble
