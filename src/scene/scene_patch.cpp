#include "scene/scene_patch.h"

#include <algorithm>

#include "base/error.h"
#include "scene/json_text.h"
#include "scene/object_reader.h"
#include "scene/suggest.h"

namespace tumble {
namespace {

[[noreturn]] void refuse(const std::string& label, const std::string& message) {
  throw Error(ExitCode::BadInput, label + ": " + message);
}

// The entry of a list a path segment names: by index, or by its "name" member.
std::size_t entryOf(const nlohmann::json& list, const std::string& segment, const std::string& list_name,
                    const std::string& label) {
  if (!segment.empty() && segment.find_first_not_of("0123456789") == std::string::npos) {
    std::size_t i = std::stoul(segment);
    if (i >= list.size()) refuse(label, list_name + " has " + std::to_string(list.size()) + " entries; no entry " + segment);
    return i;
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    auto name = list[i].is_object() ? list[i].find("name") : list[i].end();
    if (name == list[i].end() || !name->is_string()) continue;
    if (*name == segment) return i;
    names.push_back(name->get<std::string>());
  }
  std::string near = closestMatch(segment, names);
  refuse(label, list_name + " has no entry named \"" + segment + "\"" +
                    (near.empty() ? "" : "; did you mean \"" + near + "\"?"));
}

// "bodies.ball.restitution=0.9": walks the path, making missing objects on the way, and writes
// the value; returns where it went.
EditOrigin applySet(nlohmann::json& doc, const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos)
    throw Error(ExitCode::Usage, "--set " + text + ": expected PATH=VALUE, e.g. bodies.ball.restitution=0.9");
  const std::string path = text.substr(0, eq), raw = text.substr(eq + 1);
  const std::string label = "--set " + path;
  std::vector<std::string> segments;
  for (std::size_t from = 0;;) {
    std::size_t dot = path.find('.', from);
    segments.push_back(path.substr(from, dot - from));
    if (segments.back().empty())
      throw Error(ExitCode::Usage, label + ": an empty name in the path (write a.b.c)");
    if (dot == std::string::npos) break;
    from = dot + 1;
  }
  // A value that reads as JSON is JSON; anything else is a string, so render.draw=hulls works
  // unquoted in a shell.
  nlohmann::json value = nlohmann::json::parse(raw, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = raw;

  nlohmann::json* at = &doc;
  std::string pointer, walked;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const std::string& s = segments[k];
    const bool last = k + 1 == segments.size();
    if (at->is_array()) {
      std::size_t i = entryOf(*at, s, walked, label);
      pointer += "/" + std::to_string(i);
      at = &(*at)[i];
    } else if (at->is_object()) {
      pointer += "/" + pointerToken(s);
      if (!last && !at->contains(s)) (*at)[s] = nlohmann::json::object();
      at = &(*at)[s];
    } else {
      refuse(label, (walked.empty() ? "the scene" : walked) + " is " + describeType(*at) +
                        ", which has no field \"" + s + "\"");
    }
    walked += (walked.empty() ? "" : ".") + s;
  }
  *at = value;
  return EditOrigin{pointer, label, nullptr, nullptr, ""};
}

// The values of a merge patch, leaf by leaf: what it writes (null deletes, and writes nothing).
void collectOrigins(const nlohmann::json& patch, const std::string& pointer, const std::string& source,
                    const EditOrigin& base, std::vector<EditOrigin>& out) {
  for (auto it = patch.begin(); it != patch.end(); ++it) {
    const std::string token = "/" + pointerToken(it.key());
    if (it->is_null()) continue;
    if (it->is_object() && !it->empty()) {
      collectOrigins(*it, pointer + token, source + token, base, out);
      continue;
    }
    EditOrigin o = base;
    o.pointer = pointer + token;
    o.source_pointer = source + token;
    out.push_back(o);
  }
}

void applyPatch(nlohmann::json& doc, const std::string& file, std::vector<EditOrigin>& out) {
  auto text = std::make_shared<const std::string>(readJsonFile(file, "patch file"));
  auto locations = std::make_shared<const JsonLocations>(*text);
  nlohmann::json patch = parseJsonText(*text, *locations, file);
  const ParseContext ctx{file, locations.get()};
  // RFC 7386 lets a patch that is not an object replace the whole document: never a scene.
  if (!patch.is_object()) failAt(ctx, "", "a patch of a scene is an object {...}, got " + describeType(patch));
  const EditOrigin base{"", file, text, locations, ""};
  auto bodies = patch.find("bodies");
  if (bodies != patch.end() && bodies->is_object() && doc.contains("bodies") && doc["bodies"].is_array()) {
    nlohmann::json& list = doc["bodies"];
    std::vector<std::size_t> removed;
    for (auto it = bodies->begin(); it != bodies->end(); ++it) {
      const std::string source = "/bodies/" + pointerToken(it.key());
      std::size_t i;
      try {
        i = entryOf(list, it.key(), "bodies", file);
      } catch (const Error& e) {
        failAt(ctx, source, std::string(e.what()).substr(file.size() + 2), /*at_key=*/true);
      }
      if (it->is_null()) {
        removed.push_back(i);
        continue;
      }
      list[i].merge_patch(*it);
      if (it->is_object()) collectOrigins(*it, "/bodies/" + std::to_string(i), source, base, out);
      else out.push_back(EditOrigin{"/bodies/" + std::to_string(i), file, text, locations, source});
    }
    std::sort(removed.rbegin(), removed.rend());
    for (std::size_t i : removed) list.erase(i);
    patch.erase("bodies");
  }
  doc.merge_patch(patch);
  collectOrigins(patch, "", "", base, out);
}

bool holds(const std::string& outer, const std::string& pointer) {
  return pointer.compare(0, outer.size(), outer) == 0 && (pointer.size() == outer.size() || pointer[outer.size()] == '/');
}

}  // namespace

std::vector<EditOrigin> applyEdits(nlohmann::json& doc, const std::vector<SceneEdit>& edits) {
  std::vector<EditOrigin> origins;
  if (edits.empty()) return origins;
  if (!doc.is_object()) return origins;   // the loader says what is wrong with the file itself
  for (const SceneEdit& e : edits) {
    if (e.kind == SceneEdit::Kind::Set) origins.push_back(applySet(doc, e.text));
    else applyPatch(doc, e.text, origins);
  }
  return origins;
}

void failInEdit(const std::vector<EditOrigin>& edits, const std::string& pointer, const std::string& message,
                bool at_key) {
  for (auto o = edits.rbegin(); o != edits.rend(); ++o) {
    if (!holds(o->pointer, pointer)) continue;
    const std::string rest = pointer.substr(o->pointer.size());
    if (!o->locations)
      throw Error(ExitCode::BadInput, o->label + ": " + (rest.empty() ? "" : pointer + ": ") + message);
    const std::string inside = o->source_pointer + rest;
    TextPosition pos = o->locations->find(inside, at_key);
    std::string where = o->label;
    if (pos.line > 0) where += ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
    throw Error(ExitCode::BadInput, where + ": " + (inside.empty() ? "(top level)" : inside) + ": " + message);
  }
}

}  // namespace tumble
