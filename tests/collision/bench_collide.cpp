// Micro benchmark (not a test): time per box-box collide call in the situations a pile produces,
// and per ball-box call: an exact sphere against a polyhedral one of 642 vertices (the icosphere a
// sphere was before spheres were exact), a capsule, and a cylinder standing and lying.
// Prints CSV: case,calls,ns_per_call,contacts
#include <ctime>
#include <cstdio>
#include <random>

#include "collision/broad_phase.h"
#include "collision/narrow_phase.h"
#include "geometry/primitives.h"

using namespace tumble;
using Eigen::Vector3d;

namespace {

Eigen::Isometry3d pose(const Vector3d& t, const Eigen::Quaterniond& q) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = q.toRotationMatrix();
  p.translation() = t;
  return p;
}

template <class MakePose>
void run(const char* name, const CollisionHull& ha, const CollisionHull& hb, MakePose make_pose, bool keep_cache) {
  constexpr int kPoses = 1024, kRepeats = 200;
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < kPoses; ++i) poses.push_back(make_pose(i));
  std::vector<SatCache> caches(kPoses);
  ContactManifold m;
  long contacts = 0;
  // CPU time of this process, not wall time: the build machine is shared
  const std::clock_t t0 = std::clock();
  for (int r = 0; r < kRepeats; ++r) {
    for (int i = 0; i < kPoses; ++i) {
      if (!keep_cache) caches[i] = SatCache{};
      contacts += collide(ha, Eigen::Isometry3d::Identity(), hb, poses[i], 0.01, caches[i], m);
    }
  }
  const double ns = 1e9 * double(std::clock() - t0) / CLOCKS_PER_SEC;
  std::printf("%s,%d,%.1f,%ld\n", name, kPoses * kRepeats, ns / (kPoses * kRepeats), contacts);
}

// 1000 unit boxes in a loose 10 x 10 x 10 lattice (touching neighbours), jiggled a little each
// update: the coherent case the insertion sort is for.
void runBroadPhase() {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  SweepAndPrune sap;
  std::vector<Vector3d> centre;
  for (int i = 0; i < 1000; ++i) {
    centre.emplace_back(i % 10 * 1.05, i / 10 % 10 * 1.05, i / 100 * 1.05);
    sap.add({Aabb{centre.back() - Vector3d::Constant(0.55), centre.back() + Vector3d::Constant(0.55)},
             i, false});
  }
  std::vector<ProxyPair> pairs;
  constexpr int kUpdates = 200;
  const std::clock_t t0 = std::clock();
  for (int k = 0; k < kUpdates; ++k) {
    for (int i = 0; i < 1000; ++i) {
      centre[i] += 0.005 * Vector3d(u(rng), u(rng), u(rng));
      sap.setBox(i, {centre[i] - Vector3d::Constant(0.55), centre[i] + Vector3d::Constant(0.55)});
    }
    sap.findPairs(pairs);
  }
  const double ns = 1e9 * double(std::clock() - t0) / CLOCKS_PER_SEC;
  std::printf("broad_phase_1000_boxes,%d,%.1f,%zu\n", kUpdates, ns / kUpdates, pairs.size());
  std::printf("# insertion-sort moves in the last update: %lld\n", (long long)sap.swapsLastUpdate());
}

}  // namespace

int main() {
  const ConvexPiece box = makeBox(Vector3d(0.5, 0.5, 0.5));
  const CollisionHull h = makeCollisionHull(box);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::printf("case,calls,ns_per_call,contacts\n");
  const auto resting = [&](int) {
    return pose(Vector3d(0.3 * u(rng), 0.3 * u(rng), 0.995),
                Eigen::Quaterniond(Eigen::AngleAxisd(u(rng), Vector3d::UnitZ())));
  };
  run("resting_face_face", h, h, resting, true);
  run("resting_face_face_cold_cache", h, h, resting, false);
  const auto random_touching = [&](int) {
    return pose(0.9 * Vector3d(u(rng), u(rng), u(rng)), Eigen::Quaterniond::UnitRandom());
  };
  run("random_near", h, h, random_touching, true);
  const auto separated = [&](int) {
    return pose(Vector3d(1.2 + 0.2 * std::abs(u(rng)), 0.3 * u(rng), 0.3 * u(rng)),
                Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * u(rng), Vector3d::UnitZ())));
  };
  run("separated_cached", h, h, separated, true);
  run("separated_cold_cache", h, h, separated, false);
  // A ball of radius 0.1 m resting on a box's top face anywhere on it, and a capsule lying there.
  const ConvexPiece ball = makeSphere(0.1), facets = makeIcosphere(0.1, 3), pill = makeCapsule(0.1, 0.3);
  const CollisionHull h_ball = makeCollisionHull(ball), h_facets = makeCollisionHull(facets), h_pill = makeCollisionHull(pill);
  const auto on_top = [&](int) {
    return pose(Vector3d(0.4 * u(rng), 0.4 * u(rng), 0.6 - 1e-6), Eigen::Quaterniond::UnitRandom());
  };
  run("ball_on_box_exact_sphere", h, h_ball, on_top, true);
  run("ball_on_box_icosphere_642", h, h_facets, on_top, true);
  const auto lying = [&](int) {
    return pose(Vector3d(0.2 * u(rng), 0.2 * u(rng), 0.6 - 1e-6),
                Eigen::Quaterniond(Eigen::AngleAxisd(u(rng), Vector3d::UnitZ()) * Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX())));
  };
  run("capsule_lying_on_box", h, h_pill, lying, true);
  // A can (radius 0.1 m, height 0.2 m) standing and lying on the box: the support query (GJK/EPA).
  const ConvexPiece can = makeCylinder(0.1, 0.2);
  const CollisionHull h_can = makeCollisionHull(can);
  const auto standing = [&](int) {
    return pose(Vector3d(0.3 * u(rng), 0.3 * u(rng), 0.6 - 1e-6), Eigen::Quaterniond(Eigen::AngleAxisd(u(rng), Vector3d::UnitZ())));
  };
  run("cylinder_standing_on_box", h, h_can, standing, true);
  run("cylinder_lying_on_box", h, h_can, [&](int) {
    return pose(Vector3d(0.2 * u(rng), 0.2 * u(rng), 0.6 - 1e-6),
                Eigen::Quaterniond(Eigen::AngleAxisd(u(rng), Vector3d::UnitZ()) * Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX())));
  }, true);
  runBroadPhase();
}
