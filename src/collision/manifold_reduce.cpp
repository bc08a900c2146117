// Contact reduction: at most four points that keep the support polygon (docs/architecture.md, narrow phase).
// The solver needs the polygon a body rests on, not every vertex of it; four points bound a
// quadrilateral, and picking them by area keeps as much of the support as four points can.
#include <algorithm>
#include <array>
#include <cmath>
#include <cassert>

#include "collision/narrow_internal.h"

namespace tumble::narrow {

namespace {

// Twice the signed area of triangle (u, v, w) seen along n.
double area2(const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& w,
             const Eigen::Vector3d& n) {
  return (v - u).cross(w - u).dot(n);
}

int deepest(const std::vector<ContactPoint>& pts) {
  int best = 0;  // strict '>' so the first of equal depths wins: deterministic
  for (int i = 1; i < int(pts.size()); ++i) {
    if (pts[i].depth > pts[best].depth) best = i;
  }
  return best;
}

int farthestFrom(const std::vector<ContactPoint>& pts, int from, const Eigen::Vector3d& n) {
  int best = from == 0 ? 1 : 0;
  double far2 = -1;
  for (int i = 0; i < int(pts.size()); ++i) {
    Eigen::Vector3d d = pts[i].position - pts[from].position;
    d -= d.dot(n) * n;  // in the contact plane
    if (i != from && d.squaredNorm() > far2) far2 = d.squaredNorm(), best = i;
  }
  return best;
}

int largestTriangle(const std::vector<ContactPoint>& pts, int i1, int i2, const Eigen::Vector3d& n) {
  // Starts at the first other point, not -1: with non-finite positions (a state the fault check
  // is about to report) every area is NaN and no comparison holds.
  int best = 0;
  while (best == i1 || best == i2) ++best;
  double most = -1;
  for (int i = 0; i < int(pts.size()); ++i) {
    if (i == i1 || i == i2) continue;
    const double a = std::abs(area2(pts[i1].position, pts[i2].position, pts[i].position, n));
    if (a > most) most = a, best = i;
  }
  return best;
}

// The point that adds the most area outside triangle (i1, i2, i3), or -1 if none is outside.
int largestAddition(const std::vector<ContactPoint>& pts, const std::array<int, 3>& tri,
                    const Eigen::Vector3d& n) {
  const Eigen::Vector3d& p1 = pts[tri[0]].position;
  const Eigen::Vector3d& p2 = pts[tri[1]].position;
  const Eigen::Vector3d& p3 = pts[tri[2]].position;
  const double sigma = area2(p1, p2, p3, n) >= 0 ? 1.0 : -1.0;
  int best = -1;
  double most = 0;
  for (int i = 0; i < int(pts.size()); ++i) {
    if (i == tri[0] || i == tri[1] || i == tri[2]) continue;
    const Eigen::Vector3d& q = pts[i].position;
    // how far q lies outside the farthest-out edge: the area it would add to the polygon
    const double out = std::max({-sigma * area2(p1, p2, q, n), -sigma * area2(p2, p3, q, n),
                                 -sigma * area2(p3, p1, q, n)});
    if (out > most) most = out, best = i;
  }
  return best;
}

}  // namespace

void reduceManifold(std::vector<ContactPoint>& points, const Eigen::Vector3d& normal) {
  if (points.size() <= 4) return;
  const int i1 = deepest(points);
  const int i2 = farthestFrom(points, i1, normal);
  const int i3 = largestTriangle(points, i1, i2, normal);
  const int i4 = largestAddition(points, {i1, i2, i3}, normal);
  std::array<ContactPoint, 4> kept{points[i1], points[i2], points[i3], ContactPoint{}};
  int count = 3;
  if (i4 >= 0) kept[count++] = points[i4];
  points.assign(kept.begin(), kept.begin() + count);
}

}  // namespace tumble::narrow
