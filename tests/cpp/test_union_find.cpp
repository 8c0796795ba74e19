// Union-find and edge keys (core/union_find.hpp): the groups of a known set of unions, their roots (the smallest
// id), the same whatever the order of the unions; one key per undirected edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/union_find.hpp"

using namespace hexlayer;

namespace {

// find of every element after the unions, in that order.
std::vector<int> roots(std::size_t n, const std::vector<std::pair<int, int>>& unions) {
  UnionFind groups(n);
  for (const auto& [a, b] : unions) groups.unite(a, b);
  std::vector<int> out;
  for (std::size_t v = 0; v < n; ++v) out.push_back(groups.find(static_cast<int>(v)));
  return out;
}

}  // namespace

// Over 0..9: {1, 3, 5, 8} joined through a chain, {6, 7}, {2, 9} joined twice, 0 and 4 alone.
TEST(UnionFind, GroupsOfAKnownSetHaveTheirSmallestIdAsRoot) {
  const std::vector<std::pair<int, int>> unions = {{5, 8}, {8, 3}, {7, 6}, {3, 1}, {9, 2}, {2, 9}, {5, 5}};
  EXPECT_EQ(roots(10, unions), (std::vector<int>{0, 1, 2, 1, 4, 1, 6, 6, 1, 2}));
  std::vector<std::pair<int, int>> reversed(unions.rbegin(), unions.rend());
  EXPECT_EQ(roots(10, reversed), roots(10, unions)) << "the same groups whatever the order";
  for (auto& [a, b] : reversed) std::swap(a, b);
  EXPECT_EQ(roots(10, reversed), roots(10, unions)) << "and whichever side each union names first";
  EXPECT_EQ(roots(4, {}), (std::vector<int>{0, 1, 2, 3})) << "no unions: every element is its own group";
}

// A long chain united from its far end: every find ends at 0, and finds do not change the groups.
TEST(UnionFind, LongChainEndsAtItsSmallestId) {
  const int n = 1000;
  UnionFind groups(n);
  for (int v = n - 1; v > 0; --v) groups.unite(v, v - 1);
  for (int pass = 0; pass < 2; ++pass)
    for (int v = 0; v < n; ++v) EXPECT_EQ(groups.find(v), 0) << "pass " << pass << ", element " << v;
}

TEST(UnionFind, EdgeKeyIsOnePerUndirectedEdge) {
  EXPECT_EQ(edgeKey(2, 5), edgeKey(5, 2));
  EXPECT_EQ(edgeKey(2, 5), (std::uint64_t{2} << 32) | 5u);
  EXPECT_NE(edgeKey(2, 5), edgeKey(2, 6));
  EXPECT_NE(edgeKey(2, 5), edgeKey(5, 5));
  EXPECT_NE(edgeKey(0, 1 << 20), edgeKey(1, 0)) << "the ids' bits do not mix";
  std::vector<std::uint64_t> keys;
  for (int a = 0; a < 40; ++a)
    for (int b = a + 1; b < 40; ++b) keys.push_back(edgeKey(b, a));
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end()) << "780 edges, 780 keys";
}
