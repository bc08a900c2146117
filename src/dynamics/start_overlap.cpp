#include "dynamics/start_overlap.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "dynamics/body_extent.h"
#include "dynamics/contact_detection.h"

namespace tumble {

std::vector<StartOverlap> findStartOverlaps(const World& world, double tolerance_m, double depth_share) {
  ContactDetector detector(world);
  ContactSettings settings;
  settings.margin_m = 0;   // overlaps only: pairs merely near each other do not matter here
  settings.tolerance_m = tolerance_m;
  std::vector<Contact> contacts;
  detector.detect(world, settings, contacts);

  std::map<std::pair<int, int>, double> deepest;   // ordered: messages in body order
  for (const Contact& c : contacts) {
    if (c.depth <= tolerance_m) continue;
    double& d = deepest[{std::min(c.a, c.b), std::max(c.a, c.b)}];
    d = std::max(d, c.depth);
  }
  auto thinnest = [&](int body) { return extentOf(world.bodies[body]).thinnest; };   // inf for a plane
  std::vector<StartOverlap> out;
  for (const auto& [pair, depth] : deepest)
    out.push_back({pair.first, pair.second, depth, depth_share * std::min(thinnest(pair.first), thinnest(pair.second))});
  return out;
}

}  // namespace tumble
