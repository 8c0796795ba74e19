// Where one sheet runs on across a CAD edge (geometry/sheet_edges.hpp): smooth and convex edges join faces of
// one sheet, concave ones (where a rib stands on it) do not.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <algorithm>
#include <string>
#include <utility>

#include "geometry/cad_solid.hpp"
#include "geometry/sheet_edges.hpp"
#include "test_parts.hpp"

using namespace hexlayer;

namespace {

CadSolid readSample(const std::string& path) {
  return prepareSolid(readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/" + path).at(0));
}

int count(const std::vector<SheetJoin>& joins, bool smooth) {
  return static_cast<int>(
      std::count_if(joins.begin(), joins.end(), [&](const SheetJoin& j) { return j.smooth == smooth; }));
}

}  // namespace

// A box's 12 edges are all convex and sharp: 12 joins of two distinct faces (lower index first), none smooth.
TEST(SheetEdges, ABoxHasTwelveConvexSharpJoins) {
  const CadSolid box = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const std::vector<SheetJoin> joins = sheetJoins(box);
  EXPECT_EQ(joins.size(), 12u);
  EXPECT_EQ(count(joins, true), 0);
  for (const SheetJoin& j : joins) EXPECT_LT(j.a, j.b);
}

// An L-bracket (rims/lbracket_round_ends): the bend's two cylinders meet the legs' walls at 4 tangent edges,
// and the half-round ends meet the legs' walls at 4 more: 8 smooth joins; the rest (the side faces' edges)
// convex and sharp.
TEST(SheetEdges, ABendAndRoundEndsJoinSmoothly) {
  const CadSolid cad = readSample("Resources/samples/rims/lbracket_round_ends.step");
  const std::vector<SheetJoin> joins = sheetJoins(cad);
  EXPECT_EQ(count(joins, true), 8);
  EXPECT_GT(count(joins, false), 0);
}

// A rib on a plate (robustness/t_junction: a 60 x 40 x 2 plate fused with a 60 x 2 x 12 rib along its middle,
// scripts/make_bad_inputs.py): 10 faces, 24 edges, of which the 2 where the rib's walls meet the plate's top are
// concave: they join nothing; the other 22 are convex and sharp.
TEST(SheetEdges, ConcaveEdgesWhereARibStandsJoinNothing) {
  const CadSolid cad = readSample("tests/data/robustness/t_junction.step");
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(cad.solid, TopAbs_EDGE, edges);
  ASSERT_EQ(edges.Extent(), 24);
  const std::vector<SheetJoin> joins = sheetJoins(cad);
  EXPECT_EQ(joins.size(), 22u);
  EXPECT_EQ(count(joins, true), 0);
  // The other two are concave: where the rib's walls meet the plate's top.
  const std::vector<FacePairEdge> concave = concaveEdges(cad);
  ASSERT_EQ(concave.size(), 2u);
  for (const FacePairEdge& c : concave) {
    EXPECT_LT(c.a, c.b);
    for (const SheetJoin& j : joins) EXPECT_FALSE(j.a == c.a && j.b == c.b) << "an edge is concave or joins";
  }
}

// A pin's round written as 2 or 4 faces, a cylinder or a cone (test_parts::plateWithSplitPin), and its top disc so
// split: every smooth join is between pieces of one surface (the rounds' seams, the discs' radii: 4 joins in
// halves, 8 in quarters), at x1, 1e-3 and 1e3. The bends and half-round ends of an L-bracket (rims/lbracket_round_ends)
// meet its planes smoothly with a step in curvature: none of its 8 smooth joins is.
TEST(SheetEdges, ARoundWrittenInPiecesIsOneSurfaceAcrossItsSeams) {
  for (double s : {1.0, 1e-3, 1e3})
    for (const auto& [pieces, tip] : {std::pair{2, 2.0}, std::pair{4, 2.0}, std::pair{2, 1.0}, std::pair{4, 1.0}}) {
      SCOPED_TRACE("x " + std::to_string(s) + ", " + std::to_string(pieces) + " pieces, tip " + std::to_string(tip));
      const CadSolid cad = prepareSolid(test_parts::plateWithSplitPin(s, pieces, tip));
      const std::vector<SheetJoin> joins = sheetJoins(cad);
      EXPECT_EQ(count(joins, true), 2 * pieces);
      for (const SheetJoin& j : joins) EXPECT_EQ(oneSurfaceAcross(cad, j), j.smooth) << j.a << " " << j.b;
    }
  const CadSolid bracket = readSample("Resources/samples/rims/lbracket_round_ends.step");
  const std::vector<SheetJoin> joins = sheetJoins(bracket);
  ASSERT_EQ(count(joins, true), 8);
  for (const SheetJoin& j : joins) EXPECT_FALSE(oneSurfaceAcross(bracket, j)) << j.a << " " << j.b;
}
