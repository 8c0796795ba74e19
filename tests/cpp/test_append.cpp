// Concatenation of meshes (core/append.hpp): the cells of one more mesh after those already there.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "core/append.hpp"

using namespace hexlayer;

namespace {

// One unit hex with nodes 0..7, its per-node data marked by `mark`, and (if quadratic) mid-edge ids 8..19.
HexMesh oneHex(int mark, bool quadratic) {
  HexMesh m;
  const int nodes = quadratic ? 20 : 8;
  for (int i = 0; i < nodes; ++i) {
    m.nodes.emplace_back(i, mark, 0);
    m.nodeLayer.push_back(i < 4 ? 0 : 1);
    m.nodeOnRim.push_back(0);
    m.nodeFace.push_back(mark);
  }
  m.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
  if (quadratic) m.midEdges.push_back({8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19});
  m.layers = 1;
  return m;
}

}  // namespace

// Triangles end with -1: that stays; every other id moves past the nodes already there.
TEST(Append, CellsShiftTheirIdsButMinusOne) {
  std::vector<std::array<int, 4>> cells{{0, 1, 2, -1}};
  appendCells(cells, {{0, 1, 2, 3}, {2, 1, 0, -1}}, 10);
  EXPECT_EQ(cells, (std::vector<std::array<int, 4>>{{0, 1, 2, -1}, {10, 11, 12, 13}, {12, 11, 10, -1}}));
}

// Two quadratic hexes of 20 nodes each: the second's corners and mid-edge nodes come after the first's 20
// nodes, its per-node data after the first's.
TEST(Append, HexMeshesFollowOneAnother) {
  HexMesh all = oneHex(1, true);
  appendHexMesh(all, oneHex(2, true));
  ASSERT_EQ(all.nodes.size(), 40u);
  ASSERT_EQ(all.hexes.size(), 2u);
  EXPECT_EQ(all.hexes[1], (std::array<int, 8>{20, 21, 22, 23, 24, 25, 26, 27}));
  EXPECT_EQ(all.midEdges[1][0], 28);
  EXPECT_EQ(all.midEdges[1][11], 39);
  EXPECT_EQ(all.nodeFace[19], 1);
  EXPECT_EQ(all.nodeFace[20], 2);
  EXPECT_EQ(all.nodes[25].y(), 2);
  EXPECT_EQ(all.nodeLayer.size(), 40u);
  EXPECT_EQ(all.nodeOnRim.size(), 40u);
  EXPECT_EQ(all.layers, 1);
}

// A hex on top of another, joined on the first's top face: the second's bottom nodes are the first's top nodes
// (same ids), its other nodes and their data follow, the shared ones keep the first's data.
TEST(Append, JoinedMeshesShareTheirCommonNodes) {
  HexMesh all = oneHex(1, false);
  HexMesh top = oneHex(2, false);
  for (Vec3& p : top.nodes) p.z() += 1;
  const std::vector<int> shared{4, 5, 6, 7, -1, -1, -1, -1};
  const std::vector<int> id = joinHexMesh(all, top, shared);
  EXPECT_EQ(id, (std::vector<int>{4, 5, 6, 7, 8, 9, 10, 11}));
  ASSERT_EQ(all.nodes.size(), 12u);
  EXPECT_EQ(all.hexes[1], (std::array<int, 8>{4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(all.nodeFace[7], 1);
  EXPECT_EQ(all.nodeFace[8], 2);
  EXPECT_EQ(all.nodes[8].z(), 1);
  EXPECT_EQ(all.nodeLayer.size(), 12u);
  EXPECT_EQ(all.nodeOnRim.size(), 12u);
}
