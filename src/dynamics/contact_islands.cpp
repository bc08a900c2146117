#include "dynamics/contact_islands.h"

#include <numeric>

namespace tumble {
namespace {

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];   // path halving
  return i;
}

}  // namespace

std::vector<std::vector<const Contact*>> splitIntoIslands(const World& world,
                                                          const std::vector<const Contact*>& contacts) {
  std::vector<int> parent(world.bodies.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Contact* c : contacts) {
    if (world.bodies[c->a].is_static || world.bodies[c->b].is_static) continue;
    int ra = findRoot(parent, c->a), rb = findRoot(parent, c->b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);   // smaller id wins: deterministic
  }
  std::vector<int> island_of_root(world.bodies.size(), -1);
  std::vector<std::vector<const Contact*>> islands;
  for (const Contact* c : contacts) {
    int body = world.bodies[c->a].is_static ? c->b : c->a;
    int root = findRoot(parent, body);
    if (island_of_root[root] < 0) {
      island_of_root[root] = static_cast<int>(islands.size());
      islands.emplace_back();
    }
    islands[island_of_root[root]].push_back(c);
  }
  return islands;
}

}  // namespace tumble
