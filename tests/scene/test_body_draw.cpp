// What a body shows: "draw" ("visual", the default, or "hulls") per body with a default in
// "render", and whether the scene's colour replaces a mesh file's own.
#include <catch2/catch.hpp>

#include "base/error.h"
#include "scene/scene_loader.h"

using namespace tumble;

namespace {

std::string errorOf(const std::string& text) {
  try {
    parseScene(text, "scenes/test.json");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("draw is read per body, with the render section's default", "[scene]") {
  const Scene plain = parseScene(R"({ "schema_version": 1, "bodies": [ { "shape": "box" } ] })", "scenes/test.json");
  CHECK(plain.render.draw == BodyDraw::Visual);
  CHECK_FALSE(plain.bodies[0].draw);
  CHECK_FALSE(plain.bodies[0].colour_given);

  const Scene s = parseScene(R"({ "schema_version": 1, "render": { "draw": "hulls" },
    "bodies": [ { "name": "a", "shape": "box", "draw": "visual", "color": "#ff0000" },
                { "name": "b", "shape": "box" } ] })", "scenes/test.json");
  CHECK(s.render.draw == BodyDraw::Hulls);
  REQUIRE(s.bodies[0].draw);
  CHECK(*s.bodies[0].draw == BodyDraw::Visual);
  CHECK(s.bodies[0].colour_given);
  CHECK_FALSE(s.bodies[1].draw);
}

TEST_CASE("a misspelt draw, or draw on the ground, is refused where it is written", "[scene]") {
  CHECK(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "shape": "box", "draw": "hull" } ] })") ==
        "scenes/test.json:2:41: /bodies/0/draw: \"hull\" is not one of \"visual\", \"hulls\"; did you mean \"hulls\"?");
  CHECK_THAT(errorOf(R"({ "schema_version": 1,
  "bodies": [ { "shape": "plane", "draw": "hulls" } ] })"),
             Catch::StartsWith("scenes/test.json:2:43: /bodies/0/draw: the ground plane is drawn as a checkerboard"));
  CHECK_THAT(errorOf(R"({ "schema_version": 1, "render": { "draw": 3 }, "bodies": [ { "shape": "box" } ] })"),
             Catch::Contains("/render/draw: expected a string"));
}
