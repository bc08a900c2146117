// --set and --patch change the scene's JSON before it is read, and errors in what they wrote
// name the edit.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "scene/scene_loader.h"

using namespace tumble;
namespace fs = std::filesystem;

namespace {

const char* kTwoBodies = R"({"schema_version": 1,
  "bodies": [{"name": "ground", "shape": "plane"},
             {"name": "ball", "shape": "sphere", "restitution": 0.5, "position_m": [0, 0, 2]}]})";

SceneEdit set(const std::string& text) { return {SceneEdit::Kind::Set, text}; }

fs::path writePatch(const std::string& name, const std::string& text) {
  fs::path p = fs::temp_directory_path() / ("tumble_patch_" + name);
  std::ofstream(p) << text;
  return p;
}

std::string errorOf(const std::vector<SceneEdit>& edits) {
  try {
    parseScene(kTwoBodies, "s.json", edits);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a --set finds a body by its name and writes a typed value", "[scene][edits]") {
  Scene s = parseScene(kTwoBodies, "s.json", {set("bodies.ball.restitution=0.9"), set("render.draw=hulls")});
  CHECK(s.bodies[1].restitution == 0.9);
  CHECK(s.render.draw == BodyDraw::Hulls);   // an unquoted word is a string
  Scene by_index = parseScene(kTwoBodies, "s.json", {set("bodies.1.position_m=[1, 2, 3]")});
  CHECK(by_index.bodies[1].position_m == Eigen::Vector3d(1, 2, 3));
}

TEST_CASE("a value --set wrote that the scene refuses names the --set, not the file", "[scene][edits]") {
  CHECK(errorOf({set("bodies.ball.restitusion=0.9")}) ==
        "--set bodies.ball.restitusion: unknown field \"restitusion\"; did you mean \"restitution\"?");
  CHECK(errorOf({set("bodies.ball.restitution=2")}) == "--set bodies.ball.restitution: 2 is outside [0, 1]");
  CHECK(errorOf({set("bodies.bal.restitution=0.9")}) ==
        "--set bodies.bal.restitution: bodies has no entry named \"bal\"; did you mean \"ball\"?");
}

TEST_CASE("a malformed --set is a usage error, a refused one bad input", "[scene][edits]") {
  auto code = [](const std::string& text) {
    try {
      parseScene(kTwoBodies, "s.json", {set(text)});
    } catch (const Error& e) {
      return e.code();
    }
    return ExitCode::Ok;
  };
  CHECK(code("bodies.ball.restitution") == ExitCode::Usage);
  CHECK(code("bodies..restitution=1") == ExitCode::Usage);
  CHECK(code("bodies.ball.restitution=\"high\"") == ExitCode::BadInput);
}

TEST_CASE("a merge patch follows RFC 7386, and its bodies may be keyed by name", "[scene][edits]") {
  fs::path p = writePatch("merge.json", R"({"render": {"fps": 60}, "bodies": {"ball": {"restitution": 0.25}}})");
  Scene s = parseScene(kTwoBodies, "s.json", {{SceneEdit::Kind::Patch, p.string()}});
  CHECK(s.render.fps == 60);
  CHECK(s.bodies[1].restitution == 0.25);
  CHECK(s.bodies[1].position_m.z() == 2);   // the rest of the body stays
  fs::path remove = writePatch("remove.json", R"({"bodies": {"ball": null}})");
  CHECK(parseScene(kTwoBodies, "s.json", {{SceneEdit::Kind::Patch, remove.string()}}).bodies.size() == 1);
  // --set after a patch wins, as later edits do.
  Scene both = parseScene(kTwoBodies, "s.json", {{SceneEdit::Kind::Patch, p.string()}, set("render.fps=24")});
  CHECK(both.render.fps == 24);
}

TEST_CASE("an error in a patched value is located in the patch", "[scene][edits]") {
  fs::path p = writePatch("located.json", "{\n  \"bodies\": {\"ball\": {\"restitution\": 7}}}");
  CHECK(errorOf({{SceneEdit::Kind::Patch, p.string()}}) ==
        p.string() + ":2:38: /bodies/ball/restitution: 7 is outside [0, 1]");
  fs::path broken = writePatch("broken.json", "{\"render\": ");
  try {
    parseScene(kTwoBodies, "s.json", {{SceneEdit::Kind::Patch, broken.string()}});
    FAIL("a patch that is not JSON was accepted");
  } catch (const Error& e) {
    CHECK(e.code() == ExitCode::BadInput);
    CHECK_THAT(e.what(), Catch::StartsWith(broken.string() + ":1:") && Catch::Contains("invalid JSON"));
  }
}

TEST_CASE("the resolved scene's JSON holds the edits", "[scene][edits]") {
  Scene plain = parseScene(kTwoBodies, "s.json");
  Scene edited = parseScene(kTwoBodies, "s.json", {set("bodies.ball.restitution=0.9")});
  CHECK(plain.resolved_json != edited.resolved_json);
  CHECK(edited.resolved_json.find("0.9") != std::string::npos);
}
