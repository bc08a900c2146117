// What the benchmark needs from a physics engine: build a BenchScene at a fixed step, take one
// step, and report the pose and velocity of every moving box. tumble and each peer (Bullet, ODE,
// MuJoCo) implement it in a file of their own.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_scene.h"

namespace tumble::bench {

struct BodyState {
  Eigen::Vector3d x;       // m, box centre, world
  Eigen::Quaterniond q;    // box axes -> world
  Eigen::Vector3d v;       // m/s, world
  Eigen::Vector3d w;       // rad/s, world
};

class Engine {
 public:
  virtual ~Engine() = default;
  // Exactly one engine step of the dt the engine was made with (no substepping by the harness).
  virtual void step() = 0;
  // The moving boxes in scene order.
  virtual void read(std::vector<BodyState>& out) const = 0;
  // Anything the engine wants said next to its figures (e.g. dropped contacts); "" if nothing.
  virtual std::string note() const { return ""; }
};

// One engine with one set of options: a line on the plots, a group of rows in the table.
struct EngineSetting {
  std::string name;     // "tumble-rk4", "bullet-nosleep", "ode-quick", ...
  std::string engine;   // "tumble", "bullet", "ode", "mujoco"
  std::function<std::unique_ptr<Engine>(const BenchScene&, double dt)> make;
  // Whether this setting runs on a scene, and if not why (shown in the report).
  std::function<std::string(const BenchScene&)> skip_reason = [](const BenchScene&) { return ""; };
  // s: where above zero, the setting runs at the swept step nearest this one only (unless named on
  // the command line), for the reason given: a model whose error does not follow the step.
  double only_dt = 0;
  std::string only_dt_reason;
};

// A setting whose engine class E is built as E(scene, dt, options).
template <typename E, typename Options>
EngineSetting settingOf(const std::string& name, const std::string& engine, Options options) {
  EngineSetting s;
  s.name = name;
  s.engine = engine;
  s.make = [options](const BenchScene& scene, double dt) -> std::unique_ptr<Engine> {
    return std::make_unique<E>(scene, dt, options);
  };
  return s;
}

// Every setting available in this build: tumble's, then each peer found at configure time.
std::vector<EngineSetting> availableSettings();

// Per engine, filled by its own file (peers only when built with them).
std::vector<EngineSetting> tumbleSettings();
std::vector<EngineSetting> bulletSettings();
std::vector<EngineSetting> odeSettings();
std::vector<EngineSetting> mujocoSettings();

// Every engine in this build with its version, tumble first: "tumble 0.1.0", "Bullet 3.24", ...
std::vector<std::string> engineVersions();
// Per peer, from its own file: the version of the library actually linked where it says so.
std::string bulletVersion();
std::string odeVersion();
std::string mujocoVersion();

}  // namespace tumble::bench
