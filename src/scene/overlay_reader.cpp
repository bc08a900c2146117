#include "scene/overlay_reader.h"

#include <algorithm>

#include "scene/suggest.h"

namespace tumble {
namespace {

// The strings of a list field, each checked to be a string; `at` receives their pointers.
std::vector<std::string> stringList(ObjectReader& root, const ParseContext& ctx, const std::string& key,
                                    const nlohmann::json& list, const char* what, std::vector<std::string>& at) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    at.push_back(root.pointerOf(key) + "/" + std::to_string(i));
    if (!list[i].is_string()) failAt(ctx, at.back(), std::string("expected ") + what + ", got " + describeType(list[i]));
    out.push_back(list[i].get<std::string>());
  }
  return out;
}

}  // namespace

void readOverlays(ObjectReader& root, const ParseContext& ctx, Scene& scene) {
  std::vector<std::string> at;
  if (const nlohmann::json* list = root.optionalArray("overlays")) {
    const std::vector<std::string> names = stringList(root, ctx, "overlays", *list, "overlay names", at);
    for (std::size_t i = 0; i < names.size(); ++i) {
      OverlayKind kind;
      if (!parseOverlayKind(names[i], kind)) failAt(ctx, at[i], unknownOverlayMessage(names[i]));
      scene.overlays.add(kind);
    }
  }
  at.clear();
  const nlohmann::json* bodies = root.optionalArray("overlay_bodies");
  if (!bodies) return;
  scene.overlays.bodies = stringList(root, ctx, "overlay_bodies", *bodies, "body names", at);
  std::vector<std::string> moving;
  for (const BodySpec& b : scene.bodies)
    if (b.shape != ShapeKind::Plane && !b.is_static) moving.push_back(b.name);
  for (std::size_t i = 0; i < scene.overlays.bodies.size(); ++i) {
    const std::string& name = scene.overlays.bodies[i];
    if (std::find(moving.begin(), moving.end(), name) != moving.end()) continue;
    for (const BodySpec& b : scene.bodies)
      if (b.name == name) failAt(ctx, at[i], "\"" + name + "\" never moves; overlay_bodies names moving bodies");
    std::string message = "no body is named \"" + name + "\"";
    if (const std::string near = closestMatch(name, moving); !near.empty()) message += "; did you mean \"" + near + "\"?";
    failAt(ctx, at[i], message);
  }
}

}  // namespace tumble
