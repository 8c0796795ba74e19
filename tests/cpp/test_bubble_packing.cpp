// Bubble packing (bubbles/bubble_packing.hpp, paper §4): the bubble force, bubble nodes that land on the
// top and bottom faces of a thin box only, and a wall split round a hole packed as one wall (its seams not as densely
// as the hole's rim), on copies scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>
#include <BRepAdaptor_Curve.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "bubbles/bubble_packing.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"
#include "test_parts.hpp"

using namespace hexlayer;
using hexlayer::test_parts::box;

// Shimada's force f(w) = 1.25 w^3 - 2.375 w^2 + 1.125 on [0, 1.5], 0 beyond.
TEST(BubblePacking, BubbleForceRepelsBelowStableDistanceAndAttractsUpTo1Point5) {
  EXPECT_DOUBLE_EQ(bubbleForce(0.0), 1.125);
  EXPECT_NEAR(bubbleForce(1.0), 0.0, 1e-15);
  EXPECT_NEAR(bubbleForce(1.5), 0.0, 1e-14) << "continuous where it is cut off";
  EXPECT_NEAR(bubbleForce(0.5), 1.25 * 0.125 - 2.375 * 0.25 + 1.125, 1e-15);
  for (double w : {0.1, 0.4, 0.7, 0.95, 0.999}) EXPECT_GT(bubbleForce(w), 0) << "w = " << w;
  for (double w : {1.001, 1.1, 1.25, 1.4, 1.499}) EXPECT_LT(bubbleForce(w), 0) << "w = " << w;
  EXPECT_NEAR(bubbleForce(1.25), 1.25 * 1.953125 - 2.375 * 1.5625 + 1.125, 1e-15);
  for (double w : {1.5001, 1.6, 2.0, 10.0}) EXPECT_EQ(bubbleForce(w), 0.0) << "w = " << w;
  // Repulsion weakens monotonically up to the stable distance.
  for (double w = 0.05; w <= 1.0; w += 0.05) EXPECT_LT(bubbleForce(w), bubbleForce(w - 0.05)) << "w = " << w;
}

// §4: bubbles larger than the wall thickness, on the top and bottom faces and their edges only.
TEST(BubblePacking, PackBubblesOnThinBoxPutsSpacedNodesOnTopAndBottomOnly) {
  const CadSolid cad = box(40, 30, 2);
  const WallSides w = classifyWallSides(cad);
  const std::vector<SurfaceNode> nodes = packBubbles(cad, w, BubbleOptions{});
  ASSERT_GT(nodes.size(), 50u);
  int onTop = 0, onBottom = 0, corners = 0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const SurfaceNode& n = nodes[i];
    const Vec3& p = n.point;
    const bool top = std::abs(p.z() - 2) < 1e-9, bottom = std::abs(p.z()) < 1e-9;
    ASSERT_TRUE(top || bottom) << "node " << i << " at " << p.transpose() << " is inside a lateral face";
    EXPECT_EQ(n.side, top ? Side::Top : Side::Bottom) << "node " << i;
    EXPECT_GE(p.x(), -1e-9);
    EXPECT_LE(p.x(), 40 + 1e-9);
    EXPECT_GE(p.y(), -1e-9);
    EXPECT_LE(p.y(), 30 + 1e-9);
    EXPECT_EQ((n.face >= 0) + (n.edge >= 0) + (n.vertex >= 0), 1) << "node " << i << " on one CAD entity";
    if (n.face >= 0) EXPECT_EQ(w.faces[n.face].side, n.side) << "node " << i << " on a face of the other side";
    onTop += top, onBottom += bottom, corners += n.vertex >= 0;
  }
  EXPECT_EQ(corners, 8);
  EXPECT_GT(onTop, 20);
  EXPECT_GT(onBottom, 20);
  double closest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < nodes.size(); ++i)
    for (size_t j = i + 1; j < nodes.size(); ++j) closest = std::min(closest, (nodes[i].point - nodes[j].point).norm());
  EXPECT_GT(closest, 0.5 * w.thickness);
}

// A plate's top and bottom split by circles R2 and R4 round a Ø2 hole (test_parts::plateSplitRoundAHole): the hole's
// rim is a feature the nodes follow (its curvature limits the bubbles: 0.5 rad each, at least 12 round R1); the seam
// R2 beside the ring 1 wide (half the wall) is not (packed at the wall's bubble diameter, 1.5 x the wall: at most
// 2 pi R / 3 + 1 round it), so the nodes near the hole are as dense on either wall as on the unsplit plate; the seam R4
// between faces as wide as the wall keeps its curve's nodes (a boss's foot circle on a plate). x1, 1e-3, 1e3.
TEST(BubblePacking, ASeamBesideANarrowRingIsPackedAsTheWallNotAsACurvedRim) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = prepareSolid(test_parts::plateSplitRoundAHole(s));
    const WallSides w = classifyWallSides(cad);
    std::map<int, int> onEdge;  // nodes per edge
    for (const SurfaceNode& n : packBubbles(cad, w, BubbleOptions{}))
      if (n.edge >= 0) ++onEdge[n.edge];
    std::map<long, int> byRadius;  // nodes on the circles R1, R2, R4 (both walls), by radius
    for (const auto& [e, count] : onEdge) {
      const BRepAdaptor_Curve curve(TopoDS::Edge(cad.edges(e + 1)));
      if (curve.GetType() != GeomAbs_Circle) continue;
      byRadius[std::lround(curve.Circle().Radius() / (s * cad.unit))] += count;
    }
    ASSERT_EQ(byRadius.size(), 3u);
    EXPECT_GE(byRadius[1], 2 * 11) << "the hole's rim, both walls: curvature-limited";
    EXPECT_LE(byRadius[2], 2 * static_cast<int>(2 * M_PI * 2 / 3 + 1)) << "a seam: the wall's bubbles";
    EXPECT_GE(byRadius[4], 2 * 11) << "a seam between wide faces: curvature-limited";
  }
}
