// A hash of the bodies' states, bit for bit: the golden trajectory hashes
// (test_trajectory_hash.cpp) and the overlays' check that recording leaves the motion alone
// (test_frame_record.cpp) take it after every step.
#pragma once

#include <cstdint>
#include <cstring>

#include "dynamics/world.h"

namespace tumble::test {

// FNV-1a over the bytes of every double.
struct TrajectoryHash {
  std::uint64_t value = 1469598103934665603ull;
  void add(double x) {
    unsigned char bytes[sizeof x];
    std::memcpy(bytes, &x, sizeof x);
    for (unsigned char b : bytes) value = (value ^ b) * 1099511628211ull;
  }
  void add(const World& world) {
    add(world.time);
    for (const RigidBody& b : world.bodies) {
      for (int i = 0; i < 3; ++i) add(b.x[i]);
      add(b.q.w()), add(b.q.x()), add(b.q.y()), add(b.q.z());
      for (int i = 0; i < 3; ++i) add(b.P[i]);
      for (int i = 0; i < 3; ++i) add(b.L[i]);
    }
  }
};

}  // namespace tumble::test
