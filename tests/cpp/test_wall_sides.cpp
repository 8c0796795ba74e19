// Top, bottom and lateral faces (geometry/wall_sides.hpp) on rims of every shape: a ray crosses the wall
// when its middle is as far from the whole boundary as from its ends, decided per sample; a cut through the part (a
// junction piece's foot) is no such boundary.
#include <gtest/gtest.h>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_sides.hpp"
#include "test_parts.hpp"

using namespace hexlayer;
using hexlayer::test_parts::box;

namespace {

CadSolid readSample(const std::string& path) {
  return prepareSolid(readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/" + path).at(0));
}

BRepAdaptor_Surface surfaceOf(const CadSolid& cad, int f) {
  return BRepAdaptor_Surface(TopoDS::Face(cad.faces(f + 1)));
}

int count(const WallSides& w, Side side) {
  int n = 0;
  for (const FaceSide& f : w.faces) n += f.side == side;
  return n;
}

Vec3 faceCentre(const CadSolid& cad, int f) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(cad.faces(f + 1), props);
  const gp_Pnt c = props.CentreOfMass();
  return {c.X(), c.Y(), c.Z()};
}

// Calls check(cad, w, s) on part(s) (a solid at scale s) classified (w, with `faces` faces), at scales 1, 1e-3, 1e3.
template <class Part, class Check>
void atEachScale(Part part, std::size_t faces, Check check) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = prepareSolid(part(s));
    const WallSides w = classifyWallSides(cad);
    ASSERT_EQ(w.faces.size(), faces);
    check(cad, w, s);
  }
}

}  // namespace

// A sample of the top crosses the wall unless the middle of its ray (1 below it) is nearer a side than
// 1 / 1.3: the share of the 40 x 30 top farther than 0.77 from its sides. No ray of a side crosses it.
TEST(WallSides, ThinBoxTopCrossesTheWallButNearItsSidesAndTheSidesNowhere) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallSides w = classifyWallSides(cad);
  const double d = 1 / 1.3, share = (40 - 2 * d) * (30 - 2 * d) / (40 * 30);
  for (const FaceSide& f : w.faces) {
    if (f.side == Side::Lateral)
      EXPECT_EQ(f.wallShare, 0.0);
    else
      EXPECT_NEAR(f.wallShare, share, 0.04) << "the samples stand for about 3 x 3 each";
  }
}

// The half-cylinder ends (radius t/2) of a bent sheet: their rays hit the ends themselves or run along the
// wall; they are rims, and the sheet's walls are one top and one bottom side, with no branching.
TEST(WallSides, FullRoundEndsAreLateral) {
  const CadSolid cad = readSample("Resources/samples/rims/lbracket_round_ends.step");
  const WallSides w = classifyWallSides(cad);
  int ends = 0;
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    const BRepAdaptor_Surface s = surfaceOf(cad, f);
    if (s.GetType() == GeomAbs_Cylinder && std::abs(s.Cylinder().Radius() - 1.0) < 1e-9) {
      ++ends;
      EXPECT_EQ(w.faces[f].side, Side::Lateral) << "Face" << f + 1;
      EXPECT_LT(w.faces[f].wallShare, 0.5);
    }
  }
  EXPECT_EQ(ends, 2);
  EXPECT_EQ(count(w, Side::Top), 3);
  EXPECT_EQ(count(w, Side::Bottom), 3);
  EXPECT_TRUE(w.ownSideFaces.empty());
  EXPECT_EQ(findSheets(cad, w).size(), 1u);
  EXPECT_NEAR(w.thickness, 2.0, 1e-3);
}

// Chamfers at 45 degrees and rims cut at 45 and 70.5 degrees are rim faces however wide; only the faces
// parallel to the walls' plane are walls. The cut at 70.5 degrees (3 walls wide) first faces the opposite wall
// across a knife edge; being narrower than kMaxObliqueRim walls across that edge, it is made a rim.
TEST(WallSides, ChamferedAndObliqueRimsAreLateral) {
  for (const char* part : {"plate_chamfer_both_sides", "plate_chamfer_one_side", "strip_oblique_45", "strip_oblique_3x",
                           "plate_split_rim"}) {
    const CadSolid cad = readSample(std::string("Resources/samples/rims/") + part + ".step");
    const WallSides w = classifyWallSides(cad);
    for (int f = 0; f < cad.faces.Extent(); ++f) {
      const BRepAdaptor_Surface s = surfaceOf(cad, f);
      ASSERT_EQ(s.GetType(), GeomAbs_Plane);
      const bool horizontal = std::abs(std::abs(s.Plane().Axis().Direction().Z()) - 1) < 1e-9;
      EXPECT_EQ(w.faces[f].side != Side::Lateral, horizontal) << part << " Face" << f + 1;
    }
    EXPECT_TRUE(w.knifeEdges.empty()) << part;
    EXPECT_EQ(w.obliqueRims.size(), std::string(part) == "strip_oblique_3x" ? 2u : 0u) << part;
  }
}

