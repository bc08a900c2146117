// Detection that keeps manifolds between steps (ContactDetector::detect with reuse), held against
// detection that runs the narrow phase for every pair, on the same states of a settling pile of
// boxes and convex hulls.
#include <catch2/catch.hpp>

#include <cstdio>
#include <map>
#include <memory>

#include "collision/collision_hull.h"
#include "collision/narrow_phase.h"
#include "contact_scene_runner.h"
#include "dynamics/contact_detection.h"

using namespace tumble;

namespace {

// The deepest point of each pair (m); a pair without contact counts as apart by the margin.
std::map<PiecePair, double> deepestPerPair(const std::vector<Contact>& contacts, const std::vector<PiecePair>& pairs) {
  std::map<PiecePair, double> out;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    auto [it, fresh] = out.emplace(pairs[i], contacts[i].depth);
    if (!fresh) it->second = std::max(it->second, contacts[i].depth);
  }
  return out;
}

}  // namespace

TEST_CASE("kept manifolds: through a settling pile, every pair is as deep as the narrow phase finds it afresh, "
          "to second order in the drift",
          "[contact][time_stepping][kept_manifolds]") {
  ContactSettings settings;   // the default margin (1 mm) and contact tolerance (1e-6 m)
  std::unique_ptr<ContactDetector> kept, fresh;
  std::vector<Contact> kept_contacts, fresh_contacts;
  std::vector<PiecePair> kept_pairs, fresh_pairs;
  double worst = 0, worst_t = 0;
  long compared = 0;
  ContactDetector::Work settled;   // the kept detector's counts when the pile has landed (3 s)
  // The pieces in the detector's order (piece ids): each body's pieces in turn, planes left out.
  struct Piece {
    int body;
    CollisionHull hull;
  };
  std::vector<Piece> pieces;
  const test::SceneRun run = test::runScene(
      "pile_time_stepping", 4.0,
      [&](const World& world) {
        if (!kept) {
          kept = std::make_unique<ContactDetector>(world);
          fresh = std::make_unique<ContactDetector>(world);
          for (std::size_t b = 0; b < world.bodies.size(); ++b)
            if (world.bodies[b].shape != ShapeKind::Plane)
              for (const ConvexPiece& piece : world.bodies[b].pieces) pieces.push_back({int(b), makeCollisionHull(piece)});
        }
        if (world.time < 3.0) settled = kept->work();
        kept->detect(world, settings, kept_contacts, &kept_pairs, nullptr, true);
        fresh->detect(world, settings, fresh_contacts, &fresh_pairs, nullptr, false);
        const auto a = deepestPerPair(kept_contacts, kept_pairs);
        const auto b = deepestPerPair(fresh_contacts, fresh_pairs);
        auto depthIn = [&](const std::map<PiecePair, double>& m, const PiecePair& p) {
          auto it = m.find(p);
          return it == m.end() ? -settings.margin_m : it->second;
        };
        // A pair farther apart than the margin less the slack cannot touch within the step (its
        // reach is in the margin beyond the base margin, contact_detection.h): a feature the kept
        // manifold leaves out may be there, and only there.
        const double cannot_touch = -(1 - ContactDetector::kReuseSlack) * settings.margin_m;
        // A pair apart may be held against its exact distance (GJK) where the fresh narrow phase
        // differs: the fresh phase's points on a face's border carry the clipping's error (a vertex
        // 0.5 um past a wall's bottom edge, clipped there, read 4.7e-7 m farther than the vertex
        // is), which the kept manifold, vertex to plane, does not. (GJK alone is no truth for the
        // gap the narrow phase reports along a face's normal between edges apart.)
        auto apartBy = [&](const PiecePair& p) {
          const Piece &pa = pieces[std::size_t(p.piece_a)], &pb = pieces[std::size_t(p.piece_b)];
          const RigidBody &ba = world.bodies[std::size_t(pa.body)], &bb = world.bodies[std::size_t(pb.body)];
          return pieceDistance(pa.hull, poseOf(ba), pb.hull, poseOf(bb)).distance;
        };
        auto compare = [&](const PiecePair& p) {
          if (depthIn(a, p) < cannot_touch && depthIn(b, p) < cannot_touch) return;
          const bool apart = depthIn(a, p) < 0 && depthIn(b, p) < 0 && p.piece_a >= 0 && p.piece_b >= 0;
          double d = std::abs(depthIn(a, p) - depthIn(b, p));
          if (apart && d > 0) d = std::min(d, std::abs(depthIn(a, p) + apartBy(p)));
          if (d > worst) worst = d, worst_t = world.time;
          ++compared;
        };
        for (const auto& [p, d] : a) compare(p);
        for (const auto& [p, d] : b)
          if (!a.count(p)) compare(p);
      },
      1000000);
  const ContactDetector::Work& w = kept->work();
  const double reused = double(w.manifolds_reused) / double(w.manifolds_reused + w.manifolds_built);
  const long last_reused = w.manifolds_reused - settled.manifolds_reused;
  const long last_built = w.manifolds_built - settled.manifolds_built;
  const double reused_settled = double(last_reused) / double(last_reused + last_built);
  std::printf("kept manifolds, pile 4 s: %ld pairs compared, worst depth difference %.3g m at t = %.4f s; "
              "%.1f %% of pair manifolds reused (%.1f %% in the last second)\n",
              compared, worst, worst_t, 100 * reused, 100 * reused_settled);
  // Only manifolds of corners on a face (and of pairs apart) are kept, and a corner's depth below
  // a face is recomputed exactly; the face's normal turns with its own piece, which the other
  // piece's turn since the manifold was built (at most the slack over its size) moves by second
  // order: slack^2 / size = (1e-4 m)^2 / 0.25 m = 4e-8 m for the pile's smallest pieces. (Keeping
  // clipped corners gave 5.9e-6 m here, and keeping the one point of pieces touching at a vertex
  // 1.4e-5 m.)
  const double slack = ContactDetector::kReuseSlack * settings.margin_m;
  CHECK(worst <= slack * slack / 0.25);
  // And it pays where a pile has landed: its pairs rest face on face.
  CHECK(reused_settled > 0.5);
  CHECK(run.faults == 0);
}
