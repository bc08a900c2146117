#include "scene/scene_loader.h"

#include <cmath>
#include <limits>
#include <set>

#include "base/error.h"
#include "scene/body_reader.h"
#include "scene/camera_reader.h"
#include "scene/joint_reader.h"
#include "scene/json_text.h"
#include "scene/object_reader.h"
#include "scene/overlay_reader.h"
#include "scene/scene_overrides.h"

namespace tumble {
namespace {

// Refused before any work: a frame this large or a clip this long is a typo, not a request.
constexpr int kMaxSide = 8192;
constexpr int kMaxFrames = 1000000;
// Steps in a whole run: 1e8 steps at 1/240 s is 116 hours of simulated time. More is a typo in
// dt_s or the frame count, and would look like a hang.
constexpr double kMaxSteps = 1e8;

// The scene's default output comes from a file that may have been written by someone else: it
// stays inside the working folder, so a scene cannot direct a render (with -y) onto files
// elsewhere. `-o` on the command line is the user's own choice and may go anywhere.
void checkSceneOutput(ObjectReader& root, const std::string& output) {
  if (output.empty()) root.fail("output", "the output path cannot be empty");
  checkPathText(root, "output", output);
  std::filesystem::path path(output);
  if (path.is_absolute())
    root.fail("output", "\"" + output + "\" is an absolute path; a scene's output stays inside the "
                        "working folder (give -o to write elsewhere)");
  for (const auto& part : path.lexically_normal())
    if (part == "..")
      root.fail("output", "\"" + output + "\" leaves the working folder; a scene's output stays inside "
                          "it (give -o to write elsewhere)");
}

void readRender(ObjectReader& in, RenderSpec& r) {
  r.width = in.integer("width", r.width, 16, kMaxSide);
  r.height = in.integer("height", r.height, 16, kMaxSide);
  r.fps = in.integer("fps", r.fps, 1, 1000);
  auto duration = in.optionalNumber("duration_s", {0, kMaxFrames / double(r.fps), true, false});
  if (duration && in.has("frames")) in.fail("frames", "give either \"duration_s\" or \"frames\", not both");
  if (duration) r.frames = framesForDuration(*duration, r.fps);
  r.frames = in.integer("frames", r.frames, 1, kMaxFrames);
  r.samples = in.integer("samples", r.samples, 1, 4);
  if (r.samples == 3) in.fail("samples", "MSAA takes 1, 2 or 4 samples");
  r.shadow_map_size = in.integer("shadow_map_size", r.shadow_map_size, 256, 8192);
  r.crf = in.integer("crf", r.crf, 0, 51);
  if (in.has("background") && in.has("background_color"))
    in.fail("background_color", "give \"background\" or \"background_color\", not both");
  r.background_srgb = in.colour("background", in.colour("background_color", r.background_srgb));
  r.draw = readBodyDraw(in, r.draw);
  in.rejectUnknownKeys();
}

// A law named by its scene-file name (settings.h's table), with "did you mean" for a near miss;
// returns the name read.
template <typename Law, std::size_t N>
std::string readLaw(ObjectReader& in, const std::string& key, Law fallback, const LawName<Law> (&names)[N], Law& out) {
  std::vector<std::string> choices;
  for (const LawName<Law>& n : names) choices.push_back(n.name);
  const std::string name = readChoice(in, key, nameOf(fallback, names), choices);
  for (const LawName<Law>& n : names)
    if (name == n.name) out = n.law;
  return name;
}

// The penalty model's laws and their parameters (dynamics/penalty/). A stiffness is given in the
// unit of its law (N/m for the linear laws, N/m^1.5 for the Hertz-type ones), so a number meant
// for the other family is refused rather than read a thousand times off.
void readPenalty(ObjectReader& in, PenaltySettings& p) {
  const std::string law = readLaw(in, "law", NormalForceLaw::HuntCrossley, kNormalForceLawNames, p.law);
  const bool linear = p.law == NormalForceLaw::Hooke || p.law == NormalForceLaw::KelvinVoigt;
  const char* right = linear ? "stiffness_n_m" : "stiffness_n_m1_5";
  const char* wrong = linear ? "stiffness_n_m1_5" : "stiffness_n_m";
  if (in.has(wrong))
    in.fail(wrong, "the " + law + " law's stiffness is \"" + right + "\" (" +
                       (linear ? "N/m: force = k overlap" : "N/m^1.5: force = K overlap^1.5") + ")");
  p.stiffness = in.number(right, 0, {0, 1e15, true, false});
  readLaw(in, "friction_law", FrictionLaw::Coulomb, kFrictionLawNames, p.friction_law);
  p.ramp_speed_m_s = in.number("ramp_speed_m_s", p.ramp_speed_m_s, {0, 100, true, false});
  p.ambrosio_dead_speed_m_s = in.number("dead_speed_m_s", p.ambrosio_dead_speed_m_s, {0, 100, false, false});
  if (p.friction_law == FrictionLaw::Ambrosio && p.ambrosio_dead_speed_m_s >= p.ramp_speed_m_s)
    in.fail(in.has("dead_speed_m_s") ? "dead_speed_m_s" : "ramp_speed_m_s",
            "Ambrosio's friction rises from \"dead_speed_m_s\" (" + formatNumber(p.ambrosio_dead_speed_m_s) +
                ") to \"ramp_speed_m_s\" (" + formatNumber(p.ramp_speed_m_s) + "): the first must be smaller");
  p.static_friction_ratio = in.number("static_friction_ratio", p.static_friction_ratio, {1, 100});
  p.stribeck_decay_s_m = in.number("stribeck_decay_s_m", p.stribeck_decay_s_m, {0, 1e6, true, false});
  p.max_substeps = in.integer("max_substeps", p.max_substeps, 1, 10000000);
  in.rejectUnknownKeys();
}

// "target": what the run's accuracy must be (settings.h, AccuracyTarget). The automatic model
// meets it by its choice and its contact tolerance; a scene that names its model gets it measured
// and reported. The floors are what any model can hold: the finest contact tolerance there is,
// and the rounding of an energy sum.
void readTarget(ObjectReader& in, StepSettings& step, bool tolerance_given) {
  AccuracyTarget& t = step.target;
  t.penetration_m = in.number("penetration_m", 0, {1e-9, 1, false, false});
  t.energy_drift = in.number("energy_drift", 0, {1e-12, 1, false, false});
  if (in.has("penetration_m") && tolerance_given && step.contact.tolerance_m > t.penetration_m)
    in.fail("penetration_m", "the scene's \"contact_tolerance_m\" (" + formatNumber(step.contact.tolerance_m) +
                                 " m) lets contacts end a step deeper than this target (" +
                                 formatNumber(t.penetration_m) + " m): drop one, or make the tolerance smaller");
  in.rejectUnknownKeys();
  if (!t.any()) in.fail("", "a target needs \"penetration_m\" or \"energy_drift\" (or both)");
}

void readSimulation(ObjectReader& in, SimulationSpec& sim, int fps, int frames) {
  StepSettings& step = sim.step;
  step.integrator = readIntegrator(in, "integrator", step.integrator);
  sim.gravity_m_s2 = in.vector3("gravity_m_s2", sim.gravity_m_s2, {-1e4, 1e4});
  step.contact.regula_falsi =
      readChoice(in, "time_of_impact", "bisection", {"bisection", "regula_falsi"}) == "regula_falsi";
  step.contact.max_direct_rows = in.integer("pivoting_max_rows", step.contact.max_direct_rows, 0, 100000);
  step.contact.tolerance_m = in.number("contact_tolerance_m", step.contact.tolerance_m, {1e-9, 1e-2});
  step.contact.reuse_manifolds = in.boolean("reuse_manifolds", step.contact.reuse_manifolds);
  const std::string model = readChoice(in, "contact_model", "auto", {"auto", "baraff", "time_stepping", "penalty"});
  step.model = model == "baraff"          ? ContactModel::Baraff
               : model == "penalty"       ? ContactModel::Penalty
               : model == "time_stepping" ? ContactModel::TimeStepping
                                          : ContactModel::Auto;
  if (auto penalty = in.optionalObject("penalty")) {
    if (step.model != ContactModel::Penalty)
      in.fail("penalty", "\"penalty\" settings go with \"contact_model\": \"penalty\" (this scene's model is \"" +
                             model + "\")");
    readPenalty(*penalty, step.penalty);
  }
  // Only the event-driven model follows an impact through compression and restitution and so has
  // a choice of law (time stepping's one impulse per step is Newton's law): the key is refused
  // with any other model, whatever law it names.
  const std::string law = readChoice(in, "restitution_law", "newton", {"newton", "poisson", "stronge"});
  if (in.has("restitution_law") && step.model != ContactModel::Baraff && step.model != ContactModel::Auto)
    in.fail("restitution_law", "the \"" + model + "\" contact model has no choice of restitution law (\"" + law +
                                   "\" is one of the \"baraff\" model's)");
  step.contact.restitution_law = law == "poisson"   ? RestitutionLaw::Poisson
                                 : law == "stronge" ? RestitutionLaw::Stronge
                                                    : RestitutionLaw::Newton;
  step.time_stepping_sweeps = in.integer("time_stepping_sweeps", step.time_stepping_sweeps, 1, 100000);
  if (auto target = in.optionalObject("target")) readTarget(*target, step, in.has("contact_tolerance_m"));
  step.sleep.enabled = in.boolean("sleep", step.sleep.enabled);
  step.sleep.speed_m_s = in.number("sleep_speed_m_s", step.sleep.speed_m_s, {0, 10, true, false});
  step.sleep.spin_rad_s = in.number("sleep_spin_rad_s", step.sleep.spin_rad_s, {0, 100, true, false});
  step.sleep.after_s = in.number("sleep_after_s", step.sleep.after_s, {0, 1e6, true, false});
  // Every frame must fall on a step, so the step divides the frame interval. The file gives dt_s
  // as a rounded decimal (1/240 = 0.0041667); the exact step is the interval / steps per frame.
  // Without dt_s the step is the one nearest 1/240 s that divides the frame interval.
  bool given = in.has("dt_s");
  double dt = in.number("dt_s", step.dt, {0, 0.1, true, false});
  double interval = 1.0 / fps;
  double steps = interval / dt;
  long whole = std::max(1L, std::lround(steps));
  if (given && std::abs(steps - whole) > 1e-3 * whole) {
    long near = std::max(1L, whole);
    in.fail("dt_s", formatNumber(dt) + " s does not divide the frame interval 1/" +
                        std::to_string(fps) + " s; try " + formatNumber(interval / near) + " (1/" +
                        std::to_string(near * fps) + ")");
  }
  if (whole > 100000) in.fail("dt_s", "more than 100000 steps per frame; use a larger step");
  if (double(whole) * frames > kMaxSteps)
    in.fail("dt_s", std::to_string(frames) + " frames of " + std::to_string(whole) +
                        " steps each are more than " + formatNumber(kMaxSteps) +
                        " steps; use a larger step or fewer frames");
  sim.steps_per_frame = static_cast<int>(whole);
  step.dt = interval / whole;
  in.rejectUnknownKeys();
}

void readLights(ObjectReader& root, const nlohmann::json& list, LightingSpec& lighting,
                const ParseContext& ctx) {
  lighting.directional.clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    ObjectReader in(ctx, list[i], root.pointerOf("lights") + "/" + std::to_string(i));
    std::string type = readChoice(in, "type", "directional", {"directional", "ambient"});
    Eigen::Vector3d colour = in.colour("color", in.colour("colour", {1, 1, 1}));
    double intensity = in.number("intensity", type == "ambient" ? 0.35 : 1.0, {0, 1000});
    if (type == "ambient") {
      lighting.ambient_srgb = colour;
      lighting.ambient_intensity = intensity;
    } else {
      DirectionalLightSpec light;
      light.direction = in.vector3("direction", light.direction);
      if (light.direction.norm() < 1e-12) in.fail("direction", "a light direction cannot be zero");
      light.colour_srgb = colour;
      light.intensity = intensity;
      light.shadows = in.boolean("shadows", lighting.directional.empty());
      lighting.directional.push_back(light);
    }
    in.rejectUnknownKeys();
  }
  if (lighting.directional.empty())
    failAt(ctx, root.pointerOf("lights"), "at least one \"directional\" light is needed");
}

void readBodies(ObjectReader& root, const ParseContext& ctx, Scene& scene) {
  const nlohmann::json* list = root.optionalArray("bodies");
  if (!list) {
    root.rejectUnknownKeys();  // "bodys" is better answered with "did you mean"
    failAt(ctx, "", "missing required field \"bodies\" (the list of bodies)");
  }
  if (list->empty()) failAt(ctx, "/bodies", "the scene has no bodies");
  std::filesystem::path dir = scene.file.parent_path();
  std::set<std::string> names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    ObjectReader in(ctx, (*list)[i], "/bodies/" + std::to_string(i));
    scene.bodies.push_back(readBody(in, static_cast<int>(i), dir));
    if (!names.insert(scene.bodies.back().name).second)
      in.fail("name", "another body is already named \"" + scene.bodies.back().name + "\"");
  }
}

}  // namespace

