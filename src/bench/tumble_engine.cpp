// tumble as a benchmark engine: the BenchScene becomes a tumble Scene (boxes with mass_kg, a plane
// for the ground, static boxes for walls), built by the same buildWorld the command line uses and
// stepped by the same Pipeline.
#include <cmath>
#include <sstream>

#include "bench/engine.h"
#include "dynamics/pipeline.h"
#include "scene/world_builder.h"

namespace tumble::bench {
namespace {

// A tumble setting is the simulation's own StepSettings (dynamics/settings.h); the benchmark sets
// the step per run. Sleeping is off in every setting but the "-sleep" one: the error columns
// measure the contact solve, which a frozen body would hide; on, the pile time compares with
// Bullet's default, which sleeps.
StepSettings baraff(Integrator integrator, double tolerance_m, int pivoting_max_rows = 256) {
  StepSettings s;
  s.integrator = integrator;
  s.contact.tolerance_m = tolerance_m;
  s.contact.max_direct_rows = pivoting_max_rows;
  s.model = ContactModel::Baraff;
  return s;
}

StepSettings timeStepping(int sweeps, int pivoting_max_rows, bool sleep = false, bool reuse_manifolds = true,
                          int threads = 1) {
  StepSettings s;
  s.threads = threads;
  s.contact.reuse_manifolds = reuse_manifolds;
  s.integrator = Integrator::SemiImplicitEuler;
  s.model = ContactModel::TimeStepping;
  s.time_stepping_sweeps = sweeps;
  s.contact.max_direct_rows = pivoting_max_rows;
  s.sleep.enabled = sleep;
  return s;
}

// The penalty model with one normal force law and Coulomb's law with a ramp. Its stiffness is set
// per scene (penaltyStiffness): the benchmark's boxes are light for their size (1 kg for a metre),
// and a stiffness from a material would make them ring at tens of kilohertz.
StepSettings penalty(NormalForceLaw law) {
  StepSettings s;
  s.model = ContactModel::Penalty;
  s.penalty.law = law;
  return s;
}

// The stiffness that lets the heaviest box, resting on its four corners, sink kStaticOverlap: a
// compliance a viewer does not see, and the figure the penetration columns start from.
constexpr double kStaticOverlap = 1e-4;   // m
double penaltyStiffness(const BenchScene& bench, NormalForceLaw law) {
  double heaviest = 0;
  for (const BoxBody& b : bench.bodies) heaviest = std::max(heaviest, b.mass);
  const double corner_load = heaviest * std::max(bench.gravity.norm(), 9.81) / 4;
  const bool linear = law == NormalForceLaw::Hooke || law == NormalForceLaw::KelvinVoigt;
  return corner_load / (linear ? kStaticOverlap : std::pow(kStaticOverlap, 1.5));
}

BodySpec boxSpec(const BoxBody& b, const BenchScene& scene, bool is_static, int index) {
  BodySpec spec;
  spec.name = (is_static ? "wall_" : "box_") + std::to_string(index);
  spec.shape = ShapeKind::Box;
  spec.box_size_m = 2 * b.half_extents;
  spec.is_static = is_static;
  spec.position_m = b.x;
  spec.orientation = b.q;
  spec.velocity_m_s = b.v;
  spec.angular_velocity_rad_s = b.w;
  spec.mass_kg = b.mass;
  // tumble combines friction by geometric mean and restitution by mean: equal values pass through.
  spec.friction = scene.friction;
  spec.restitution = scene.restitution;
  return spec;
}

Scene tumbleScene(const BenchScene& bench, double dt, const StepSettings& opt) {
  Scene scene;
  scene.file = bench.id;
  scene.name = bench.id;
  scene.simulation.step = opt;
  scene.simulation.step.dt = dt;
  if (opt.model == ContactModel::Penalty && opt.penalty.stiffness == 0)
    scene.simulation.step.penalty.stiffness = penaltyStiffness(bench, opt.penalty.law);
  scene.simulation.steps_per_frame = 1;
  scene.simulation.gravity_m_s2 = bench.gravity;
  if (bench.ground) {
    BodySpec ground;
    ground.name = "ground";
    ground.shape = ShapeKind::Plane;
    ground.is_static = true;
    ground.friction = bench.friction;
    ground.restitution = bench.restitution;
    scene.bodies.push_back(ground);
  }
  for (std::size_t i = 0; i < bench.walls.size(); ++i)
    scene.bodies.push_back(boxSpec(bench.walls[i], bench, true, static_cast<int>(i)));
  for (std::size_t i = 0; i < bench.bodies.size(); ++i)
    scene.bodies.push_back(boxSpec(bench.bodies[i], bench, false, static_cast<int>(i)));
  return scene;
}

class TumbleEngine : public Engine {
 public:
  TumbleEngine(const BenchScene& bench, double dt, const StepSettings& opt)
      : built_(buildWorld(tumbleScene(bench, dt, opt))),
        first_moving_(built_.world.bodies.size() - bench.bodies.size()),
        pipeline_(built_.world, built_.step) {
    // The body frame is the principal frame; keep the constant turn from it to the box axes.
    for (std::size_t i = 0; i < bench.bodies.size(); ++i)
      to_box_.push_back(built_.world.bodies[first_moving_ + i].q.conjugate() * bench.bodies[i].q);
  }

