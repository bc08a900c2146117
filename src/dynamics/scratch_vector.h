// A vector of doubles whose storage only grows, for the per-island buffers of a step. An
// Eigen::VectorXd frees and allocates again whenever its length changes, and the islands of a step
// come in every size; a view of a scratch vector costs nothing once it has held that many.
//
// The storage is aligned as Eigen aligns its own vectors, and a view starts at the storage's first
// element, so Eigen's vectorised sums (dot products, norms) group their terms exactly as they do on
// a VectorXd of the same length: a solve run on views gives the same bits as one run on vectors.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace tumble {

class ScratchVector {
 public:
  // The first n entries, their contents unspecified. A longer view later may move the storage,
  // so take every view of a scratch vector after the last one that lengthens it.
  Eigen::Map<Eigen::VectorXd, Eigen::AlignedMax> view(Eigen::Index n) {
    if (static_cast<Eigen::Index>(data_.size()) < n) data_.resize(static_cast<std::size_t>(n));
    return {data_.data(), n};
  }

 private:
  std::vector<double, Eigen::aligned_allocator<double>> data_;
};

}  // namespace tumble
