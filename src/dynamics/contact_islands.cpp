#include "dynamics/contact_islands.h"

#include <algorithm>
#include <numeric>

#include "base/pair_order.h"

namespace tumble {
namespace {

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];   // path halving
  return i;
}

}  // namespace

std::vector<std::vector<const Contact*>> splitIntoIslands(const World& world,
                                                          const std::vector<const Contact*>& contacts) {
  ContactIslands split;
  split.split(world, contacts);
  std::vector<std::vector<const Contact*>> islands(split.size());
  for (std::size_t k = 0; k < split.size(); ++k) islands[k].assign(split[k].begin(), split[k].end());
  return islands;
}

void ContactIslands::split(const World& world, std::span<const Contact* const> contacts) {
  std::vector<int>& parent = parent_;
  parent.resize(world.bodies.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Contact* c : contacts) {
    if (world.bodies[c->a].is_static || world.bodies[c->b].is_static) continue;
    int ra = findRoot(parent, c->a), rb = findRoot(parent, c->b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);   // smaller id wins: deterministic
  }
  // Each contact's island, numbered by first contact; then the islands laid out by a counting sort,
  // each keeping its contacts' order.
  island_of_root_.assign(world.bodies.size(), -1);
  island_of_contact_.resize(contacts.size());
  begin_.assign(1, 0);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact* c = contacts[i];
    int body = world.bodies[c->a].is_static ? c->b : c->a;
    int root = findRoot(parent, body);
    if (island_of_root_[root] < 0) {
      island_of_root_[root] = static_cast<int>(begin_.size() - 1);
      begin_.push_back(0);
    }
    island_of_contact_[i] = island_of_root_[root];
    ++begin_[island_of_root_[root] + 1];
  }
  for (std::size_t k = 1; k < begin_.size(); ++k) begin_[k] += begin_[k - 1];
  contacts_.resize(contacts.size());
  // begin_[k] serves as island k's cursor, and is shifted back one island after.
  for (std::size_t i = 0; i < contacts.size(); ++i) contacts_[begin_[island_of_contact_[i]]++] = contacts[i];
  for (std::size_t k = begin_.size() - 1; k > 0; --k) begin_[k] = begin_[k - 1];
  begin_[0] = 0;
}

BodyPairGroups groupByBodyPair(const std::vector<Contact>& contacts) {
  BodyPairGroups out;
  groupByBodyPair(contacts, out);
  return out;
}

void groupByBodyPair(const std::vector<Contact>& contacts, BodyPairGroups& out) {
  const std::size_t m = contacts.size();
  out.groups.clear();
  auto pairOf = [&](std::size_t i) { return std::make_pair(contacts[i].a, contacts[i].b); };
  thread_local PairOrderScratch scratch;
  orderByPair(m, [&](std::size_t i) { return contacts[i].a; }, [&](std::size_t i) { return contacts[i].b; },
                  out.order, scratch);
  for (std::size_t k = 0; k < m;) {
    std::size_t end = k;
    while (end < m && pairOf(out.order[end]) == pairOf(out.order[k])) ++end;
    out.groups.push_back({k, end});
    k = end;
  }
}

}  // namespace tumble
