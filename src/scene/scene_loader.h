// Reads and validates a scene file (JSON with comments, schema version 1).
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.h"

namespace tumble {

// Throws tumble::Error: MissingInput when the scene or a mesh file it names does not exist or
// cannot be read; BadInput for malformed JSON or a field that is unknown, of the wrong type or out
// of range, with "file:line:column: /json/pointer: message".
Scene loadScene(const std::filesystem::path& file);
// The same from text already in memory; `file` names it in messages and anchors relative paths.
Scene parseScene(const std::string& text, const std::filesystem::path& file);

}  // namespace tumble
