#include "collision/first_touch.h"

#include <cmath>

#include "collision/narrow_phase.h"

namespace tumble {

Eigen::Isometry3d FreeMotion::at(double t) const {
  Eigen::Isometry3d p = pose;
  p.translation() += velocity * t;
  const double angle = spin.norm() * t;
  if (angle > 0) p.linear() = Eigen::AngleAxisd(angle, spin.normalized()).toRotationMatrix() * pose.linear();
  return p;
}

FirstTouch firstTouch(const CollisionHull& a, const FreeMotion& ma, const CollisionHull& b, const FreeMotion& mb,
                      double horizon, double within) {
  // Each piece's points turn about its body's origin at |w| r at most (r: the piece's radius).
  const double turning = ma.spin.norm() * a.radius + mb.spin.norm() * b.radius;
  FirstTouch out;
  double t = 0;
  // A translating pair settles in one or two iterates (the closest features change at most a few
  // times); a spinning one approaches by shrinking steps. The cap ends those that would not.
  constexpr int kMaxIterates = 32;
  for (int k = 0; k < kMaxIterates; ++k) {
    const PieceDistance d = pieceDistance(a, ma.at(t), b, mb.at(t));
    out.time = t;
    out.point_a = d.point_a;
    out.point_b = d.point_b;
    if (d.distance > 0) out.normal = (d.point_b - d.point_a) / d.distance;
    if (d.distance <= within) return out.touches = true, out;
    const double closing = out.normal.dot(ma.velocity - mb.velocity) + turning;
    if (!(closing > 0)) return out;             // never closer along n: apart for good
    t += (d.distance - 0.5 * within) / closing;
    if (t > horizon) return out;
  }
  out.touches = true;
  return out;
}

}  // namespace tumble