  void step() override {
    pipeline_.step(built_.world, built_.step);
    built_.world.time = static_cast<double>(++steps_) * built_.step.dt;
  }

  void read(std::vector<BodyState>& out) const override {
    out.resize(to_box_.size());
    for (std::size_t i = 0; i < to_box_.size(); ++i) {
      const RigidBody& b = built_.world.bodies[first_moving_ + i];
      out[i] = {b.x, (b.q * to_box_[i]).normalized(), b.velocity(), b.angularVelocity()};
    }
  }

  std::string note() const override {
    // Where the step time went, by pipeline stage: the profile the pile analysis needs.
    const PipelineCounters& c = pipeline_.counters();
    std::ostringstream s;
    s << "substeps " << c.substeps << ", back-steps " << c.back_steps;
    const ContactDetector::Work& w = pipeline_.detectionWork();
    if (w.manifolds_built + w.manifolds_reused > 0)
      s << ", manifolds reused " << std::lround(100.0 * w.manifolds_reused / (w.manifolds_built + w.manifolds_reused))
        << "%";
    double total = 0;
    for (const StageTime& t : pipeline_.profile()) total += t.seconds;
    if (total <= 0) return s.str();
    s << "; time:";
    for (const StageTime& t : pipeline_.profile())
      if (t.seconds > 0.01 * total) s << " " << t.name << " " << std::lround(100 * t.seconds / total) << "%";
    return s.str();
  }

