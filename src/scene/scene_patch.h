// Edits of a scene given on the command line: `--set PATH=VALUE` and `--patch FILE.json` (a JSON
// merge patch, RFC 7386). They change the parsed JSON before the scene is read, so every check
// the file goes through applies to them as well; what they wrote is remembered (EditOrigin), so
// that an error in it names the edit instead of a line of the file that holds no such value.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/json_locations.h"

namespace tumble {

struct SceneEdit {
  enum class Kind { Set, Patch };
  Kind kind = Kind::Set;
  std::string text;   // "bodies.ball.restitution=0.9", or the patch file's path
};

// One value an edit wrote into the scene.
struct EditOrigin {
  std::string pointer;                              // where it sits in the scene: /bodies/0/restitution
  std::string label;                                // "--set bodies.ball.restitution", or the patch file
  std::shared_ptr<const std::string> text;          // the patch's text, which `locations` reads
  std::shared_ptr<const JsonLocations> locations;   // null for --set: it has no lines
  std::string source_pointer;                       // the same value in the patch: /bodies/ball/restitution
};

// Applies the edits in order. A --set path names object members by key and list entries by
// their "name" (bodies.ball.mass_kg, cameras.top.fov_deg) or index (lights.0.intensity); its
// value is read as JSON (0.9, true, [0, 0, 1]), else taken as a string (hulls). A patch is an
// object; as an extension of RFC 7386 (where a list is replaced whole) its "bodies" may be an
// object keyed by body name, merged into those bodies (null removes one).
// Throws Error(Usage) for a malformed --set (no "=", an empty name in the path),
// Error(MissingInput) for a patch file that cannot be read, and Error(BadInput) for a patch that
// is not a JSON object, or a path or body name that the scene does not have.
std::vector<EditOrigin> applyEdits(nlohmann::json& doc, const std::vector<SceneEdit>& edits);

// For failAt: when the latest edit that wrote `pointer`, or a value holding it, is found, throws
// Error(BadInput) under its name ("--set bodies.ball.restitusion: unknown field ..." or
// "fix.json:3:5: /bodies/ball/restitusion: ..."); returns when no edit wrote it.
void failInEdit(const std::vector<EditOrigin>& edits, const std::string& pointer, const std::string& message,
                bool at_key);

}  // namespace tumble
