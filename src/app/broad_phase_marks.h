// The broad_phase overlay (README, "Overlays"): every convex piece's box as the broad phase's last
// sweep in the frame's step left it (grown by the detection margin, and under the time-stepping and
// penalty models by how far its body could travel in the step), as faint yellow lines, and each
// candidate pair the sweep passed to the narrow phase as a line between the two boxes' centres.
// A sleeping body pairs with nothing static, so a stack gone to sleep shows boxes and no lines.
#pragma once

#include "dynamics/frame_record.h"
#include "render/draw_list.h"

namespace tumble {

void addBroadPhaseMarks(const BroadPhaseRecord& record, DrawMarks& marks);

}  // namespace tumble
