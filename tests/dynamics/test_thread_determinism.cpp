// Threads change how fast a run goes, never what it computes: every body's state after every step
// of a run with two or three threads must be bit-identical to the one-thread run (the detection's
// pairs and the islands' solves run on several threads, dynamics/parallel_for.h; each writes only
// its own outputs and the outputs are merged in a fixed order). Three threads on fewer cores
// checks that a thread left waiting changes nothing either.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

#include "dynamics/simulator.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"
#include "scene/world_builder.h"
#include "state_hash.h"

using namespace tumble;

namespace {

std::uint64_t simulateAndHash(const std::string& name, ContactModel model, double seconds, int threads,
                              long* contacts_seen = nullptr) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name + ".json");
  scene.simulation.step.model = model;
  scene.simulation.step.threads = threads;
  setFrameCount(scene, static_cast<int>(std::lround(seconds * scene.render.fps)));
  BuiltWorld built = buildWorld(scene);
  Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, scene.render.frames});
  test::TrajectoryHash hash;
  hash.add(sim.world());
  sim.run({}, [&](const World& w) { hash.add(w); });
  if (contacts_seen) *contacts_seen = sim.pipeline().counters().contacts.resting + sim.pipeline().counters().contacts.colliding;
  return hash.value;
}

}  // namespace

TEST_CASE("threads: a pile's trajectory is bit-identical with one, two and three threads, every contact model",
          "[determinism][threads]") {
  struct Run {
    const char* scene;
    ContactModel model;
    double seconds;
  };
  const Run runs[] = {
      {"pile", ContactModel::TimeStepping, 1.5},
      {"pile", ContactModel::Baraff, 0.5},
      {"knockdown", ContactModel::TimeStepping, 1.0},
      {"knockdown", ContactModel::Penalty, 0.3},
  };
  for (const Run& run : runs) {
    long contacts = 0;
    const std::uint64_t one = simulateAndHash(run.scene, run.model, run.seconds, 1, &contacts);
    INFO(run.scene << ", model " << static_cast<int>(run.model) << ", " << run.seconds << " s");
    // the threads had contacts to share (the penalty model counts no solves: its forces are laws)
    if (run.model != ContactModel::Penalty) REQUIRE(contacts > 1000);
    CHECK(simulateAndHash(run.scene, run.model, run.seconds, 2) == one);
    CHECK(simulateAndHash(run.scene, run.model, run.seconds, 3) == one);
  }
}
