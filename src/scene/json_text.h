// Reading a JSON text the way scene files are read: bounded in size, comments allowed, every
// syntax error "file:line:column: invalid JSON: ...", a key given twice refused. Shared by the
// scene file and the merge patches (--patch) applied to it.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/json_locations.h"

namespace tumble {

// The file's text. Throws Error(MissingInput) when it does not exist, is a folder or a device, or
// cannot be read; Error(BadInput) past 64 MB. `what` names it in messages ("scene file").
std::string readJsonFile(const std::filesystem::path& file, const std::string& what);
// Parses `text` (located by `locations`, built from the same text). Throws Error(BadInput) with
// "file:line:column: invalid JSON: ..." on a syntax error, on nesting deeper than
// JsonLocations::kMaxDepth, and at the second of two keys of the same name in one object.
nlohmann::json parseJsonText(const std::string& text, const JsonLocations& locations, const std::string& file);

}  // namespace tumble
