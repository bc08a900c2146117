#include "dynamics/joints/joint_integrator.h"

#include "dynamics/joints/joint_forces.h"

namespace tumble {
namespace {

void setState(RigidBody& body, const BodyState& s) {
  body.x = s.x;
  body.P = s.P;
  body.L = s.L;
  body.q = toQuaternion(s.q);
}

}  // namespace

long integrateJoined(World& world, const std::vector<Wrench>& wrenches, const StepSettings& settings,
                     bool velocity_motors) {
  const double dt = settings.dt;
  if (settings.integrator == Integrator::SemiImplicitEuler) {
    std::vector<Wrench> total = wrenches;
    addJointForces(world, total, dt, velocity_motors, JointHold::Velocity);
    return integrateBodies(world, total, settings);
  }
  const std::size_t n = world.bodies.size();
  std::vector<BodyState> start(n), k[4];
  for (auto& stage : k) stage.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    if (!world.bodies[i].is_static) start[i] = stateOf(world.bodies[i]);
  std::vector<Wrench> total;
  // Stage s: the derivatives at start + h_s k[s-1] (h = 0, dt/2, dt/2, dt), all bodies at once.
  const double h[4] = {0, dt / 2, dt / 2, dt};
  for (int s = 0; s < 4; ++s) {
    for (std::size_t i = 0; i < n; ++i)
      if (!world.bodies[i].is_static && s > 0) setState(world.bodies[i], advanced(start[i], k[s - 1][i], h[s]));
    total = wrenches;
    addJointForces(world, total, dt, velocity_motors);
    for (std::size_t i = 0; i < n; ++i) {
      if (world.bodies[i].is_static) continue;
      const BodyState at = s == 0 ? start[i] : advanced(start[i], k[s - 1][i], h[s]);
      k[s][i] = derivativeOf(world.bodies[i], at, total[i]);
    }
  }
  long count = 0;
  auto combine = [&](auto a, auto b, auto c, auto d) { return (a + 2 * b + 2 * c + d) * (dt / 6); };
  for (std::size_t i = 0; i < n; ++i) {
    RigidBody& body = world.bodies[i];
    if (body.is_static) continue;
    ++count;
    const BodyState& s = start[i];
    body.x = s.x + combine(k[0][i].x, k[1][i].x, k[2][i].x, k[3][i].x);
    body.P = s.P + combine(k[0][i].P, k[1][i].P, k[2][i].P, k[3][i].P);
    body.L = s.L + combine(k[0][i].L, k[1][i].L, k[2][i].L, k[3][i].L);
    body.q = toQuaternion(s.q + combine(k[0][i].q, k[1][i].q, k[2][i].q, k[3][i].q));
  }
  return count;
}

}  // namespace tumble
