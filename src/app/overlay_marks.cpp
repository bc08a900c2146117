#include "app/overlay_marks.h"

#include <algorithm>
#include <cmath>

namespace tumble {
namespace {

// The smallest of 1, 2, 5 x 10^k at least v: a scale that reads well in the legend.
double roundUp125(double v) {
  if (!(v > 0) || !std::isfinite(v)) return 1;
  const double decade = std::pow(10.0, std::floor(std::log10(v)));
  for (double k : {1.0, 2.0, 5.0, 10.0})
    if (k * decade >= v * (1 - 1e-12)) return k * decade;
  return 10 * decade;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

Eigen::Vector3f f(const Eigen::Vector3d& v) { return v.cast<float>(); }

// A shaft and a head of two strokes opening across the line of sight.
void arrow(DrawMarks& m, const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3f& eye,
           const Eigen::Vector3f& colour) {
  const Eigen::Vector3f a = f(from), b = f(to);
  const Eigen::Vector3f d = b - a;
  const float len = d.norm();
  if (!(len > 1e-6f)) return;
  m.segments.push_back({a, b, colour});
  Eigen::Vector3f side = d.cross(eye - b);
  if (side.norm() < 1e-9f * len) side = d.unitOrthogonal();
  side.normalize();
  const Eigen::Vector3f back = -d / len * (0.28f * len), wing = side * (0.16f * len);
  m.segments.push_back({b, b + back + wing, colour});
  m.segments.push_back({b, b + back - wing, colour});
}

// Scaled to `per_m` units per metre of arrow, cut at `longest` m.
Eigen::Vector3d arrowVector(const Eigen::Vector3d& v, double per_m, double longest) {
  Eigen::Vector3d d = v / per_m;
  if (d.norm() > longest) d *= longest / d.norm();
  return d;
}

Eigen::Vector3f stateColour(const RecordedContact& c) {
  using namespace overlay_colour;
  switch (c.state) {
    case ContactState::Colliding: return kColliding;
    case ContactState::Separating: return kSeparating;
    case ContactState::Resting: break;
  }
  return c.friction == FrictionState::Sliding ? kSliding : kResting;
}

// The body a pair's marks are drawn on: B, or A when B never moves (the ground gets none).
int drawnOn(const World& world, int a, int b) { return world.bodies[static_cast<std::size_t>(b)].fixedByScene() ? a : b; }

}  // namespace

std::vector<int> velocityBodies(const OverlaySpec& spec, const World& world) {
  std::vector<int> out;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const RigidBody& b = world.bodies[i];
    if (b.fixedByScene()) continue;
    if (spec.bodies.empty() || std::find(spec.bodies.begin(), spec.bodies.end(), b.name) != spec.bodies.end())
      out.push_back(static_cast<int>(i));
  }
  return out;
}

OverlayScales overlayScales(const World& world, const std::vector<double>& radii,
                            const std::vector<FrameRecord>& records, const Trajectory& trajectory,
                            const std::vector<int>& velocity_bodies) {
  std::vector<double> sizes, weights;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    if (world.bodies[i].fixedByScene()) continue;
    if (i < radii.size() && radii[i] > 0) sizes.push_back(radii[i]);
    weights.push_back(world.bodies[i].mass * world.gravity.norm());
  }
  OverlayScales s;
  s.length_m = sizes.empty() ? 0.1 : median(sizes);
  s.longest_m = 4 * s.length_m;
  // A typical body's weight, the force resting contacts carry, is an arrow of about 1.5 sizes.
  const double weight = median(weights);
  s.force_n_per_m = roundUp125((weight > 0 ? weight : 1) / (1.5 * s.length_m));
  double impulse = 0, speed = 0;
  for (const FrameRecord& r : records)
    for (const ImpactMark& m : r.impacts) impulse = std::max(impulse, m.impulse.norm());
  s.impulse_ns_per_m = roundUp125((impulse > 0 ? impulse : 1) / (2 * s.length_m));
  s.impacts = impulse > 0;
  for (const std::vector<BodySample>& frame : trajectory.frames)
    for (int b : velocity_bodies) speed = std::max(speed, frame[static_cast<std::size_t>(b)].v.norm());
  // The fastest body's arrow is about three sizes long.
  s.speed_s = speed > 0 ? 1 / roundUp125(speed / (3 * s.length_m)) : 1;
  return s;
}

DrawMarks overlayMarks(const OverlaySpec& spec, const OverlayScales& scales, const FrameRecord& record,
                       const std::vector<BodySample>& samples, const std::vector<int>& velocity_bodies,
                       const World& world, const Eigen::Vector3f& eye, int frame_height) {
  DrawMarks m;
  const float h = static_cast<float>(frame_height);
  m.line_px = std::max(1.0f, h / 300);
  m.dot_px = std::max(3.0f, h / 90);
  m.outline_px = std::max(0.75f, h / 720);
  m.faint_px = std::max(1.0f, h / 480);
  if (spec.has(OverlayKind::Forces)) {
    for (const RecordedContact& c : record.contacts) {
      if (!c.has_force) continue;
      // The force on B, or its reaction on A when B is the ground: always on the body that moves.
      const Eigen::Vector3d on = drawnOn(world, c.a, c.b) == c.b ? c.force : Eigen::Vector3d(-c.force);
      arrow(m, c.point, c.point + arrowVector(on, scales.force_n_per_m, scales.longest_m), eye, overlay_colour::kForce);
    }
    for (const ImpactMark& i : record.impacts)
      arrow(m, i.point, i.point + arrowVector(i.impulse, scales.impulse_ns_per_m, scales.longest_m), eye,
            overlay_colour::kImpulse);
  }
  if (spec.has(OverlayKind::Velocities))
    for (int b : velocity_bodies) {
      const BodySample& s = samples[static_cast<std::size_t>(b)];
      m.dots.push_back({f(s.x), overlay_colour::kVelocity});
      arrow(m, s.x, s.x + s.v * scales.speed_s, eye, overlay_colour::kVelocity);
    }
  if (spec.has(OverlayKind::Contacts)) {
    // The impacts since the frame before (the Baraff model's, resolved between frames), as colliding.
    for (const ImpactMark& i : record.impacts) {
      const Eigen::Vector3d n = i.on == i.b ? i.normal : Eigen::Vector3d(-i.normal);
      m.segments.push_back({f(i.point), f(i.point + n * (0.5 * scales.length_m)), overlay_colour::kColliding});
      m.dots.push_back({f(i.point), overlay_colour::kColliding});
    }
    for (const RecordedContact& c : record.contacts) {
      const Eigen::Vector3f colour = stateColour(c);
      // The normal as it pushes the body the marks are drawn on.
      const Eigen::Vector3d n = drawnOn(world, c.a, c.b) == c.b ? c.normal : Eigen::Vector3d(-c.normal);
      m.segments.push_back({f(c.point), f(c.point + n * (0.5 * scales.length_m)), colour});
      m.dots.push_back({f(c.point), colour});
    }
  }
  return m;
}

}  // namespace tumble
