// All-quad completion (quad_completion): Gmsh's leftover triangles paired through quad strips.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "quadmesh/quad_completion.hpp"

using namespace hexlayer;

namespace {

std::map<std::pair<int, int>, int> edgeUses(const std::vector<std::array<int, 4>>& quads) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& q : quads)
    for (int k = 0; k < 4; ++k) ++uses[std::minmax(q[k], q[(k + 1) % 4])];
  return uses;
}

}  // namespace

// Triangle (a, b0, c0), quads b0 b1 c1 c0 and b1 b2 c2 c1, triangle (b2, z, c2): a strip of two
// quads between two triangles becomes three quads over the same nodes and the same boundary.
TEST(QuadCompletion, TwoTrianglesAcrossAStripBecomeQuads) {
  enum { a, b0, b1, b2, c0, c1, c2, z };
  std::vector<std::array<int, 4>> quads{{b0, b1, c1, c0}, {b1, b2, c2, c1}};
  std::vector<std::array<int, 3>> triangles{{a, b0, c0}, {b2, z, c2}};
  const QuadCompletion done = pairTriangles(quads, triangles, 20);
  EXPECT_EQ(done.paired, 2u);
  EXPECT_EQ(done.unpaired, 0u);
  EXPECT_TRUE(triangles.empty());
  ASSERT_EQ(quads.size(), 3u);
  std::set<int> used;
  for (const auto& q : quads) {
    EXPECT_EQ(std::set<int>(q.begin(), q.end()).size(), 4u) << "four distinct corners";
    used.insert(q.begin(), q.end());
  }
  EXPECT_EQ(used.size(), 8u) << "every node is still used";
  int rim = 0;
  for (const auto& [edge, n] : edgeUses(quads)) {
    EXPECT_LE(n, 2);
    rim += n == 1;
  }
  EXPECT_EQ(rim, 8) << "the strip's outline: a-b0-b1-b2-z-c2-c1-c0-a";
}

TEST(QuadCompletion, NeighbouringTrianglesBecomeOneQuad) {
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  const QuadCompletion done = pairTriangles(quads, triangles, 0);
  EXPECT_EQ(done.paired, 2u);
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_EQ(std::set<int>(quads[0].begin(), quads[0].end()), (std::set<int>{0, 1, 2, 3}));
}

// A triangle whose strips all end at the boundary (or are longer than allowed) stays, counted.
TEST(QuadCompletion, ALoneTriangleIsCountedAsAHole) {
  std::vector<std::array<int, 4>> quads{{1, 3, 4, 2}};
  std::vector<std::array<int, 3>> triangles{{0, 1, 2}};
  const QuadCompletion done = pairTriangles(quads, triangles, 20);
  EXPECT_EQ(done.paired, 0u);
  EXPECT_EQ(done.unpaired, 1u);
  EXPECT_EQ(quads.size(), 1u);
  EXPECT_EQ(triangles.size(), 1u);
}

// A lone triangle beside a row of two quads: the triangle becomes three quads and the row, whose
// edge the triangle's edge midpoint splits, is halved lengthwise up to the rim.
//   3---4---5          nodes 0..5 a 2 x 1 row of quads (0 1 4 3), (1 2 5 4);
//   |   |   |          triangle (3, 4, 6) above it.
//   0---1---2
TEST(QuadCompletion, ALoneTriangleIsSplitAndItsStripHalved) {
  std::vector<Vec3> nodes{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0.5, 2, 0}};
  std::vector<std::array<int, 4>> quads{{0, 1, 4, 3}, {1, 2, 5, 4}};
  std::vector<std::array<int, 3>> triangles{{3, 4, 6}};
  EXPECT_EQ(splitTriangles(nodes, quads, triangles), 1u);
  EXPECT_TRUE(triangles.empty());
  EXPECT_EQ(quads.size(), 3u + 2u + 1u) << "3 from the triangle, the quad below it halved, its neighbour untouched";
  double area = 0;
  for (const auto& q : quads) {
    EXPECT_EQ(std::set<int>(q.begin(), q.end()).size(), 4u);
    const Vec3 n = (nodes[q[2]] - nodes[q[0]]).cross(nodes[q[3]] - nodes[q[1]]);
    EXPECT_GT(n.z(), 0) << "orientation kept";
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 2.0 + 0.5, 1e-12) << "same area as the row and the triangle";
  for (const auto& [edge, n] : edgeUses(quads)) EXPECT_LE(n, 2) << "conformal";
}
