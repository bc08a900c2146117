// Reads and validates a scene file (JSON with comments, schema version 1).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_patch.h"

namespace tumble {

// Throws tumble::Error: MissingInput when the scene or a mesh file it names does not exist or
// cannot be read; BadInput for malformed JSON or a field that is unknown, of the wrong type or out
// of range, with "file:line:column: /json/pointer: message". `edits` (--set, --patch) change the
// file's JSON before it is read, in order; a value an edit wrote that the scene refuses is
// reported under the edit's name ("--set bodies.ball.mass_kg: ...", "fix.json:3:5: ...").
Scene loadScene(const std::filesystem::path& file, const std::vector<SceneEdit>& edits = {});
// The same from text already in memory; `file` names it in messages and anchors relative paths.
Scene parseScene(const std::string& text, const std::filesystem::path& file,
                 const std::vector<SceneEdit>& edits = {});

}  // namespace tumble