// A blade: a 60 x 20 strip, 2 thick, whose top slopes down to the bottom over its last 20 mm (a face 10 walls
// wide across its knife edge): the slope is a wall that tapers out, not a rim.
TEST(WallSides, KnifeEdgeTapersTheWall) {
  BRepBuilderAPI_MakePolygon profile;
  for (const gp_Pnt& p : {gp_Pnt(0, 0, 0), gp_Pnt(60, 0, 0), gp_Pnt(40, 0, 2), gp_Pnt(0, 0, 2)}) profile.Add(p);
  profile.Close();
  const TopoDS_Shape blade =
      BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(profile.Wire()).Face(), gp_Vec(0, 20, 0)).Shape();
  TopExp_Explorer solid(blade, TopAbs_SOLID);
  const CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()));
  const WallSides w = classifyWallSides(cad);
  EXPECT_EQ(count(w, Side::Top), 2);
  EXPECT_EQ(count(w, Side::Bottom), 1);
  EXPECT_EQ(w.knifeEdges.size(), 1u);
  EXPECT_TRUE(w.obliqueRims.empty());
  EXPECT_TRUE(w.ownSideFaces.empty());
}

// A wall split into coplanar faces is wall in every piece; a bend split into tangent faces too.
TEST(WallSides, SplitWallsAreWallsInEveryPiece) {
  const CadSolid walls = readSample("Resources/samples/rims/plate_split_walls.step");
  const WallSides w = classifyWallSides(walls);
  EXPECT_EQ(count(w, Side::Top), 3);
  EXPECT_EQ(count(w, Side::Bottom), 3);
  const CadSolid bend = readSample("Resources/samples/rims/lbracket_split_bend.step");
  const WallSides b = classifyWallSides(bend);
  EXPECT_EQ(count(b, Side::Top) + count(b, Side::Bottom), 9);
  EXPECT_EQ(findSheets(bend, b).size(), 1u);
}

// A plate's top and bottom split by circles R2 and R4 round a Ø2 hole: the rings next to the hole, 1 wide (half the
// wall), are wall though most of their rays pass the hole on the way (wallExtensions): every face facing +-z is wall,
// three on each side, the hole's wall and the four sides are rims. On copies scaled by 1e-3 and 1e3.
TEST(WallSides, ANarrowRingOfASplitWallRoundAHoleIsWall) {
  atEachScale(test_parts::plateSplitRoundAHole, 11, [](const CadSolid& cad, const WallSides& w, double s) {
    EXPECT_EQ(count(w, Side::Top), 3);
    EXPECT_EQ(count(w, Side::Bottom), 3);
    for (int f = 0; f < static_cast<int>(w.faces.size()); ++f)
      if (surfaceOf(cad, f).GetType() == GeomAbs_Plane &&
          std::abs(surfaceOf(cad, f).Plane().Axis().Direction().Z()) > 0.99)
        EXPECT_NE(w.faces[f].side, Side::Lateral) << "face " << f;
    EXPECT_NEAR(w.thickness, 2 * s, 1e-6 * s);
  });
}

// A short-walled box with a lid's lip (test_parts::shortWalledLippedBox): the walls' outer faces under the ledge cross
// the wall on under half their area (0.47: the floor's end and the band near the ledge run along a wall), but they are
// flat and face the walls' inner faces across the wall's thickness: walls (shortWallFaces), not rims, and the part is
// one sheet; only the ledge and the lip's top are rims. On copies scaled by 1e-3 and 1e3.
TEST(WallSides, AShortWallUnderALedgeIsAWall) {
  atEachScale(test_parts::shortWalledLippedBox, 16, [](const CadSolid& cad, const WallSides& w, double s) {
    for (int f = 0; f < static_cast<int>(w.faces.size()); ++f) {
      const Vec3 c = faceCentre(cad, f) / s;
      const bool rim = std::abs(c.z() - 8.1) < 1e-6 || std::abs(c.z() - 12) < 1e-6;
      EXPECT_EQ(w.faces[f].side == Side::Lateral, rim) << "face " << f << " at " << c.transpose();
      if (std::abs(c.x()) < 1e-6) EXPECT_LT(w.faces[f].wallShare, 0.5) << "the outer face under the ledge";
    }
    EXPECT_EQ(findSheets(cad, w).size(), 1u);
  });
}

