// The smoothing of poor hexes (sweep/smoothing.hpp) on a block with one inner node pushed aside.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"
#include "sweep/smoothing.hpp"

using namespace hexlayer;

// A 3 x 3 x 2 block of unit hexes in a box, its inner node (1, 1, 1) pushed 0.7 along x and y: the four hexes
// round it fall below 0.5; smoothing moves it back towards its neighbours' mean (the only free node: the
// others are on the boundary and not put on the CAD), and every hex ends above 0.9.
TEST(Smoothing, AFreeInnerNodeGoesBackWhereItsHexesAreSquare) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 30, 30, 2).Solid());  // thin: no node on it
  const WallSides sides = classifyWallSides(cad);
  const WallProjector walls(cad, sides);
  HexMesh m;
  m.layers = 2;
  auto id = [](int i, int j, int k) { return (k * 4 + j) * 4 + i; };
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 3; ++i) {
        m.nodes.emplace_back(i, j, k);
        m.nodeLayer.push_back(k);
        m.nodeOnRim.push_back(i == 0 || i == 3 || j == 0 || j == 3 ? kRimSwept : 0);
        m.nodeFace.push_back(-1);
      }
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                           id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  m.nodes[id(1, 1, 1)] += Vec3(0.7, 0.7, 0);
  const SmoothingStats s = smoothPoorHexes(m, walls, sides);
  EXPECT_LT(s.worstBefore, 0.5);
  EXPECT_GE(s.poorHexes, 1u);
  EXPECT_GT(s.worstAfter, 0.9);
  EXPECT_LT((m.nodes[id(1, 1, 1)] - Vec3(1, 1, 1)).norm(), 0.2);
  for (int k = 0; k <= 2; k += 2) EXPECT_EQ(m.nodes[id(1, 1, k)], Vec3(1, 1, k)) << "not free: a wall node off the CAD";
}
