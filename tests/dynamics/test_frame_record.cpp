// The overlays' records (dynamics/frame_record.h) never change the motion: every step's state is
// hashed bit for bit with the recorder and the impact log on and off, under the Baraff and the
// time-stepping models. And the records hold what the overlays draw: contacts with their states,
// forces, impacts and the energy.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>

#include "dynamics/frame_record.h"
#include "dynamics/simulator.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"
#include "scene/world_builder.h"
#include "state_hash.h"

using namespace tumble;

namespace {

using test::TrajectoryHash;


struct Run {
  std::uint64_t hash = 0;
  std::vector<FrameRecord> records;   // empty without recording
};

Run simulate(const std::string& name, ContactModel model, double seconds, bool record) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name + ".json");
  scene.simulation.step.model = model;
  setFrameCount(scene, static_cast<int>(std::lround(seconds * scene.render.fps)) + 1);
  BuiltWorld built = buildWorld(scene);
  Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, scene.render.frames});
  Run run;
  std::optional<FrameRecorder> recorder;
  std::vector<ImpactMark> impacts;
  if (record) {
    recorder.emplace(sim.world(), built.step);
    sim.setImpactLog(&impacts);
  }
  TrajectoryHash hash;
  hash.add(sim.world());
  sim.run([&](int) { if (recorder) run.records.push_back(recorder->record(sim.world(), sim.pipeline(), impacts)); },
          [&](const World& w) { hash.add(w); });
  run.hash = hash.value;
  return run;
}

int count(const std::vector<FrameRecord>& records, ContactState state) {
  int n = 0;
  for (const FrameRecord& r : records)
    for (const RecordedContact& c : r.contacts) n += c.state == state;
  return n;
}

}  // namespace

TEST_CASE("recording for overlays leaves every step's state bit-identical", "[overlays][determinism]") {
  for (ContactModel model : {ContactModel::Baraff, ContactModel::TimeStepping})
    for (const char* scene : {"knockdown", "incline_slide"}) {
      INFO(scene << (model == ContactModel::Baraff ? " (baraff)" : " (time_stepping)"));
      const Run plain = simulate(scene, model, 1.5, false);
      const Run recorded = simulate(scene, model, 1.5, true);
      CHECK(recorded.hash == plain.hash);
      CHECK(recorded.records.size() == 46);   // one per frame, the first (t = 0) included
    }
}

TEST_CASE("frame records hold contacts, forces, impacts and the energy", "[overlays]") {
  SECTION("baraff: the knockdown's landing and impact, the tower resting with its forces") {
    const Run run = simulate("knockdown", ContactModel::Baraff, 1.5, true);
    CHECK(count(run.records, ContactState::Resting) > 100);
    int forces = 0, impacts = 0;
    for (const FrameRecord& r : run.records) {
      impacts += static_cast<int>(r.impacts.size());
      for (const RecordedContact& c : r.contacts) forces += c.has_force && c.force.dot(c.normal) > 0;
      CHECK(std::isfinite(r.total()));
      CHECK(r.deepest_m >= 0);
    }
    CHECK(forces > 100);   // resting forces push the pair apart: along the normal on B
    CHECK(impacts > 0);
    for (const FrameRecord& r : run.records)
      for (const ImpactMark& m : r.impacts) CHECK(m.impulse.norm() > 0);
    // The energy falls from the start (impacts and friction take it), never rises above it by
    // more than the correction's allowance.
    CHECK(run.records.back().total() < run.records.front().total());
  }
  SECTION("friction: a block sliding down an incline slides, a resting block sticks") {
    const Run run = simulate("incline_slide", ContactModel::Baraff, 1.0, true);
    int sliding = 0;
    for (const FrameRecord& r : run.records)
      for (const RecordedContact& c : r.contacts) sliding += c.friction == FrictionState::Sliding;
    CHECK(sliding > 20);
    const Run rest = simulate("rest", ContactModel::Baraff, 1.0, true);
    int sticking = 0, slid = 0;
    for (const FrameRecord& r : rest.records)
      for (const RecordedContact& c : r.contacts) {
        sticking += c.friction == FrictionState::Sticking;
        slid += c.friction == FrictionState::Sliding;
      }
    CHECK(sticking > 20);
    CHECK(slid == 0);
  }
  SECTION("time stepping: contacts carry the impulse of the last step as a force") {
    const Run run = simulate("knockdown", ContactModel::TimeStepping, 1.0, true);
    int forces = 0;
    for (const FrameRecord& r : run.records)
      for (const RecordedContact& c : r.contacts) forces += c.has_force;
    CHECK(forces > 100);
  }
}

TEST_CASE("a resting cube's contact forces add up to its weight", "[overlays]") {
  // 1 kg on the ground: the forces over the last step, impulse / step, hold 9.81 N between them.
  for (ContactModel model : {ContactModel::Baraff, ContactModel::TimeStepping}) {
    INFO((model == ContactModel::Baraff ? "baraff" : "time_stepping"));
    const Run run = simulate("rest", model, 0.3, true);
    for (std::size_t k = 3; k < run.records.size(); ++k) {
      double normal = 0;
      for (const RecordedContact& c : run.records[k].contacts) normal += std::abs(c.force.dot(c.normal));
      CHECK(normal == Approx(9.81).epsilon(0.01));
    }
  }
}