// A pin standing on a plate, its round written as 2 or 4 faces (test_parts::plateWithSplitPin, a cylinder and a cone):
// the pieces face each other across the pin, as a round of one face meets itself, which is no wall branching
// (oneSurfaceGroups; before, they were all on one side facing each other: ownSideFaces, the part refused). As with a
// round of one face, the pin is a sheet of its own standing on the plate: two sheets, the pin's every piece of its
// round, on one side. At x1, 1e-3 and 1e3.
TEST(WallSides, APinsRoundWrittenInPiecesIsNoBranch) {
  for (const auto& [pieces, tip] : {std::pair{2, 2.0}, std::pair{4, 2.0}, std::pair{4, 1.0}}) {
    SCOPED_TRACE(std::to_string(pieces) + " pieces, tip " + std::to_string(tip));
    const int n = pieces;
    const double r = tip;
    const auto part = [n, r](double s) { return test_parts::plateWithSplitPin(s, n, r); };
    atEachScale(part, 6 + 2 * static_cast<std::size_t>(n), [n, r](const CadSolid& cad, const WallSides& w, double s) {
      EXPECT_TRUE(w.ownSideFaces.empty());
      const std::vector<Sheet> sheets = findSheets(cad, w);
      ASSERT_EQ(sheets.size(), 2u);
      ASSERT_EQ(sheets[1].faces.size(), static_cast<std::size_t>(n));
      for (int f : sheets[1].faces) {
        EXPECT_EQ(w.faces[f].side, w.faces[sheets[1].faces[0]].side);
        EXPECT_NEAR(faceCentre(cad, f).z() / s, r < 2 ? 58.0 / 9 : 7, 1e-6);  // the round's area centroid
      }
    });
  }
}

// A rib standing on a plate still branches the sheet: it is found (here as a second sheet), where it is.
TEST(WallSides, RibOnAPlateIsStillAJunction) {
  const CadSolid cad = readSample("tests/data/robustness/t_junction.step");
  const WallSides w = classifyWallSides(cad);
  const std::vector<Sheet> sheets = findSheets(cad, w);
  EXPECT_TRUE(sheets.size() >= 2 || !w.ownSideFaces.empty());
}

// A 40 x 30 x 2 plate: 2 mm thick, z = 2 is Top, z = 0 Bottom, the four rim faces Lateral.
TEST(WallSides, ThinBoxHasOneTopOneBottomAndFourLateralFaces) {
  const CadSolid cad = box(40, 30, 2);
  EXPECT_NEAR(cad.volume, 2400.0, 1e-9 * 2400);
  EXPECT_EQ(cad.faces.Extent(), 6);
  EXPECT_NEAR(cad.diagonal, std::sqrt(40.0 * 40 + 30 * 30 + 2 * 2), 1e-6);
  const WallSides w = classifyWallSides(cad);
  ASSERT_EQ(w.faces.size(), 6u);
  EXPECT_NEAR(w.thickness, 2.0, 2e-6);
  EXPECT_NEAR(w.sheetAreaShare, 2400.0 / (2400 + 2 * (40 * 2 + 30 * 2)), 1e-6);
  int top = -1, bottom = -1, lateral = 0;
  for (int f = 0; f < 6; ++f) {
    const Vec3 c = faceCentre(cad, f);
    switch (w.faces[f].side) {
      case Side::Top:
        EXPECT_EQ(top, -1) << "two Top faces";
        top = f;
        EXPECT_NEAR(c.z(), 2.0, 1e-9);
        break;
      case Side::Bottom:
        EXPECT_EQ(bottom, -1) << "two Bottom faces";
        bottom = f;
        EXPECT_NEAR(c.z(), 0.0, 1e-9);
        break;
      case Side::Lateral:
        ++lateral;
        EXPECT_NEAR(c.z(), 1.0, 1e-9);
        break;
    }
  }
  ASSERT_GE(top, 0);
  ASSERT_GE(bottom, 0);
  EXPECT_EQ(lateral, 4);
  EXPECT_NEAR(w.faces[top].thickness, 2.0, 2e-6);
  EXPECT_NEAR(w.faces[bottom].thickness, 2.0, 2e-6);
  EXPECT_EQ(w.faces[top].opposite, bottom);
  EXPECT_EQ(w.faces[bottom].opposite, top);
  EXPECT_NEAR(w.faces[top].area, 1200.0, 1e-6);
}

