// The list of engines compiled in. Peers are optional: CMake defines TUMBLE_BENCH_WITH_<PEER>
// when it found the peer's Debian package and built its driver library.
#include "bench/engine.h"

namespace tumble::bench {

std::vector<EngineSetting> availableSettings() {
  std::vector<EngineSetting> all = tumbleSettings();
  auto append = [&](std::vector<EngineSetting> more) {
    for (EngineSetting& s : more) all.push_back(std::move(s));
  };
#if TUMBLE_BENCH_WITH_BULLET
  append(bulletSettings());
#endif
#if TUMBLE_BENCH_WITH_ODE
  append(odeSettings());
#endif
#if TUMBLE_BENCH_WITH_MUJOCO
  append(mujocoSettings());
#endif
  (void)append;
  return all;
}

}  // namespace tumble::bench
