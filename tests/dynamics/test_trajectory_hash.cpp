// Golden trajectory hashes: a handful of scenes simulated with each contact model, every body's
// state (x, q, P, L) after every step hashed bit by bit and compared with the value committed
// here. A refactor must leave every hash unchanged; a change meant to alter motion updates them,
// after checking the accuracy tests, with
//
//   TUMBLE_PRINT_HASHES=1 build/tests/dynamics/test_trajectory_hash
//
// which prints the table below with the new values (and fails while they differ). The values hold for this project's build
// (x86-64, GCC, -ffp-contract=off, no -ffast-math): another compiler or architecture may round
// differently and need its own table.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "dynamics/simulator.h"
#include "state_hash.h"
#include "scene/world_builder.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

using namespace tumble;

namespace {

using test::TrajectoryHash;

struct GoldenRun {
  const char* scene;      // under scenes/
  const char* model;      // "baraff", "time_stepping" or "" for the scene's own
  double seconds;
  std::uint64_t hash;
};

// Sleeping stays as each scene sets it (on by default): falling asleep is part of the motion.
const GoldenRun kRuns[] = {
    {"cube_drop", "", 2.0, 0xd037ad42f79d82d3ull},
    {"knockdown", "", 1.0, 0x9792dfd3c480eaaeull},
    {"pile", "baraff", 1.0, 0x748d8bb51a1a64a3ull},
    {"pile", "time_stepping", 1.0, 0x65c21354ac6f9a12ull},
    {"hard/cradle", "", 0.3, 0xbe4ded9cecc16fdeull},
    {"knockdown", "time_stepping", 1.0, 0x373ba1301c92ebb5ull},
    {"stack10", "", 1.0, 0xa73cc00235e5d84dull},
    {"incline_slide", "", 1.0, 0xeb92ef3d07790f75ull},
    {"hard/tunnel_shot", "", 0.2, 0x44f1efbeb4add1baull},
    {"free_spin", "", 2.0, 0x1cbeced242122622ull},
};

std::uint64_t simulateAndHash(const GoldenRun& run) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + run.scene + ".json");
  if (std::string(run.model) == "baraff") scene.simulation.step.model = ContactModel::Baraff;
  if (std::string(run.model) == "time_stepping") scene.simulation.step.model = ContactModel::TimeStepping;
  // The committed runs: seconds x fps frames, the last at (frames - 1) / fps (the frame count a
  // duration gave when these hashes were taken; setDuration now gives one more, reaching it).
  setFrameCount(scene, static_cast<int>(std::lround(run.seconds * scene.render.fps)));
  BuiltWorld built = buildWorld(scene);
  Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, scene.render.frames});
  TrajectoryHash hash;
  hash.add(sim.world());
  sim.run({}, [&](const World& w) { hash.add(w); });
  return hash.value;
}

}  // namespace

TEST_CASE("trajectory hashes: every step of the golden runs is bit-identical to the committed values",
          "[determinism][golden]") {
  const bool print = std::getenv("TUMBLE_PRINT_HASHES") != nullptr;
  for (const GoldenRun& run : kRuns) {
    const std::uint64_t got = simulateAndHash(run);
    if (print)
      std::printf("    {\"%s\", \"%s\", %.1f, 0x%016llxull},\n", run.scene, run.model, run.seconds,
                  static_cast<unsigned long long>(got));
    INFO(run.scene << " (" << (*run.model ? run.model : "scene's model") << ", " << run.seconds << " s): got 0x"
                   << std::hex << got << ", committed 0x" << run.hash);
    CHECK(got == run.hash);
  }
}
