// Command-line overrides go through the same rules as the file.
#include <catch2/catch.hpp>

#include "base/error.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

using namespace tumble;

TEST_CASE("an --fps override keeps dt close and keeps the duration", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "render": {"fps": 30, "frames": 60},
    "bodies": [{"shape": "box"}]})", "t.json");
  setFrameRate(s, 60);
  CHECK(s.render.frames == 119);   // 60 frames at 30 fps span 59/30 s: so do 119 at 60 fps
  CHECK(s.simulation.steps_per_frame == 4);
  CHECK(s.simulation.step.dt == 1.0 / 240);
}

TEST_CASE("a --dt that does not divide the frame interval is a usage error", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [{"shape": "box"}]})", "t.json");
  // 1/30 s / 1 ms = 33.3 steps: no whole number of steps lands on every frame.
  CHECK_THROWS_AS(setTimeStep(s, 0.001, "--dt"), Error);
  setTimeStep(s, 1.0 / 300, "--dt");
  CHECK(s.simulation.steps_per_frame == 10);
  CHECK(s.simulation.step.dt == 1.0 / 30 / 10);
}

TEST_CASE("the --size override takes WIDTHxHEIGHT within limits", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "bodies": [{"shape": "box"}]})", "t.json");
  setSize(s, "640x360");
  CHECK(s.render.width == 640);
  CHECK(s.render.height == 360);
  CHECK_THROWS_AS(setSize(s, "640*360"), Error);
  CHECK_THROWS_AS(setSize(s, "100000x100000"), Error);
}

TEST_CASE("a --contact-model without the scene's restitution law is a usage error", "[scene]") {
  Scene s = parseScene(R"({"schema_version": 1, "simulation": {"restitution_law": "poisson"},
    "bodies": [{"shape": "box"}]})", "t.json");
  try {
    setContactModel(s, ContactModel::TimeStepping, "--contact-model");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::Usage);
    CHECK_THAT(e.what(), Catch::StartsWith("--contact-model: only the baraff contact model has a choice of restitution law, and the scene asks for \"poisson\""));
  }
  CHECK(s.simulation.step.model == ContactModel::Auto);   // untouched: the default, which keeps Baraff for it
  setContactModel(s, ContactModel::Baraff, "--contact-model");
  Scene newton = parseScene(R"({"schema_version": 1, "bodies": [{"shape": "box"}]})", "t.json");
  setContactModel(newton, ContactModel::TimeStepping, "--contact-model");
  CHECK(newton.simulation.step.model == ContactModel::TimeStepping);
}
