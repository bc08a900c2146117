#include "scene/camera_reader.h"

#include <algorithm>
#include <set>

#include "scene/body_reader.h"
#include "scene/suggest.h"

namespace tumble {
namespace {

void readFixed(ObjectReader& in, CameraSpec& cam) {
  cam.position_m = in.vector3("position_m", cam.position_m);
  bool has_look = in.has("look_at_m");
  bool has_quat = in.has("quat_wxyz") || in.has("rotation_deg");
  if (has_look && has_quat) in.fail("look_at_m", "give \"look_at_m\" or an orientation, not both");
  if (has_quat) {
    cam.orientation = readOrientation(in);
    cam.look_at_m.reset();
  } else {
    cam.look_at_m = in.vector3("look_at_m", *cam.look_at_m);
    if ((*cam.look_at_m - cam.position_m).norm() < 1e-9)
      in.fail("look_at_m", "the camera cannot look at its own position");
    readOrientation(in);  // marks the orientation keys as known
  }
}

// yaw and pitch, shared by orbit and fit. Pitch stops short of the poles, where "up" would be
// the view direction itself.
void readAngles(ObjectReader& in, CameraSpec& cam) {
  cam.yaw_deg = in.number("yaw_deg", cam.yaw_deg, {-360, 360});
  cam.pitch_deg = in.number("pitch_deg", cam.pitch_deg, {-89, 89});
}

// "target": a point [x, y, z] in m, or a body's name (orbiting its centre of mass as it moves).
void readOrbit(ObjectReader& in, CameraSpec& cam) {
  cam.form = CameraSpec::Form::Orbit;
  const nlohmann::json* target = in.optionalValue("target");
  if (target && target->is_string()) {
    cam.target_body = target->get<std::string>();
    cam.body_refs.push_back({cam.target_body, in.pointerOf("target")});
  } else {
    cam.target_m = in.vector3("target", cam.target_m);
  }
  cam.distance_m = in.number("distance_m", cam.distance_m, {0, 1e6, true, false});
  readAngles(in, cam);
}

void readFollow(ObjectReader& in, CameraSpec& cam) {
  cam.form = CameraSpec::Form::Follow;
  ObjectReader follow = *in.optionalObject("follow");
  if (!follow.has("body")) follow.fail("", "a follow camera needs \"body\": the name of the body to follow");
  cam.follow_body = follow.string("body", "");
  cam.body_refs.push_back({cam.follow_body, follow.pointerOf("body")});
  cam.offset_m = follow.vector3("offset_m", cam.offset_m, {-1e6, 1e6});
  if (cam.offset_m.norm() < 1e-9) follow.fail("offset_m", "the camera cannot sit at the body's centre");
  cam.smoothing_s = follow.number("smoothing_s", cam.smoothing_s, {0, 1e3});
  follow.rejectUnknownKeys();
}

// "fit": "all", or a list of body names.
void readFit(ObjectReader& in, CameraSpec& cam) {
  cam.form = CameraSpec::Form::Fit;
  const nlohmann::json& fit = *in.optionalValue("fit");
  if (fit.is_string()) {
    if (fit.get<std::string>() != "all")
      in.fail("fit", "expected \"all\" or a list of body names, got \"" + fit.get<std::string>() + "\"");
  } else if (!fit.is_array() || fit.empty()) {
    in.fail("fit", "expected \"all\" or a list of body names, got " + (fit.is_array() ? std::string("an empty list") : describeType(fit)));
  }
  for (std::size_t i = 0; fit.is_array() && i < fit.size(); ++i) {
    const std::string at = in.pointerOf("fit") + "/" + std::to_string(i);
    if (!fit[i].is_string()) in.fail("fit", "expected body names, got " + describeType(fit[i]) + " at " + at);
    cam.fit_bodies.push_back(fit[i].get<std::string>());
    cam.body_refs.push_back({cam.fit_bodies.back(), at});
  }
  readAngles(in, cam);
}

CameraSpec readCamera(ObjectReader& in, CameraSpec cam) {
  const bool follow = in.has("follow"), fit = in.has("fit");
  const bool orbit = in.has("distance_m") || in.has("target") || (!fit && (in.has("yaw_deg") || in.has("pitch_deg")));
  const int forms = int(follow) + int(fit) + int(orbit);
  if (forms > 1)
    in.fail(follow ? "follow" : "fit", "a camera takes one form: \"follow\", \"fit\" or an orbit "
                                        "(\"target\", \"distance_m\", \"yaw_deg\", \"pitch_deg\"), not several");
  const char* placed = in.has("position_m") ? "position_m" : in.has("look_at_m") ? "look_at_m" : nullptr;
  if (forms == 1 && placed)
    in.fail(placed, std::string("\"") + placed + "\" places a fixed camera; a " +
                        (follow ? "follow" : fit ? "fit" : "orbit") + " camera places itself");
  if (follow) readFollow(in, cam);
  else if (fit) readFit(in, cam);
  else if (orbit) readOrbit(in, cam);
  else readFixed(in, cam);
  cam.up = in.vector3("up", cam.up, {-1e6, 1e6});
  if (cam.up.norm() < 1e-12) in.fail("up", "the up vector cannot be zero");
  cam.fov_y_deg = in.number("fov_y_deg", cam.fov_y_deg, {0, 180, true, true});
  return cam;
}

}  // namespace

void readCameras(ObjectReader& root, Scene& scene) {
  if (auto c = root.optionalObject("camera")) {
    scene.camera = readCamera(*c, CameraSpec{});
    c->rejectUnknownKeys();
  }
  const nlohmann::json* list = root.optionalArray("cameras");
  if (!list) return;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    ObjectReader in = root.element("cameras", i);
    if (!in.has("name")) in.fail("", "a camera in \"cameras\" needs a \"name\" (what --camera picks it by)");
    CameraSpec cam;
    cam.name = in.string("name", "");
    if (cam.name.empty()) in.fail("name", "a camera's name cannot be empty");
    if (!names.insert(cam.name).second) in.fail("name", "another camera is already named \"" + cam.name + "\"");
    cam = readCamera(in, cam);
    in.rejectUnknownKeys();
    scene.cameras.push_back(cam);
  }
  if (!root.has("camera") && !scene.cameras.empty()) scene.camera = scene.cameras.front();
}

void checkCameraBodies(const Scene& scene, const ParseContext& ctx) {
  std::vector<std::string> names;
  for (const BodySpec& b : scene.bodies)
    if (b.shape != ShapeKind::Plane) names.push_back(b.name);
  std::vector<const CameraSpec*> cameras{&scene.camera};
  for (const CameraSpec& c : scene.cameras) cameras.push_back(&c);
  for (const CameraSpec* cam : cameras)
    for (const CameraBodyRef& ref : cam->body_refs) {
      if (std::find(names.begin(), names.end(), ref.name) != names.end()) continue;
      for (const BodySpec& b : scene.bodies)
        if (b.name == ref.name)
          failAt(ctx, ref.pointer, "\"" + ref.name + "\" is the ground plane; a camera follows or frames bodies that move");
      std::string message = "no body is named \"" + ref.name + "\"";
      const std::string near = closestMatch(ref.name, names);
      if (!near.empty()) message += "; did you mean \"" + near + "\"?";
      failAt(ctx, ref.pointer, message);
    }
}

}  // namespace tumble
