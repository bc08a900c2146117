// The MJCF model of a BenchScene for MuJoCo 2.2.2, with the settings of docs/bench/peers.md.
#pragma once

#include <string>

#include "bench/bench_scene.h"

namespace tumble::bench {

struct MujocoOptions {
  bool cg = false;   // solver="CG" (the 2.2.2 Newton Hessian is dense nv x nv); default Newton
};

std::string mjcfOf(const BenchScene& scene, double dt, const MujocoOptions& opt);

// MuJoCo has no restitution parameter: e is emulated by an under-damped contact spring with
// damping ratio zeta = -ln e / sqrt(pi^2 + ln^2 e) (the mass-spring-damper restitution law);
// e = 0.5 gives 0.2154. e = 0 keeps MuJoCo's critical damping, 1.
double dampingRatioFor(double restitution);

}  // namespace tumble::bench
