// core/groups.hpp: items grouped by key with a counting sort.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "core/groups.hpp"

using namespace hexlayer;

// Hexes round the nodes of two hexes sharing a face: each node's group holds the hexes it is in, in the order
// the hexes were given; a key without items has an empty group; the items are all there once.
TEST(Groups, ItemsOfEachKeyInTheOrderGiven) {
  const std::vector<std::array<int, 8>> hexes = {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 8, 9, 2, 5, 10, 11, 6}};
  const std::size_t nodes = 13;  // node 12 is in no hex
  const Groups<int> at = groupByKey<int>(nodes, [&](auto emit) {
    for (int h = 0; h < static_cast<int>(hexes.size()); ++h)
      for (int v : hexes[h]) emit(v, h);
  });
  ASSERT_EQ(at.start.size(), nodes + 1);
  EXPECT_EQ(at.items.size(), 16u);
  auto group = [&](int v) {
    return std::vector<int>(at.items.begin() + at.start[v], at.items.begin() + at.start[v + 1]);
  };
  EXPECT_EQ(group(0), std::vector<int>{0});
  EXPECT_EQ(group(1), (std::vector<int>{0, 1}));
  EXPECT_EQ(group(6), (std::vector<int>{0, 1}));
  EXPECT_EQ(group(11), std::vector<int>{1});
  EXPECT_TRUE(group(12).empty());
}
