// Rim caps (sweep/rim_cap.hpp) on the round ends of a bent sheet.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/pipeline.hpp"
#include "quality/quality.hpp"

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
