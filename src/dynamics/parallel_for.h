// Runs independent work items on several threads. Determinism is the caller's: each item must
// compute from inputs no other item writes, and write only its own outputs, so that its result is
// the same bits whichever thread ran it and whenever; the caller then merges the outputs in item
// order. Under that rule a run is bit-identical at any thread count (tests/dynamics/
// test_thread_determinism.cpp), which is why the items may be handed out dynamically.
#pragma once

#include <cstddef>
#include <functional>

namespace tumble {

// Calls item(i) for every i in [0, count), on up to `threads` threads (the caller's among them).
// With one thread, or fewer than two items, it is a plain loop on the caller's thread.
void parallelFor(int threads, std::size_t count, const std::function<void(std::size_t)>& item);

// The threads a run asks for: `requested` if positive, else every hardware thread (at least one).
int resolveThreads(int requested);

}  // namespace tumble
