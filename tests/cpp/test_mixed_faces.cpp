// Faces that are partly wall and partly rim (geometry/mixed_faces.hpp): a B-spline skin over the top wall
// and round the strip's end is split where the wall meets the round, and only there.
#include <gtest/gtest.h>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <Bnd_Box.hxx>
#include <gp_GTrsf.hxx>
#include <gp_Mat.hxx>

#include <algorithm>
#include <string>

#include "geometry/cad_solid.hpp"
#include "geometry/mixed_faces.hpp"
#include "geometry/wall_sides.hpp"
#include "test_boxes.hpp"

using namespace hexlayer;

namespace {

CadSolid readSample(const std::string& path) {
  return prepareSolid(readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/" + path).at(0));
}

// A skin strip (40 x 20 x 2, its round end r = 1) split on `lines` parameter lines of its one skin face: as many
// FaceSplits, all of that face; the pieces (lines + 1) named as the input face, each the half cylinder of the
// round end (pi x 20, a rim) or a flat wall of 40 x 20; then one top, one bottom, `lateral` rim faces, no
// junction, and the strip's volume.
void expectSkinSplit(const std::string& sample, int lines, int lateral) {
  SCOPED_TRACE(sample);
  const CadSolid cad = readSample("Resources/samples/rims/" + sample);
  const std::vector<FaceSplit> splits = findMixedFaces(cad, classifyWallSides(cad));
  ASSERT_EQ(static_cast<int>(splits.size()), lines);
  for (const FaceSplit& f : splits) EXPECT_EQ(f.face, splits[0].face);
  const CadSolid split = splitFaces(cad, splits);
  ASSERT_EQ(split.faces.Extent(), cad.faces.Extent() + lines);
  const double exact = (40 * 2 + M_PI / 2) * 20;  // the profile's area x 20 (OpenCASCADE's volume: to ~1e-3)
  EXPECT_NEAR(split.volume, exact, 2e-3 * exact);
  const WallSides after = classifyWallSides(split);
  EXPECT_TRUE(after.ownSideFaces.empty());
  const int skin = inputFaceOf(cad, splits[0].face);
  int top = 0, bottom = 0, rims = 0, pieces = 0;
  for (int f = 0; f < split.faces.Extent(); ++f) {
    const FaceSide& s = after.faces[f];
    (s.side == Side::Top ? top : s.side == Side::Bottom ? bottom : rims)++;
    if (inputFaceOf(split, f) != skin) continue;
    ++pieces;
    EXPECT_EQ(inputFaceName(split, f), inputFaceName(cad, splits[0].face));
    if (s.side == Side::Lateral)
      EXPECT_NEAR(s.area, M_PI * 20, 0.05) << "the half cylinder";
    else
      EXPECT_NEAR(s.area, 40 * 20, 0.05) << "a flat wall";
  }
  EXPECT_EQ(pieces, lines + 1);
  EXPECT_EQ(top, 1);
  EXPECT_EQ(bottom, 1);
  EXPECT_EQ(rims, lateral);
}

// An open box 60 x 40 x 20 with 2 mm walls whose end wall at x = 0 is 10 high: the other walls stand to 20, and
// the box's outer face at x = 0 (one face: the low end wall's, the side walls' ends above it, flush) is wall below
// z = 10 and the side walls' rims above. Scaled by s; as B-splines (a plane written so by another CAD system or
// by a scaling) if bspline.
TopoDS_Solid lowEndWallBox(double s, bool bspline) {
  using test_boxes::Box;
  const TopoDS_Solid box = test_boxes::boxes(
      {{0, 0, 0, 60, 40, 2}, {0, 0, 0, 60, 2, 20}, {0, 38, 0, 60, 2, 20}, {58, 0, 0, 2, 40, 20}, {0, 0, 0, 2, 40, 10}},
      s);
  if (!bspline) return box;
  gp_GTrsf same;  // the identity, which GTransform writes as B-splines all the same
  TopExp_Explorer it(BRepBuilderAPI_GTransform(box, same, true).Shape(), TopAbs_SOLID);
  return TopoDS::Solid(it.Current());
}

}  // namespace

// The low end wall's outer face (lowEndWallBox) is split at the end wall's top, along the two stretches of the
// line z = 10 inside it (beside the end wall's top rim, a boundary edge): its two strips above (2 x 10 each) are
// rims, the rest (40 x 10) a wall, the side walls' ends then rims like any other wall's end. At x1, 1e-3 and 1e3,
// and as B-splines.
TEST(MixedFaces, AWallFaceRunningOnUpTheEndsOfHigherWallsIsSplitWhereItsWallEnds) {
  for (const double s : {1.0, 1e-3, 1e3})
    for (const bool bspline : {false, true}) {
      SCOPED_TRACE(testing::Message() << "scale " << s << (bspline ? ", B-splines" : ""));
      const CadSolid cad = prepareSolid(lowEndWallBox(s, bspline));
      const std::vector<FaceSplit> splits = findMixedFaces(cad, classifyWallSides(cad));
      ASSERT_EQ(splits.size(), 1u);
      Bnd_Box bounds;
      BRepBndLib::AddOptimal(cad.faces(splits[0].face + 1), bounds, false, false);
      double x0, y0, z0, x1, y1, z1;
      bounds.Get(x0, y0, z0, x1, y1, z1);
      EXPECT_NEAR(x1 / s, 0, 1e-3) << "the face at x = 0";
      EXPECT_NEAR(z1 / s, 20, 1e-3);
      const CadSolid split = splitFaces(cad, splits);
      ASSERT_EQ(split.faces.Extent(), cad.faces.Extent() + 2) << "three pieces";
      EXPECT_NEAR(split.volume, cad.volume, 1e-9 * cad.volume);
      const WallSides after = classifyWallSides(split);
      std::vector<double> rims, walls;
      for (int f = 0; f < split.faces.Extent(); ++f)
        if (inputFaceOf(split, f) == inputFaceOf(cad, splits[0].face))
          (after.faces[f].side == Side::Lateral ? rims : walls).push_back(after.faces[f].area / (s * s));
      ASSERT_EQ(rims.size(), 2u);
      ASSERT_EQ(walls.size(), 1u);
      for (double a : rims) EXPECT_NEAR(a, 2 * 10, 0.05);
      EXPECT_NEAR(walls[0], 40 * 10, 0.5);
    }
}

// strip_skin_round: the top wall and the half-round end one face (Face1), which whole faces itself across the
// wall. It is split once, on the knot where the line meets the circle (x = 40); then four rim faces.
TEST(MixedFaces, SkinOverAWallAndRoundItsEdgeIsSplitWhereTheWallEnds) {
  const CadSolid cad = readSample("Resources/samples/rims/strip_skin_round.step");
  EXPECT_FALSE(classifyWallSides(cad).ownSideFaces.empty()) << "whole, the skin faces itself across the wall";
  expectSkinSplit("strip_skin_round.step", 1, 4);
}

// strip_skin_wrap: the top wall, the round end and the bottom wall one face. It is split on two knots at once
// (x = 40 on the top and on the bottom); then three rim faces (the square end and the two sides) and the half
// cylinder.
TEST(MixedFaces, SkinOverBothWallsAndTheirRimIsSplitTwice) { expectSkinSplit("strip_skin_wrap.step", 2, 4); }

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

// A spherical cap cut by a plane whose walls are B-spline surfaces (tests/data/bspline): the ring of each wall
// along the flat rim, whose rays leave through the rim face, faces one way on the whole but does not turn away
// from the wall beside it (a few degrees on R50): not split. Split, a strip of wall was lost (-2.3 %).
TEST(MixedFaces, CurvedWallsAlongAnObliqueRimAreNotSplit) {
  const CadSolid cad = readSample("tests/data/bspline/cap_cut_by_plane_bspline.step");
  EXPECT_TRUE(findMixedFaces(cad, classifyWallSides(cad)).empty());
}

// An open box 60 x 40 x 20, walls and floor 2, the walls' outer half cut away over the top 4 (a lid's lip, 1 thick):
// each wall's inner face (one plane from the floor to the top) is 2 thick below z = 16 and 1 above. It is split
// along a line near z = 16, its upper piece then 1 thick and its lower 2; the box's other faces are not split. At
// x1, 1e-3 and 1e3. (Split together, OpenCASCADE left three of the four faces whole: each line ends where its
// neighbour's does, on the inside corner's edge; splitThinParts splits those one at a time.) A taper (the wedge plate,
// 1 to 4 thick) is not split.
TEST(MixedFaces, AWallFaceThinnerOverAPartIsSplitWhereTheThicknessSteps) {
  for (const double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(testing::Message() << "scale " << s);
    const CadSolid cad = prepareSolid(test_boxes::boxes({{0, 0, 0, 60, 40, 2},
                                                         {0, 0, 0, 60, 2, 16},
                                                         {0, 38, 0, 60, 2, 16},
                                                         {0, 0, 0, 2, 40, 16},
                                                         {58, 0, 0, 2, 40, 16},
                                                         {1, 1, 16, 58, 1, 4},
                                                         {1, 38, 16, 58, 1, 4},
                                                         {1, 1, 16, 1, 38, 4},
                                                         {58, 1, 16, 1, 38, 4}},
                                                        s));
    EXPECT_TRUE(findMixedFaces(cad, classifyWallSides(cad)).empty()) << "no face partly wall, partly rim";
    const std::vector<FaceSplit> splits = findThinParts(cad, classifyWallSides(cad));
    ASSERT_EQ(splits.size(), 4u) << "the four walls' inner faces";
    const CadSolid split = splitThinParts(cad, splits);
    ASSERT_EQ(split.faces.Extent(), cad.faces.Extent() + 4);
    EXPECT_NEAR(split.volume, cad.volume, 1e-9 * cad.volume);
    const WallSides after = classifyWallSides(split);
    int thin = 0, thick = 0;
    for (const FaceSplit& f : splits) {
      Bnd_Box bounds;
      BRepBndLib::AddOptimal(cad.faces(f.face + 1), bounds, false, false);
      double x0, y0, z0, x1, y1, z1;
      bounds.Get(x0, y0, z0, x1, y1, z1);
      EXPECT_NEAR(z0 / s, 2, 1e-3) << "an inner face, from the floor";
      EXPECT_NEAR(z1 / s, 20, 1e-3);
      for (int g = 0; g < split.faces.Extent(); ++g) {
        if (inputFaceOf(split, g) != inputFaceOf(cad, f.face)) continue;
        Bnd_Box piece;
        BRepBndLib::AddOptimal(split.faces(g + 1), piece, false, false);
        piece.Get(x0, y0, z0, x1, y1, z1);
        const bool upper = z1 / s > 19.99;
        EXPECT_NEAR((upper ? z0 : z1) / s, 16, 1.0) << "split near the step";
        EXPECT_NEAR(after.faces[g].thickness / s, upper ? 1.0 : 2.0, 0.05);
        ++(upper ? thin : thick);
      }
    }
    EXPECT_EQ(thin, 4);
    EXPECT_EQ(thick, 4);
    EXPECT_TRUE(findThinParts(split, after).empty()) << "nothing more to split";
  }
  const CadSolid wedge = readSample("Resources/samples/wedge_plate.step");
  EXPECT_TRUE(findThinParts(wedge, classifyWallSides(wedge)).empty()) << "a taper";
}

// A solid whose faces were split is classified from the rays of the faces left as they were (their rays that hit a
// split face cast again): every face's side, thickness, wall share, opposite face, air gap and every sample's ray as
// a classification from scratch gives them (lowEndWallBox, its outer face at x = 0 split in three; half of the other
// faces left as they were, those whose edges the lines end on made anew). At x1, 1e-3 and 1e3, and as B-splines.
TEST(MixedFaces, TheSplitSolidClassifiedFromTheRaysOfItsFacesLeftAsTheyWereIsClassifiedAsAnew) {
  for (const double s : {1.0, 1e-3, 1e3})
    for (const bool bspline : {false, true}) {
      SCOPED_TRACE(testing::Message() << "scale " << s << (bspline ? ", B-splines" : ""));
      const CadSolid cad = prepareSolid(lowEndWallBox(s, bspline));
      const WallSides before = classifyWallSides(cad);
      const CadSolid split = splitFaces(cad, findMixedFaces(cad, before));
      ASSERT_EQ(split.faces.Extent(), cad.faces.Extent() + 2);
      int kept = 0;
      for (int g = 1; g <= cad.faces.Extent(); ++g) kept += split.faces.FindIndex(cad.faces(g)) > 0;
      EXPECT_GE(kept, cad.faces.Extent() / 2) << "faces left as they were (those meeting the lines' ends are new)";
      const WallSides anew = classifyWallSides(split), reused = classifyWallSidesAfterSplit(split, cad, before);
      EXPECT_EQ(reused.thickness, anew.thickness);
      ASSERT_EQ(reused.faces.size(), anew.faces.size());
      for (std::size_t f = 0; f < anew.faces.size(); ++f) {
        const FaceSide &a = anew.faces[f], &b = reused.faces[f];
        EXPECT_EQ(b.side, a.side) << "face " << f;
        EXPECT_EQ(b.thickness, a.thickness);
        EXPECT_EQ(b.wallShare, a.wallShare);
        EXPECT_EQ(b.opposite, a.opposite);
        EXPECT_EQ(b.airGap, a.airGap);
        ASSERT_EQ(b.marks.size(), a.marks.size());
        for (std::size_t k = 0; k < a.marks.size(); ++k) {
          EXPECT_EQ(b.marks[k].hitFace, a.marks[k].hitFace);
          EXPECT_EQ(b.marks[k].length, a.marks[k].length);
          EXPECT_EQ(b.marks[k].crossing, a.marks[k].crossing);
        }
      }
    }
}
