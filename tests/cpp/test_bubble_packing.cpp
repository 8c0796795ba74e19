// Bubble packing (bubbles/bubble_packing.hpp, paper §4): the bubble force, bubble nodes that land on the
// top and bottom faces of a thin box only, and a wall split round a hole packed as one wall (no bubble on its seams),
// on copies scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

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

// A plate's top and bottom split by circles R2 and R4 round a Ø2 hole (test_parts::plateSplitRoundAHole, the faces
// left split by the boolean): the seams are one plane on either side (feature_curves.hpp oneSurfaceSeams), no feature
// the nodes must follow: no bubble on them, the faces packed as one; the hole's rim is one (its curvature limits the
// bubbles: 0.5 rad each, at least 12 round R1 on both walls), with as many as on the plate unsplit. x1, 1e-3, 1e3.
TEST(BubblePacking, SeamsWhereAWallWasSplitAreNotPacked) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    auto byRadius = [&](const CadSolid& cad) {  // nodes on the circles R1, R2, R4 (both walls), by radius
      std::map<long, int> count;
      for (const SurfaceNode& n : packBubbles(cad, classifyWallSides(cad), BubbleOptions{}))
        ++count[std::lround(std::hypot(n.point.x() - 30 * s, n.point.y() - 20 * s) / s * 1e6)];
      return count;
    };
    const CadSolid split = prepareSolid(test_parts::plateSplitRoundAHole(s));
    std::map<long, int> onSplit = byRadius(split);
    EXPECT_GE(onSplit[1000000], 2 * 12) << "the hole's rim, both walls: curvature-limited";
    EXPECT_EQ(onSplit[2000000], 0) << "a seam";
    EXPECT_EQ(onSplit[4000000], 0) << "a seam";
    const CadSolid whole = prepareSolid(test_parts::firstSolid(BRepAlgoAPI_Cut(
        BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60 * s, 40 * s, 2 * s).Shape(),
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30 * s, 20 * s, -s), gp_Dir(0, 0, 1)), s, 4 * s).Shape())));
    EXPECT_EQ(onSplit[1000000], byRadius(whole)[1000000]);
  }
}
