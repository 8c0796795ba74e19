// Faces that are partly wall and partly rim (geometry/mixed_faces.hpp): a B-spline skin over the top wall
// and round the strip's end is split where the wall meets the round, and only there.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>

#include <algorithm>
#include <string>

#include "geometry/cad_solid.hpp"
#include "geometry/mixed_faces.hpp"
#include "geometry/wall_sides.hpp"

using namespace hexlayer;

namespace {

CadSolid readSample(const std::string& path) {
  return prepareSolid(readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/" + path).at(0));
}

}  // namespace

// strip_skin_round: 40 x 20 x 2, the top wall and the half-round end (r = 1) one face (Face1). It is split
// once, on the knot where the line meets the circle (x = 40): a flat piece of 40 x 20 and a half cylinder of
// pi x 20, both named Face1; the sides then find one top, one bottom and four rim faces, and no junction.
TEST(MixedFaces, SkinOverAWallAndRoundItsEdgeIsSplitWhereTheWallEnds) {
  const CadSolid cad = readSample("Resources/samples/rims/strip_skin_round.step");
  const WallSides before = classifyWallSides(cad);
  EXPECT_FALSE(before.ownSideFaces.empty()) << "whole, the skin faces itself across the wall";
  const std::vector<FaceSplit> splits = findMixedFaces(cad, before);
  ASSERT_EQ(splits.size(), 1u);
  const CadSolid split = splitFaces(cad, splits);
  ASSERT_EQ(split.faces.Extent(), cad.faces.Extent() + 1);
  EXPECT_NEAR(split.volume, cad.volume, 2e-3 * cad.volume);
  const WallSides after = classifyWallSides(split);
  EXPECT_TRUE(after.ownSideFaces.empty());
  int top = 0, bottom = 0, lateral = 0, pieces = 0;
  for (int f = 0; f < split.faces.Extent(); ++f) {
    const FaceSide& s = after.faces[f];
    (s.side == Side::Top ? top : s.side == Side::Bottom ? bottom : lateral)++;
    if (inputFaceOf(split, f) != inputFaceOf(cad, splits[0].face)) continue;
    ++pieces;
    if (s.side == Side::Lateral)
      EXPECT_NEAR(s.area, M_PI * 20, 0.05) << "the half cylinder";
    else
      EXPECT_NEAR(s.area, 40 * 20, 0.05) << "the flat wall";
  }
  EXPECT_EQ(pieces, 2);
  EXPECT_EQ(top, 1);
  EXPECT_EQ(bottom, 1);
  EXPECT_EQ(lateral, 4);
  EXPECT_EQ(inputFaceName(split, 0), inputFaceName(cad, splits[0].face));
}

// strip_skin_wrap: the same strip whose top wall, round end and bottom wall are one face. It is split on two
// knots at once (x = 40 on the top and on the bottom): three pieces named as the one input face, the half
// cylinder between two flat walls of 40 x 20; then one top, one bottom and three rim faces (the square end, the
// sides and the half cylinder: the box's two sides are one each).
TEST(MixedFaces, SkinOverBothWallsAndTheirRimIsSplitTwice) {
  const CadSolid cad = readSample("Resources/samples/rims/strip_skin_wrap.step");
  const std::vector<FaceSplit> splits = findMixedFaces(cad, classifyWallSides(cad));
  ASSERT_EQ(splits.size(), 2u);
  EXPECT_EQ(splits[0].face, splits[1].face);
  const CadSolid split = splitFaces(cad, splits);
  ASSERT_EQ(split.faces.Extent(), cad.faces.Extent() + 2);
  const WallSides after = classifyWallSides(split);
  EXPECT_TRUE(after.ownSideFaces.empty());
  int top = 0, bottom = 0, lateral = 0, pieces = 0;
  for (int f = 0; f < split.faces.Extent(); ++f) {
    const FaceSide& s = after.faces[f];
    (s.side == Side::Top ? top : s.side == Side::Bottom ? bottom : lateral)++;
    if (inputFaceOf(split, f) != inputFaceOf(cad, splits[0].face)) continue;
    ++pieces;
    if (s.side == Side::Lateral)
      EXPECT_NEAR(s.area, M_PI * 20, 0.05) << "the half cylinder";
    else
      EXPECT_NEAR(s.area, 40 * 20, 0.05) << "a flat wall";
  }
  EXPECT_EQ(pieces, 3);
  EXPECT_EQ(top, 1);
  EXPECT_EQ(bottom, 1);
  EXPECT_EQ(lateral, split.faces.Extent() - 2);
}

// Faces that are wall or rim whole are not split: a thin box (whose top's samples near its rims do not cross
// the wall, but do not turn away from it either), a bent sheet with round ends, a cylinder shell segment.
TEST(MixedFaces, WallsAndRimsAreNotSplit) {
  const CadSolid box = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  EXPECT_TRUE(findMixedFaces(box, classifyWallSides(box)).empty());
  for (const std::string sample :
       {"Resources/samples/rims/lbracket_round_ends.step", "Resources/samples/cylinder_shell.step",
        "Resources/samples/rims/plate_full_round.step"}) {
    const CadSolid cad = readSample(sample);
    EXPECT_TRUE(findMixedFaces(cad, classifyWallSides(cad)).empty()) << sample;
  }
}
