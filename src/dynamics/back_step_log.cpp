#include "dynamics/back_step_log.h"

#include <algorithm>

namespace tumble {

void BackStepLog::add(BackStepMark mark) {
  ++added_;
  if (cap_ == 0) return;
  if (marks_.size() == cap_) marks_.erase(marks_.begin());   // a handful: shifting is cheap
  marks_.push_back(std::move(mark));
}

void BackStepLog::rollback(std::size_t to) {
  if (to >= added_) return;
  const std::size_t newer = added_ - to;   // added since `to`; the newest of them are the last held
  marks_.resize(marks_.size() - std::min(newer, marks_.size()));
  added_ = to;
}

std::vector<BackStepMark> BackStepLog::take() {
  std::vector<BackStepMark> out;
  out.swap(marks_);
  return out;
}

}  // namespace tumble