Scene loadScene(const std::filesystem::path& file, const std::vector<SceneEdit>& edits) {
  return parseScene(readJsonFile(file, "scene file"), file, edits);
}

Scene parseScene(const std::string& text, const std::filesystem::path& file, const std::vector<SceneEdit>& edits) {
  JsonLocations locations(text);
  nlohmann::json doc = parseJsonText(text, locations, file.string());
  // The edits change the document before it is read, so every check below applies to them; an
  // error in a value an edit wrote names the edit (EditOrigin), not a line of the file.
  const std::vector<EditOrigin> origins = applyEdits(doc, edits);
  ParseContext ctx{file.string(), &locations, &origins};
  Scene scene;
  scene.file = file;
  scene.name = file.stem().string();
  ObjectReader root(ctx, doc, "");
  if (!root.has("schema_version"))
    failAt(ctx, "", "missing required field \"schema_version\" (this tumble reads version 1)");
  scene.schema_version = root.integer("schema_version", 1, 0, 1000000);
  if (scene.schema_version != 1)
    root.fail("schema_version", "this tumble reads schema version 1, not " +
                                    std::to_string(scene.schema_version));
  if (auto r = root.optionalObject("render")) readRender(*r, scene.render);
  if (auto s = root.optionalObject("simulation")) readSimulation(*s, scene.simulation, scene.render.fps, scene.render.frames);
  else {
    nlohmann::json empty = nlohmann::json::object();
    ObjectReader defaults(ctx, empty, "/simulation");
    readSimulation(defaults, scene.simulation, scene.render.fps, scene.render.frames);
  }
  readCameras(root, scene);
  if (const nlohmann::json* lights = root.optionalArray("lights")) readLights(root, *lights, scene.lighting, ctx);
  else scene.lighting.directional.assign(1, DirectionalLightSpec{});
  scene.output = root.optionalString("output");
  if (scene.output) checkSceneOutput(root, *scene.output);
  readBodies(root, ctx, scene);
  readJoints(root, ctx, scene);
  checkCameraBodies(scene, ctx);
  readOverlays(root, ctx, scene);
  root.rejectUnknownKeys();
  scene.resolved_json = doc.dump();
  return scene;
}

}  // namespace tumble