 private:
  BuiltWorld built_;
  std::size_t first_moving_;
  Pipeline pipeline_;
  std::vector<Eigen::Quaterniond> to_box_;
  long steps_ = 0;
};

EngineSetting setting(const std::string& name, const StepSettings& opt, bool on_piles) {
  EngineSetting s = settingOf<TumbleEngine>(name, "tumble", opt);
  if (opt.model == ContactModel::Penalty) {
    // Where one compliant stiffness cannot serve the scene, the penalty settings do not run, and
    // say why. Flores et al.'s damping 8(1 - e)/(5e) and Kelvin-Voigt's damping ratio are
    // infinite at e = 0: these laws cannot model a plastic impact.
    const bool needs_restitution = opt.penalty.law == NormalForceLaw::Flores || opt.penalty.law == NormalForceLaw::KelvinVoigt;
    s.skip_reason = [needs_restitution](const BenchScene& scene) {
      switch (scene.kind) {
        case SceneKind::Pile: return std::string("piles run the chosen settings only");
        case SceneKind::MassRatio:
          return std::string("a stiffness that carries the 1000 kg box makes the light one ring: hunt_crossley and "
                             "flores refuse it, the others take about 30 s per simulated second (measured 2026-11-25; "
                             "the penalty scene tests run it)");
        case SceneKind::Tunnel:
          return std::string("a compliant contact cannot stop a shot at tens of metres per second within a wall "
                             "a few millimetres thick");
        default: break;
      }
      if (needs_restitution && scene.restitution < 0.1)
        return std::string("this law cannot make e below 0.1 (the scene's e is ") +
               std::to_string(scene.restitution).substr(0, 4) + ")";
      return std::string();
    };
    // One step only: the outer step is where the model samples, its sub-steps follow the contacts'
    // stiffness (penalty_model.h), so its error and cost barely move with dt, and five steps would
    // cost five times the longest runs of the whole benchmark.
    s.only_dt = 1.0 / 240;
    s.only_dt_reason = "its sub-steps follow the contact stiffness, not the step";
    return s;
  }
  // Piles are costly for tumble today (tens of wall seconds per simulated second): only the
  // default setting runs there unless asked for by name.
  if (!on_piles)
    s.skip_reason = [](const BenchScene& scene) {
      return scene.kind == SceneKind::Pile ? std::string("piles run the chosen settings only") : "";
    };
  return s;
}

}  // namespace

std::vector<EngineSetting> tumbleSettings() {
  StepSettings automatic;   // the default: auto chooses per scene (dynamics/auto/auto_model.h)
  automatic.model = ContactModel::Auto;
  return {
      setting("tumble-auto", automatic, true),
      setting("tumble-rk4", baraff(Integrator::Rk4, 1e-6), true),
      // The Baraff model with every resting island at the velocity level (pivoting_max_rows 0):
      // the setting for piles (docs/bench/results.md).
      setting("tumble-rk4-gs", baraff(Integrator::Rk4, 1e-6, 0), false),
      setting("tumble-rk4-tol1e-4", baraff(Integrator::Rk4, 1e-4), false),
      setting("tumble-semi", baraff(Integrator::SemiImplicitEuler, 1e-6), false),
      setting("tumble-semi-tol1e-4", baraff(Integrator::SemiImplicitEuler, 1e-4), false),
      // The time-stepping contact model: no back-stepping, so it runs the piles too. Default:
      // Gauss-Seidel (at most 200 sweeps) then pivoting for the small islands it leaves unconverged;
      // -gs: every island by Gauss-Seidel alone, 30 or 10 sweeps, as Bullet and ODE quickstep do.
      setting("tumble-ts", timeStepping(200, 256), true),
      setting("tumble-ts-gs", timeStepping(30, 0), true),
      setting("tumble-ts-gs10", timeStepping(10, 0), true),
      setting("tumble-ts-gs10-sleep", timeStepping(10, 0, true), true),
      // The fastest setting with every pair through the narrow phase at every step: what keeping
      // manifolds between steps gains (dynamics/contact_detection.h), side by side on the piles.
      setting("tumble-ts-gs10-fresh", timeStepping(10, 0, false, false), true),
      // The fastest setting on two threads (detection's pairs and the islands' solves shared; the
      // motion bit-identical to one thread's): reported beside the one-thread figures, since Bullet
      // runs on one.
      setting("tumble-ts-gs10-t2", timeStepping(10, 0, false, true, 2), true),
      // The penalty model, one setting per normal force law (docs/penalty.md). Not on the piles:
      // its sub-steps follow the stiffest contact, a landing pile's are many.
      setting("tumble-penalty-hooke", penalty(NormalForceLaw::Hooke), false),
      setting("tumble-penalty-kv", penalty(NormalForceLaw::KelvinVoigt), false),
      setting("tumble-penalty-hertz", penalty(NormalForceLaw::Hertz), false),
      setting("tumble-penalty-hc", penalty(NormalForceLaw::HuntCrossley), false),
      setting("tumble-penalty-ln", penalty(NormalForceLaw::LankaraniNikravesh), false),
      setting("tumble-penalty-flores", penalty(NormalForceLaw::Flores), false),
  };
}

}  // namespace tumble::bench
