// Items grouped by an integer key with a counting sort, each group in the order its items were
// given: what lies around each node of a mesh (quads, hexes, neighbours) in two flat arrays.
#pragma once
#include <cstddef>
#include <vector>

namespace hexlayer {

// The items of key k are items[start[k] .. start[k + 1]).
template <class Index>
struct Groups {
  std::vector<Index> start, items;
};

// Groups items under keys 0 .. keys - 1. forEach(emit) calls emit(key, item) for every item; it is
// called twice (to count, then to fill) and must emit the same items in the same order both times.
template <class Index, class ForEach>
Groups<Index> groupByKey(std::size_t keys, ForEach&& forEach) {
  Groups<Index> g{std::vector<Index>(keys + 1, 0), {}};
  forEach([&](Index key, Index) { ++g.start[key + 1]; });
  for (std::size_t k = 0; k < keys; ++k) g.start[k + 1] += g.start[k];
  g.items.resize(g.start.back());
  std::vector<Index> fill(g.start.begin(), g.start.end() - 1);
  forEach([&](Index key, Index item) { g.items[fill[key]++] = item; });
  return g;
}

}  // namespace hexlayer
