// Rim caps (sweep/rim_cap.hpp) on the round ends of a bent sheet, and the smoothing of poor hexes
// (sweep/smoothing.hpp) on a block with one inner node pushed aside.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>

#include <cmath>
#include <string>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"
#include "pipeline/pipeline.hpp"
#include "quality/quality.hpp"
#include "sweep/smoothing.hpp"

using namespace hexlayer;

// lbracket_round_ends: two half-round ends (radius 1), 20 wide, 2 mm wall (rims/README.md). With 2 layers the
// sweep's last column runs between the round's edges and a cap column of 3 nodes lies on the half circle at
// 45, 90 and 135 degrees: every cap node is a rim node on a CAD face, every capped rim edge has 2 cap hexes,
// and the mesh loses 4 chords' lens of each half disc (0.157 r^2 per length) where 2 chords' (0.571 r^2, 22.8
// mm^3 for both ends) would be lost without the caps, bend's chords aside.
TEST(RimCap, RoundEndsGetACapOnTheHalfCircle) {
  MeshOptions o;
  o.layers = 2;
  const MeshResult r =
      meshFile(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/rims/lbracket_round_ends.step", o);
  const RimCapStats& cap = r.report.rimCap;
  ASSERT_GT(cap.cappedEdges, 0u);
  EXPECT_EQ(cap.capHexes, 2 * cap.cappedEdges);
  EXPECT_EQ(cap.capColumns, cap.cappedEdges + 2) << "two open rows of edges, one per end";
  std::size_t capNodes = 0;
  for (std::size_t i = 0; i < r.mesh.nodes.size(); ++i) {
    if (r.mesh.nodeOnRim[i] != kRimCap) continue;
    ++capNodes;
    EXPECT_GE(r.mesh.nodeFace[i], 0);
  }
  EXPECT_EQ(capNodes, 3 * cap.capColumns);
  const double uncapped = 0.571 * 2 * 20;  // both ends, 20 wide, r = 1
  const double lost = r.report.mesh.cadVolume - r.report.mesh.quality.volume;
  EXPECT_LT(lost, 0.7 * uncapped) << "the caps' chords and the bend's";
  EXPECT_GT(lost, 0);
  EXPECT_GE(r.report.mesh.quality.sjMin, 0.7);  // a cap hex's 135 degree corner: 0.707
}

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
