// Runs independent work items on several threads. Determinism is the caller's: each item must
// compute from inputs no other item writes, and write only its own outputs, so that its result is
// the same bits whichever thread ran it and whenever; the caller then merges the outputs in item
// order. Under that rule a run is bit-identical at any thread count (tests/dynamics/
// test_thread_determinism.cpp), which is why the items may be handed out dynamically.
#pragma once

#include <cstddef>
#include <type_traits>

namespace tumble {

namespace detail {
// The loop itself, on an OpenMP pool (parallel_for.cpp): item(context, i) for every i.
void parallelForEach(int threads, std::size_t count, void (*item)(void*, std::size_t), void* context);
}  // namespace detail

// Calls item(i) for every i in [0, count), on up to `threads` threads (the caller's among them).
// With one thread, or fewer than two items, it is a plain loop on the caller's thread. The item is
// passed by reference, not copied into a std::function: a step calls this a few times and must not
// allocate for it.
template <class Item>
void parallelFor(int threads, std::size_t count, Item&& item) {
  if (threads <= 1 || count < 2) {
    for (std::size_t i = 0; i < count; ++i) item(i);
    return;
  }
  using Plain = std::remove_reference_t<Item>;
  detail::parallelForEach(
      threads, count, [](void* context, std::size_t i) { (*static_cast<Plain*>(context))(i); },
      const_cast<void*>(static_cast<const void*>(&item)));
}

// The threads a run asks for: `requested` if positive, else every hardware thread (at least one).
int resolveThreads(int requested);

}  // namespace tumble
