// The list of engines compiled in. Peers are optional: CMake defines TUMBLE_BENCH_WITH_<PEER>
// when it found the peer's Debian package and built its driver library.
#include "base/build_info.h"
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

std::vector<std::string> engineVersions() {
  std::vector<std::string> all{std::string("tumble ") + buildVersion()};
#if TUMBLE_BENCH_WITH_BULLET
  all.push_back("Bullet " + bulletVersion());
#endif
#if TUMBLE_BENCH_WITH_ODE
  all.push_back("ODE " + odeVersion());
#endif
#if TUMBLE_BENCH_WITH_MUJOCO
  all.push_back("MuJoCo " + mujocoVersion());
#endif
  return all;
}

}  // namespace tumble::bench
