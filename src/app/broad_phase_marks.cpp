#include "app/broad_phase_marks.h"

#include "app/overlay_marks.h"

namespace tumble {
namespace {

constexpr float kBoxAlpha = 0.8f;   // faint enough to see the bodies through a pile of boxes

Eigen::Vector3f centre(const RecordedBox& b) { return 0.5f * (b.min + b.max); }

}  // namespace

void addBroadPhaseMarks(const BroadPhaseRecord& record, DrawMarks& marks) {
  using overlay_colour::kBox;
  for (const RecordedBox& b : record.boxes) {
    // The twelve edges: from each corner, the edges along the axes on which it is at the min.
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3f p((corner & 1) ? b.max.x() : b.min.x(), (corner & 2) ? b.max.y() : b.min.y(),
                              (corner & 4) ? b.max.z() : b.min.z());
      for (int axis = 0; axis < 3; ++axis) {
        if (corner & (1 << axis)) continue;
        Eigen::Vector3f q = p;
        q[axis] = b.max[axis];
        marks.faint.push_back({p, q, kBox, kBoxAlpha});
      }
    }
  }
  std::vector<char> paired(record.boxes.size(), 0);
  for (const auto& [a, b] : record.pairs) {
    const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
    marks.segments.push_back({centre(record.boxes[i]), centre(record.boxes[j]), overlay_colour::kPair});
    paired[i] = paired[j] = 1;
  }
  for (std::size_t i = 0; i < paired.size(); ++i)   // a dot at each paired piece's centre, once
    if (paired[i]) marks.dots.push_back({centre(record.boxes[i]), overlay_colour::kPair});
}

}  // namespace tumble
