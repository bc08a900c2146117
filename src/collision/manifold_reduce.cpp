// Contact reduction: the points that keep the support polygon (docs/architecture.md, narrow phase).
// The solver needs the polygon a body rests on, not every vertex of it; four points bound a
// quadrilateral, and picking them by area keeps as much of the support as four points can; where
// that still loses much of it (faces turned against each other), up to four corners more.
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

// Where four points leave out much of the support polygon (two faces turned against each other
// clip to an octagon, whose largest quadrilateral holds 71 % of it at 45 degrees), the corners
// that add the most area are kept too, up to eight, while each adds at least this share of the
// polygon kept so far. A load between the quadrilateral and the octagon (a body struck there, one
// resting on it) would otherwise tip the body about the quadrilateral's edge where the true
// support holds it. Faces turned by a few degrees, or aligned, cut corners far smaller than this
// and keep four points.
constexpr double kAddedAreaShare = 0.05;

constexpr int kMostPoints = 8;

// A convex polygon of point indices, in order (no allocation: the reduction runs for every
// manifold of every step).
struct Ring {
  std::array<int, kMostPoints> at{};
  int size = 0;
  int operator[](int k) const { return at[static_cast<std::size_t>(k % size)]; }
};

// The area (twice, signed by sigma) that q adds to the ring, and the span of its edges q sees:
// [first, last] edge indices (edge k runs from corner k to k + 1). 0 when q is inside.
double addedArea(const std::vector<ContactPoint>& pts, const Ring& ring, int q, const Eigen::Vector3d& n,
                 double sigma, int& first, int& last) {
  const int m = ring.size;
  auto seen = [&](int e) {
    return -sigma * area2(pts[ring[e]].position, pts[ring[e + 1]].position, pts[q].position, n);
  };
  double added = 0;
  first = last = -1;
  for (int k = 0; k < m; ++k) {
    const double a = seen(k);
    if (!(a > 0)) continue;
    added += a;
    // the edges a point outside a convex polygon sees are consecutive (the span may wrap past
    // edge 0): it starts after an edge unseen and ends before one
    if (!(seen(k + m - 1) > 0)) first = k;
    if (!(seen(k + 1) > 0)) last = k;
  }
  return first < 0 || last < 0 ? 0.0 : added;   // every edge seen: a degenerate ring
}

// The ring with corner q added where q sees edges first..last: the corners strictly inside that
// span leave, q takes their place.
void insertCorner(Ring& ring, int q, int first, int last) {
  Ring next;
  for (int k = last + 1;; ++k) {
    next.at[static_cast<std::size_t>(next.size++)] = ring[k];
    if (k % ring.size == first) break;
  }
  next.at[static_cast<std::size_t>(next.size++)] = q;
  ring = next;
}

}  // namespace

void reduceManifold(std::vector<ContactPoint>& points, const Eigen::Vector3d& normal) {
  if (points.size() <= 4) return;
  const int i1 = deepest(points);
  const int i2 = farthestFrom(points, i1, normal);
  const int i3 = largestTriangle(points, i1, i2, normal);
  const int i4 = largestAddition(points, {i1, i2, i3}, normal);
  std::array<int, kMostPoints> kept{i1, i2, i3, i4};
  int count = i4 >= 0 ? 4 : 3;
  if (i4 >= 0) {
    // the quadrilateral as a convex ring (i4 may see two of the triangle's edges), then the
    // corners that each add their share, most first
    const double sigma = area2(points[i1].position, points[i2].position, points[i3].position, normal) >= 0 ? 1 : -1;
    Ring ring;
    ring.at = {i1, i2, i3};
    ring.size = 3;
    double area = sigma * area2(points[i1].position, points[i2].position, points[i3].position, normal);
    int first = -1, last = -1;
    const double quad = addedArea(points, ring, i4, normal, sigma, first, last);
    if (quad > 0) insertCorner(ring, i4, first, last), area += quad;
    while (count < kMostPoints && area > 0) {
      int best = -1, best_first = 0, best_last = 0;
      double most = 0;
      for (int i = 0; i < static_cast<int>(points.size()); ++i) {
        if (std::find(kept.begin(), kept.begin() + count, i) != kept.begin() + count) continue;
        const double a = addedArea(points, ring, i, normal, sigma, first, last);
        if (a > most) most = a, best = i, best_first = first, best_last = last;
      }
      if (best < 0 || most < kAddedAreaShare * area) break;
      insertCorner(ring, best, best_first, best_last);
      kept[static_cast<std::size_t>(count++)] = best;
      area += most;
    }
  }
  std::array<ContactPoint, kMostPoints> chosen;
  for (int k = 0; k < count; ++k) chosen[static_cast<std::size_t>(k)] = points[static_cast<std::size_t>(kept[static_cast<std::size_t>(k)])];
  points.assign(chosen.begin(), chosen.begin() + count);   // fewer than before: no allocation
}

}  // namespace tumble::narrow
