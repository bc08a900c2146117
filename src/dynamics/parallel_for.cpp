#include "dynamics/parallel_for.h"

#include <algorithm>
#include <thread>

namespace tumble {

namespace detail {

void parallelForEach(int threads, std::size_t count, void (*item)(void*, std::size_t), void* context) {
  const int used = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count));
  // Dynamic hand-out: items differ widely in cost (a pile's one large island beside many pairs of
  // boxes), and which thread runs an item does not change its result. In chunks of about a
  // sixteenth of a thread's share: thousands of small items (a contact's warm-start search) would
  // otherwise spend more on the hand-out than on themselves.
  const long n = static_cast<long>(count);
  const long chunk = std::max(1L, n / (16L * used));
#pragma omp parallel for num_threads(used) schedule(dynamic, chunk)
  for (long i = 0; i < n; ++i) item(context, static_cast<std::size_t>(i));
}

}  // namespace detail

int resolveThreads(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace tumble
