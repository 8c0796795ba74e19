// The smoothing of poor hexes (sweep/smoothing.hpp) on a block with one inner node pushed aside or tangled.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"
#include "sweep/smoothing.hpp"

using namespace hexlayer;

namespace {

// A 3 x 3 x 2 block of unit hexes in a box: its boundary nodes are not put on the CAD (fixed), its four inner
// nodes (layer 1) free. Returns the mesh; id(i, j, k) is node (i, j, k).
int id(int i, int j, int k) { return (k * 4 + j) * 4 + i; }
// rimOnCad: only the nodes on the box's faces x = 0 and y = 0 are rim nodes (the rest of the block's boundary is
// fixed off the CAD); else every boundary column is.
HexMesh block(bool rimOnCad = false) {
  HexMesh m;
  m.layers = 2;
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 3; ++i) {
        m.nodes.emplace_back(i, j, k);
        m.nodeLayer.push_back(k);
        const bool rim = rimOnCad ? i == 0 || j == 0 : i == 0 || i == 3 || j == 0 || j == 3;
        m.nodeOnRim.push_back(rim ? kRimSwept : 0);
        m.nodeFace.push_back(-1);
      }
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                           id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return m;
}

struct Box {
  CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 30, 30, 2).Solid());  // thin: no node on it
  WallSides sides = classifyWallSides(cad);
  WallProjector walls{cad, sides};
};

}  // namespace

// The block's inner node (1, 1, 1) pushed 0.7 along x and y: the four hexes round it fall below 0.5; smoothing
// moves it back towards its neighbours' mean, and every hex ends above 0.9.
TEST(Smoothing, AFreeInnerNodeGoesBackWhereItsHexesAreSquare) {
  const Box box;
  HexMesh m = block();
  m.nodes[id(1, 1, 1)] += Vec3(0.7, 0.7, 0);
  const SmoothingStats s = smoothPoorHexes(m, box.walls, box.sides);
  EXPECT_LT(s.worstBefore, 0.5);
  EXPECT_GE(s.poorHexes, 1u);
  EXPECT_GT(s.worstAfter, 0.9);
  EXPECT_LT((m.nodes[id(1, 1, 1)] - Vec3(1, 1, 1)).norm(), 0.2);
  for (int k = 0; k <= 2; k += 2) EXPECT_EQ(m.nodes[id(1, 1, k)], Vec3(1, 1, k)) << "not free: a wall node off the CAD";
}

// The same pushed node pinned (a node a wall's foot shares, whose place the wall gives: placeFootEnds'): it stays, and
// its hexes stay poor.
TEST(Smoothing, APinnedNodeStaysWhereItIs) {
  const Box box;
  HexMesh m = block();
  m.nodes[id(1, 1, 1)] += Vec3(0.7, 0.7, 0);
  const Vec3 pushed = m.nodes[id(1, 1, 1)];
  std::vector<char> pinned(m.nodes.size(), 0);
  pinned[id(1, 1, 1)] = 1;
  const SmoothingStats s = smoothPoorHexes(m, box.walls, box.sides, pinned);
  EXPECT_EQ(m.nodes[id(1, 1, 1)], pushed);
  EXPECT_LT(s.worstAfter, 0.9);
}

// A thin block (layers 0.1 high, hexes 1 wide) whose top node above inner node (1, 1, 1) is sheared 0.8 along x:
// its hexes start at 0.097. At its neighbours' mean (where the Laplacian move takes it) the vertical edge above it
// stays slanted far more than the one below, and the Laplacian rounds alone end at 0.116. The pattern search
// moves the inner nodes so that the edges share the slant: the worst hex ends above 0.17.
TEST(Smoothing, APatternSearchSharesASlantTheLaplacianMoveLeaves) {
  const Box box;
  HexMesh m = block();
  for (Vec3& p : m.nodes) p.z() *= 0.1;
  m.nodes[id(1, 1, 2)] += Vec3(0.8, 0, 0);
  const SmoothingStats s = smoothPoorHexes(m, box.walls, box.sides);
  EXPECT_LT(s.worstBefore, 0.1);
  EXPECT_GT(s.searchMoves, 0u);
  EXPECT_GT(s.worstAfter, 0.17);
}

// The block in the box's corner with its rim on the box's lateral faces x = 0 and y = 0: wall node (0, 1, 0), on the
// CAD edge where the bottom wall meets the face x = 0, drawn along that edge past its neighbour (0, 2, 0) to
// y = 2.5 folds the hexes beside it. The Laplacian moves leave it (a node on a rim edge stays); the search slides it
// (and its neighbours) along the edge, and the hexes unfold. Every wall node of the rim stays on the rim edges.
TEST(Smoothing, ANodeOnARimEdgeSlidesAlongItToUnfoldItsHexes) {
  const Box box;
  HexMesh m = block(true);
  m.nodes[id(0, 1, 0)] = Vec3(0, 2.5, 0);
  const SmoothingStats s = smoothPoorHexes(m, box.walls, box.sides);
  EXPECT_LE(s.worstBefore, 0);
  EXPECT_GT(s.searchMoves, 0u);
  EXPECT_GT(s.worstAfter, 0.2);
  const Vec3 slid = m.nodes[id(0, 1, 0)];
  EXPECT_NEAR(slid.x(), 0, 1e-9);
  EXPECT_NEAR(slid.z(), 0, 1e-9);
  EXPECT_LT(slid.y(), m.nodes[id(0, 2, 0)].y()) << "back before its neighbour (which may have slid too)";
  EXPECT_GT(slid.y(), m.nodes[id(0, 0, 0)].y());
  for (int k = 0; k <= 2; k += 2)
    for (int j = 0; j <= 3; ++j) {
      const Vec3 p = m.nodes[id(0, j, k)];
      EXPECT_NEAR(p.x(), 0, 1e-9) << "on the rim edge: " << j << " " << k;
      EXPECT_NEAR(p.z(), k, 1e-9) << "on the rim edge: " << j << " " << k;
    }
}