TEST(WallSides, CubeIsNotAThinSection) {
  const CadSolid cad = box(20, 20, 20);
  EXPECT_NEAR(cad.volume, 8000.0, 1e-9 * 8000);
  try {
    classifyWallSides(cad);
    FAIL() << "a cube was classified as a thin wall";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::UnsupportedGeometry);
    EXPECT_NE(std::string(e.what()).find("not a thin section"), std::string::npos) << e.what();
  }
}

// A low rib's piece cut off its plate (junction_cut.hpp): 40 long, 2 thick, 2 or 3 high, its bottom face the foot, a
// cut through the part (CadSolid::cutInput). The cut is no boundary a wall is measured against: the rib's two sides
// are its walls, 2 apart, and the foot and the top and ends rims. Taken for the part's boundary, the foot leaves too
// little of each side crossing the wall (2 high: not a thin section; 3 high: about half). At scales 1, 1e-3, 1e3.
TEST(WallSides, ALowRibsPieceHasWallsWhenItsFootIsACut) {
  for (const double high : {2.0, 3.0})
    for (const double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE("high " + std::to_string(high) + " x " + std::to_string(s));
      const TopoDS_Solid rib = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40 * s, 2 * s, high * s).Solid();
      CadSolid cad = prepareSolid(rib, normalizingUnit(rib));
      int foot = -1;
      for (int f = 0; f < cad.faces.Extent(); ++f)
        if (surfaceOf(cad, f).GetType() == GeomAbs_Plane && std::abs(faceCentre(cad, f).z()) < 1e-9 * cad.diagonal)
          foot = f;
      ASSERT_GE(foot, 0);
      if (high == 2) EXPECT_THROW(classifyWallSides(cad), Error);  // 3 high: about half of each side crosses
      cad.cutInput.assign(cad.faces.Extent(), 0);
      cad.cutInput[foot] = 1;
      const WallSides w = classifyWallSides(cad);
      EXPECT_NEAR(w.thickness / cad.unit / s, 2, 1e-6);
      EXPECT_EQ(count(w, Side::Lateral), 4);
      for (int f = 0; f < cad.faces.Extent(); ++f)
        if (w.faces[f].side != Side::Lateral) EXPECT_NEAR(std::abs(faceCentre(cad, f).y()) / cad.unit / s, 1, 1);
      EXPECT_EQ(findSheets(cad, w).size(), 1u);
    }
}

// A tab's piece cut off a box's floor and wall (the Framework cover's tab, 2.5 walls thick): 5 x 6 x 13, its faces
// z = 0 and y = 6 the feet (cuts through the part). Its wall, 5 thick, is 0.33 of its own diagonal: over the whole
// part's bar (0.25), not over a piece's (kMaxPieceSlenderness); the same box with no cut face is refused, and a cube
// piece still is. At scales 1, 1e-3, 1e3.
TEST(WallSides, AChunkyJunctionPieceIsThinWhileAWholePartAsChunkyIsNot) {
  for (const double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    for (const auto& [width, length] : {std::pair{5.0, 6.0}, std::pair{13.0, 13.0}}) {  // a cube: 0.58
      const TopoDS_Solid tab = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), width * s, length * s, 13 * s).Solid();
      CadSolid cad = prepareSolid(tab, normalizingUnit(tab));
      EXPECT_THROW(classifyWallSides(cad), Error);
      cad.cutInput.assign(cad.faces.Extent(), 0);
      for (int f = 0; f < cad.faces.Extent(); ++f) {
        const Vec3 c = faceCentre(cad, f) / cad.unit / s;
        cad.cutInput[f] =
            surfaceOf(cad, f).GetType() == GeomAbs_Plane && (std::abs(c.z()) < 1e-9 || std::abs(c.y() - length) < 1e-9);
      }
      if (length == 13) {
        EXPECT_THROW(classifyWallSides(cad), Error);
        continue;
      }
      const WallSides w = classifyWallSides(cad);
      EXPECT_NEAR(w.thickness / cad.unit / s, 5, 1e-6);
      for (int f = 0; f < cad.faces.Extent(); ++f)
        if (w.faces[f].side != Side::Lateral)
          EXPECT_NEAR(std::abs(faceCentre(cad, f).x() / cad.unit / s - 2.5), 2.5, 1e-6);
    }
  }
}

