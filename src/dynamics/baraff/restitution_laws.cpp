#include "dynamics/baraff/restitution_laws.h"

#include "dynamics/baraff/impact_energy.h"
#include "dynamics/baraff/point_impact.h"
#include "dynamics/baraff/two_phase_impact.h"
#include "dynamics/contact_jacobian.h"

namespace tumble {
namespace {

// One point's contact frame: its normal row and two tangent rows (tangentsOf), whatever its
// friction: the tangential velocity changes with the normal impulse even without friction.
std::vector<ContactRow> frameRows(const World& world, const Contact& c) {
  Eigen::Vector3d t1, t2;
  tangentsOf(c.normal, t1, t2);
  return {rowAlong(world, c, c.normal), rowAlong(world, c, t1), rowAlong(world, c, t2)};
}

// Why e = 0 adds no energy (the energy rule's fallback, impact_energy.h). At one point the energy
// change is the integral of u . dp along the impact: u_n <= 0 while compressing, and friction's
// dp_t is against the slip or holds it stopped. Over several points each phase is an inelastic
// LCP (impulse_propagation.cpp), and restitution with e = 0 has nothing to give back. Stronge's
// law at one point adds none for any e: the normal work ends at (1 - e^2) W(p_c) <= 0 and
// friction's is <= 0; Poisson's can add some where the slip stops or turns during restitution.
bool pointImpact(World& world, const Contact& c, const std::vector<const Contact*>& points, double e,
                 RestitutionLaw law, double restitution_scale) {
  const std::vector<ContactRow> rows = frameRows(world, c);
  const Eigen::Matrix3d K = delassus(world, rows);
  const Eigen::Vector3d u(rowVelocity(world, rows[0]), rowVelocity(world, rows[1]),
                          rowVelocity(world, rows[2]));
  // Compression is the same for every e: if it ends for one, it ends for all.
  const PointImpact full = followPointImpact(K, u, c.friction, restitution_scale * e, law);
  if (!full.ended) return false;
  auto apply = [&](double scale) {
    PointImpact impact = scale == restitution_scale ? full : followPointImpact(K, u, c.friction, scale * e, law);
    if (!impact.ended) impact = followPointImpact(K, u, c.friction, 0, law);
    applyAlongRows(world, rows, impact.p);
  };
  // The normal impulse alone that stops the approach: a projection (energy change -p^2 K_nn / 2).
  auto inelastic = [&] {
    const Eigen::Vector3d p(-u[0] / K(0, 0), 0, 0);
    applyAlongRows(world, rows, p);
  };
  applyAddingNoEnergy(world, points, restitution_scale, apply, inelastic);
  return true;
}

}  // namespace

bool restitutionLawImpact(World& world, const std::vector<const Contact*>& points, const std::vector<double>& vn,
                          RestitutionLaw law, const BounceThreshold& min_bounce_speed, double restitution_scale,
                          ContactSolveStats& stats) {
  std::vector<double> e;
  for (std::size_t i = 0; i < points.size(); ++i) e.push_back(vn[i] < -min_bounce_speed.along(points[i]->normal) ? points[i]->restitution : 0.0);
  if (points.size() == 1) return pointImpact(world, *points[0], points, e[0], law, restitution_scale);
  auto scaled = [&](double scale) {
    std::vector<double> out;
    for (double x : e) out.push_back(scale * x);
    return out;
  };
  applyAddingNoEnergy(
      world, points, restitution_scale,
      [&](double scale) { applyTwoPhaseImpact(world, points, scaled(scale), law, true, stats); },
      [&] { applyTwoPhaseImpact(world, points, scaled(0), law, false, stats); });
  return true;
}

}  // namespace tumble
