#include "dynamics/contact_islands.h"

#include <algorithm>
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

BodyPairGroups groupByBodyPair(const std::vector<Contact>& contacts) {
  BodyPairGroups out;
  const std::size_t m = contacts.size();
  out.order.resize(m);
  std::iota(out.order.begin(), out.order.end(), std::size_t{0});
  auto pairOf = [&](std::size_t i) { return std::make_pair(contacts[i].a, contacts[i].b); };
  std::stable_sort(out.order.begin(), out.order.end(), [&](std::size_t x, std::size_t y) { return pairOf(x) < pairOf(y); });
  for (std::size_t k = 0; k < m;) {
    std::size_t end = k;
    while (end < m && pairOf(out.order[end]) == pairOf(out.order[k])) ++end;
    out.groups.push_back({k, end});
    k = end;
  }
  return out;
}

}  // namespace tumble