// A boss merged into a box's wall, cut off along the wall (test_junction_cut's BossesMergedIntoABoxsWallAndCorner): a
// ring R4.5 round a bore R1.5, 12 high, flattened by the plane 3.5 from its axis (its flat 5.66 wide, 2 from the bore),
// the flat and the foot under it cuts through the part. Only about a third of the flat's rays cross the ring (those
// off the bore run along it to its far side); a cut face that continues a wall face across their edge (lapFeet) is
// that wall's side: the flat is on the outer cylinder's side, the bore on the other. Not cut, the flat is a rim face.
// At scales 1, 1e-3, 1e3.
TEST(WallSides, ABosssFlatCutOffAWallIsItsOuterSide) {
  for (const double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const gp_Ax2 axis(gp_Pnt(0, 3.5 * s, 0), gp::DZ());
    const TopoDS_Shape ring = BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(axis, 4.5 * s, 12 * s).Shape(),
                                              BRepPrimAPI_MakeCylinder(axis, 1.5 * s, 12 * s).Shape())
                                  .Shape();
    const TopoDS_Shape flat =
        BRepAlgoAPI_Common(ring, BRepPrimAPI_MakeBox(gp_Pnt(-10 * s, 0, 0), 20 * s, 20 * s, 12 * s).Shape()).Shape();
    TopExp_Explorer solid(flat, TopAbs_SOLID);
    ASSERT_TRUE(solid.More());
    CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()), normalizingUnit(TopoDS::Solid(solid.Current())));
    int onWall = -1, foot = -1, outer = -1, bore = -1;
    for (int f = 0; f < cad.faces.Extent(); ++f) {
      const Vec3 c = faceCentre(cad, f) / cad.unit / s;
      if (surfaceOf(cad, f).GetType() == GeomAbs_Plane && std::abs(c.y()) < 1e-9) onWall = f;
      if (surfaceOf(cad, f).GetType() == GeomAbs_Plane && std::abs(c.z()) < 1e-9) foot = f;
      if (surfaceOf(cad, f).GetType() == GeomAbs_Cylinder)
        (surfaceOf(cad, f).Cylinder().Radius() / cad.unit / s > 3 ? outer : bore) = f;
    }
    ASSERT_TRUE(onWall >= 0 && foot >= 0 && outer >= 0 && bore >= 0);
    cad.cutInput.assign(cad.faces.Extent(), 0);
    cad.cutInput[foot] = 1;
    EXPECT_EQ(classifyWallSides(cad).faces[onWall].side, Side::Lateral);
    cad.cutInput[onWall] = 1;
    const WallSides w = classifyWallSides(cad);
    EXPECT_LT(w.faces[onWall].wallShare, 0.5);
    EXPECT_EQ(w.faces[onWall].side, w.faces[outer].side);
    EXPECT_NE(w.faces[bore].side, w.faces[outer].side);
    EXPECT_NE(w.faces[outer].side, Side::Lateral);
    EXPECT_EQ(w.faces[foot].side, Side::Lateral);
  }
}

// An open hem (Resources/samples/gaps/hem_narrow: a 1 mm sheet folded back round R0.3, the air between the legs 0.6
// wide): the sheet's inner face, the leg's and the fold's inside face the solid across the air, 0.6 walls away; the
// outer faces face nothing within 1.5 walls. The same in metres.
TEST(WallSides, AWallFacingTheSolidAcrossANarrowGapMeasuresTheGap) {
  for (const char* part : {"hem_narrow", "hem_metres"}) {
    SCOPED_TRACE(part);
    const CadSolid cad = readSample(std::string("Resources/samples/gaps/") + part + ".step");
    const WallSides w = classifyWallSides(cad);
    const double gap = std::string(part) == "hem_narrow" ? 0.6 : 1.0;  // hem_metres is hem_open: the air 1.0 wide
    int facing = 0, outer = 0;
    for (int f = 0; f < cad.faces.Extent(); ++f) {
      const FaceSide& fs = w.faces[f];
      if (fs.side == Side::Lateral) continue;
      // in walls: the sheet z 0...1, the leg 1 + gap ... 2 + gap, the fold round x 100, z 1 + gap / 2
      const Vec3 c = faceCentre(cad, f) / w.thickness;
      const bool fold = c.x() > 100;  // the fold's inside: its centroid 2 x its radius / pi from the axis
      const bool inside =
          fold ? std::hypot(c.x() - 100, c.z() - 1 - 0.5 * gap) < 0.5 : c.z() > 0.5 && c.z() < 1.5 + gap;
      if (inside) {
        EXPECT_NEAR(fs.airGap / w.thickness, gap, 0.02) << "Face" << f + 1 << " at " << c.transpose();
        ++facing;
      } else {
        EXPECT_EQ(fs.airGap, 0.0) << "Face" << f + 1 << " at " << c.transpose();
        ++outer;
      }
    }
    EXPECT_EQ(facing, 3);
    EXPECT_EQ(outer, 3);
  }
}
