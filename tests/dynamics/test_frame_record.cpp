// The overlays' records (dynamics/frame_record.h) never change the motion: every step's state is
// hashed bit for bit with the recorder, the impact log, the back-step log and the broad phase's
// record on and off, under the Baraff and the time-stepping models. And the records hold what the
// overlays draw: contacts with their states, forces, impacts, the energy, the back-steps' brackets
// and the broad phase's boxes and pairs.
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
  std::size_t frames = 0;
  std::vector<FrameRecord> records;   // empty without recording
};

Run simulate(const std::string& name, ContactModel model, double seconds, bool record) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name + ".json");
  scene.simulation.step.model = model;
  setFrameCount(scene, static_cast<int>(std::lround(seconds * scene.render.fps)) + 1);
  BuiltWorld built = buildWorld(scene);
  Simulator sim(std::move(built.world), {built.step, scene.simulation.steps_per_frame, scene.render.frames});
  Run run;
  run.frames = static_cast<std::size_t>(scene.render.frames);
  std::optional<FrameRecorder> recorder;
  std::vector<ImpactMark> impacts;
  BackStepLog back_steps;
  if (record) {
    recorder.emplace(sim.world(), built.step, FrameRecordOptions{true});
    sim.setImpactLog(&impacts);
    sim.setBackStepLog(&back_steps);
  }
  TrajectoryHash hash;
  hash.add(sim.world());
  sim.run([&](int) {
            if (recorder) run.records.push_back(recorder->record(sim.world(), sim.pipeline(), impacts, &back_steps));
          },
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
    for (const char* scene : {"knockdown", "incline_slide", "demos/back_stepping"}) {
      INFO(scene << (model == ContactModel::Baraff ? " (baraff)" : " (time_stepping)"));
      const Run plain = simulate(scene, model, 1.5, false);
      const Run recorded = simulate(scene, model, 1.5, true);
      CHECK(recorded.hash == plain.hash);
      CHECK(recorded.records.size() == recorded.frames);   // one per frame, the first (t = 0) included
    }
}

TEST_CASE("the back-step log keeps each bracket's trials, and the last few per frame", "[overlays]") {
  SECTION("the back-stepping demo: each first contact found by bisection, its poses at every trial") {
    const Run run = simulate("demos/back_stepping", ContactModel::Baraff, 1.0, true);
    int marks = 0;
    for (const FrameRecord& r : run.records)
      for (const BackStepMark& m : r.back_steps) {
        ++marks;
        CHECK(m.time <= r.time);
        CHECK(m.found > 0);
        CHECK(m.found < m.h);
        REQUIRE(m.bodies.size() == 1);   // the cube; the plate and the ground never move
        REQUIRE(m.trials.size() >= 2);
        CHECK(m.iterations == static_cast<int>(m.trials.size()) - 1);   // the first trial is the sub-step's end
        CHECK(m.trials.front().t == m.h);
        CHECK(m.trials.front().too_deep);
        // The bracket closes on the time found: its last trial below the tolerance is that time.
        double lo = 0, hi = m.h;
        for (const BackStepTrial& t : m.trials) {
          REQUIRE(t.poses.size() == 1);
          CHECK(t.t >= lo);
          CHECK(t.t <= hi);
          (t.too_deep ? hi : lo) = t.t;
        }
        CHECK(lo == m.found);
        // On the plate's top (its first landing, t = 0.083 s) or on the ground, where it bounces.
        CHECK((std::abs(m.point.z() - 0.31) < 0.02 || std::abs(m.point.z()) < 0.02));
        if (marks == 1) CHECK(m.point.z() == Approx(0.31).margin(0.02));
      }
    CHECK(marks > 0);
  }
  SECTION("the log drops the oldest past its cap, and rolls back a retaken step's") {
    BackStepLog log(3);
    auto mark = [](double time) {
      BackStepMark m;
      m.time = time;
      return m;
    };
    for (int i = 0; i < 5; ++i) log.add(mark(i));
    REQUIRE(log.marks().size() == 3);
    CHECK(log.marks().front().time == 2);
    const std::size_t before = log.added();
    log.add(mark(5));   // drops 2
    log.rollback(before);
    CHECK(log.marks().back().time == 4);
    CHECK(log.take().size() == 2);   // 3 and 4: what the cap dropped stays dropped
    CHECK(log.marks().empty());
  }
}

TEST_CASE("the broad phase's record holds each piece's box and the overlapping pairs", "[overlays]") {
  const Run run = simulate("knockdown", ContactModel::Baraff, 0.5, true);
  const BroadPhaseRecord& last = run.records.back().broad_phase;
  REQUIRE(!last.boxes.empty());
  CHECK(!last.pairs.empty());   // the tower's blocks touch
  for (const auto& [a, b] : last.pairs) {
    const RecordedBox& A = last.boxes[static_cast<std::size_t>(a)];
    const RecordedBox& B = last.boxes[static_cast<std::size_t>(b)];
    CHECK(A.body != B.body);
    CHECK(((A.min.array() <= B.max.array()).all() && (B.min.array() <= A.max.array()).all()));
  }
  CHECK(run.records.front().broad_phase.boxes.empty());   // t = 0: no step has swept yet
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
