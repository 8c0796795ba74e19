// Sheets and junctions (geometry/sheet_junctions): a boss or a rib standing on a plate is a sheet of
// its own, found from the CAD faces; a sharp L bend is not, nor a bend with a sharp inside edge and a small
// outside round (bend_rounds.hpp).
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "geometry/cad_solid.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_sides.hpp"

using namespace hexlayer;

namespace {

// The fused solid with its coplanar face pieces merged, as a CAD system exports it.
CadSolid solidOf(const TopoDS_Shape& fused) {
  ShapeUpgrade_UnifySameDomain unify(fused, true, true, false);
  unify.Build();
  TopExp_Explorer it(unify.Shape(), TopAbs_SOLID);
  EXPECT_TRUE(it.More());
  return prepareSolid(TopoDS::Solid(it.Current()));
}

TopoDS_Shape plate() { return BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60, 40, 2).Shape(); }

}  // namespace

TEST(SheetJunctions, PlateIsOneSheet) {
  const CadSolid cad = solidOf(plate());
  const std::vector<Sheet> sheets = findSheets(cad, classifyWallSides(cad));
  ASSERT_EQ(sheets.size(), 1u);
  EXPECT_EQ(sheets[0].faces.size(), 2u);
  EXPECT_NEAR(sheets[0].area, 2 * 60 * 40, 1e-6 * 4800);
}

// Two boxes meeting in a sharp L (no bend radius): the inner edge is concave, the outer convex.
TEST(SheetJunctions, SharpLBendIsOneSheet) {
  const TopoDS_Shape leg = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 2, 40, 30).Shape();
  const CadSolid cad = solidOf(BRepAlgoAPI_Fuse(plate(), leg).Shape());
  EXPECT_EQ(findSheets(cad, classifyWallSides(cad)).size(), 1u);
}

// A tube (outer radius 3, wall 1.5, 7 high) standing on the plate: a boss, the second sheet, centred
// on the tube; dropping it leaves the plate's two faces as the only walls.
TEST(SheetJunctions, BossOnAPlateIsASecondSheet) {
  const gp_Ax2 axis(gp_Pnt(20, 20, 2), gp_Dir(0, 0, 1));
  const TopoDS_Shape tube =
      BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(axis, 3, 7).Shape(), BRepPrimAPI_MakeCylinder(axis, 1.5, 7).Shape())
          .Shape();
  const CadSolid cad = solidOf(BRepAlgoAPI_Fuse(plate(), tube).Shape());
  WallSides sides = classifyWallSides(cad);
  const std::vector<Sheet> sheets = findSheets(cad, sides);
  ASSERT_EQ(sheets.size(), 2u);
  EXPECT_GT(sheets[0].area, 4000);
  EXPECT_NEAR(sheets[1].area, 2 * M_PI * (3 + 1.5) * 7, 0.5) << "the tube's outer and inner walls";
  EXPECT_NEAR(sheets[1].centre.x(), 20, 0.1);
  EXPECT_NEAR(sheets[1].centre.y(), 20, 0.1);
  EXPECT_NEAR(sheets[1].centre.z(), 5.5, 0.1);
  keepFirstSheet(sheets, sides);
  int walls = 0;
  for (const FaceSide& f : sides.faces) walls += f.side != Side::Lateral;
  EXPECT_EQ(walls, static_cast<int>(sheets[0].faces.size()));
}

// A hollow boss (R3.5, bore R1.5, 13 high) standing on a plate against a wall (60 x 2 x 15), its side merged 0.3 into
// the wall: the boss's side meets the wall's face in an air wedge of 24 degrees along two lines, edges
// BRepOffset_Analyse takes for convex (folded joins: the faces' normals 156 degrees apart). They tie no sides and join
// no sheets: the boss stands on the wall and the plate (it was one sheet with them, its hexes folded). Also scaled by
// 1e-3 and 1e3.
TEST(SheetJunctions, ABossMergedShallowlyIntoAWallStandsOnIt) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const gp_Ax2 axis(gp_Pnt(30, 5.2, 2), gp_Dir(0, 0, 1));
    TopoDS_Shape part = BRepAlgoAPI_Fuse(plate(), BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60, 2, 15).Shape()).Shape();
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeCylinder(axis, 3.5, 13).Shape()).Shape();
    part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(axis, 1.5, 13).Shape()).Shape();
    gp_Trsf scaling;
    scaling.SetScale(gp_Pnt(0, 0, 0), scale);
    const CadSolid cad = solidOf(BRepBuilderAPI_Transform(part, scaling, true).Shape());
    const WallSides sides = classifyWallSides(cad);
    int folded = 0;
    for (const SheetJoin& j : sides.sheetJoins) folded += j.folded;
    EXPECT_EQ(folded, 2);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 2u);
    EXPECT_NEAR(sheets[1].centre.x() / scale, 30, 0.1);
    EXPECT_NEAR(sheets[1].centre.z() / scale, 8.5, 0.2);
    EXPECT_TRUE(sides.knifeEdges.empty());
  }
}

// A rib across the plate: two walls meeting the plate at concave edges only.
TEST(SheetJunctions, RibOnAPlateIsASecondSheet) {
  const TopoDS_Shape rib = BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 2), 2, 40, 12).Shape();
  const CadSolid cad = solidOf(BRepAlgoAPI_Fuse(plate(), rib).Shape());
  const std::vector<Sheet> sheets = findSheets(cad, classifyWallSides(cad));
  ASSERT_EQ(sheets.size(), 2u);
  EXPECT_NEAR(sheets[1].area, 2 * 40 * 12, 1.0);
}

namespace {

// The shape with the edges whose bounding box's z range (z0, z1) `which` takes rounded r (BRepFilletAPI_MakeFillet)
// or chamfered r x r (BRepFilletAPI_MakeChamfer).
template <class Maker, class Which>
TopoDS_Shape cutEdges(const TopoDS_Shape& shape, double r, Which which) {
  Maker maker(shape);
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
    Bnd_Box b;
    BRepBndLib::Add(e.Current(), b);
    double x0, y0, z0, x1, y1, z1;
    b.Get(x0, y0, z0, x1, y1, z1);
    if (which(z0, z1)) maker.Add(r, TopoDS::Edge(e.Current()));
  }
  return maker.Shape();
}

template <class Which>
TopoDS_Shape rounded(const TopoDS_Shape& shape, double r, Which which) {
  return cutEdges<BRepFilletAPI_MakeFillet>(shape, r, which);
}

// The open box 60 x 40 x 20 (wall 2, open at z = 20) with sharp inside edges and corners, its vertical and bottom
// outside edges rounded r (0: sharp), or chamfered r x r if `chamfer`, scaled by `scale`.
CadSolid sharpInsideBox(double r, double scale = 1, bool chamfer = false) {
  TopoDS_Shape outer = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60, 40, 20).Shape();
  auto verticalOrBottom = [](double z0, double z1) { return z1 - z0 > 1 || z1 < 1; };
  if (r > 0 && chamfer) outer = cutEdges<BRepFilletAPI_MakeChamfer>(outer, r, verticalOrBottom);
  if (r > 0 && !chamfer) outer = rounded(outer, r, verticalOrBottom);
  const TopoDS_Shape inner = BRepPrimAPI_MakeBox(gp_Pnt(2, 2, 2), 56, 36, 20).Shape();
  gp_Trsf scaling;
  scaling.SetScale(gp_Pnt(0, 0, 0), scale);
  return solidOf(BRepBuilderAPI_Transform(BRepAlgoAPI_Cut(outer, inner).Shape(), scaling, true).Shape());
}

int walls(const WallSides& sides) {
  int n = 0;
  for (const FaceSide& f : sides.faces) n += f.side != Side::Lateral;
  return n;
}

}  // namespace

// Walls meeting the floor and each other in sharp inside edges, their outsides joined by rounds smaller than the
// wall (R1 and R0.5 on a wall of 2, in mm and in metres): one bent sheet. The rounds' rays run to the inside edges
// and cross no wall, yet they are walls: 4 vertical and 4 bottom quarter cylinders and the 4 bottom corners'
// eighth spheres (bend_rounds.hpp); only the flat rim at the top is lateral.
TEST(SheetJunctions, OpenBoxWithSharpInsideEdgesAndSmallOutsideRoundsIsOneSheet) {
  for (const auto& [r, scale] : {std::pair{1.0, 1.0}, {0.5, 1.0}, {1.0, 1e-3}}) {
    SCOPED_TRACE("round " + std::to_string(r) + ", scale " + std::to_string(scale));
    const CadSolid cad = sharpInsideBox(r, scale);
    ASSERT_EQ(cad.faces.Extent(), 23);
    const WallSides sides = classifyWallSides(cad);
    EXPECT_EQ(sides.bendRounds.size(), 12u);
    EXPECT_TRUE(sides.ownSideFaces.empty());
    EXPECT_EQ(walls(sides), 22);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 1u);
    EXPECT_EQ(sheets[0].faces.size(), 22u);
  }
}

// The outside edges chamfered (1.5 and 2 x 2 on a wall of 2, in mm and in metres): each chamfer meets two walls in
// convex sharp edges and its rays land on the bend's inside edge, so the 4 vertical and 4 bottom chamfers are walls
// (bend_rounds.hpp) and the box one sheet; the triangles where three chamfers meet at a bottom corner, narrower than a
// quarter of the wall, stay lateral, as the flat rim at the top does.
TEST(SheetJunctions, OpenBoxWithSharpInsideEdgesAndChamferedOutsideIsOneSheet) {
  for (const auto& [c, scale] : {std::pair{1.5, 1.0}, {2.0, 1.0}, {1.5, 1e-3}}) {
    SCOPED_TRACE("chamfer " + std::to_string(c) + ", scale " + std::to_string(scale));
    const CadSolid cad = sharpInsideBox(c, scale, true);
    ASSERT_EQ(cad.faces.Extent(), 23);
    const WallSides sides = classifyWallSides(cad);
    EXPECT_EQ(sides.bendRounds.size(), 8u);
    EXPECT_EQ(walls(sides), 18);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 1u);
    EXPECT_EQ(sheets[0].faces.size(), 18u);
  }
}

// Every edge sharp: the outsides meet in convex edges, one sheet without bend rounds.
TEST(SheetJunctions, OpenBoxWithSharpEdgesIsOneSheet) {
  const CadSolid cad = sharpInsideBox(0);
  const WallSides sides = classifyWallSides(cad);
  EXPECT_TRUE(sides.bendRounds.empty());
  EXPECT_EQ(walls(sides), 10);
  EXPECT_EQ(findSheets(cad, sides).size(), 1u);
}

// A rim's rounds are no bend: a plate whose top rim edges are rounded R0.5 (each round joins one wall to a rim
// face), and a strip whose end is rounded across the wall (a half cylinder joining the top to its own bottom).
TEST(SheetJunctions, RoundedRimsAreNoBends) {
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60, 40, 2).Shape();
  const CadSolid roundedPlate = solidOf(rounded(plate, 0.5, [](double z0, double) { return z0 > 1; }));  // the top's
  const WallSides sides = classifyWallSides(roundedPlate);
  EXPECT_TRUE(sides.bendRounds.empty());
  EXPECT_EQ(walls(sides), 2);
  const TopoDS_Shape strip =
      BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60, 20, 2).Shape(),
                       BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(60, 0, 1), gp_Dir(0, 1, 0)), 1, 20))
          .Shape();
  const CadSolid end = solidOf(strip);
  const WallSides endSides = classifyWallSides(end);
  EXPECT_TRUE(endSides.bendRounds.empty());
  EXPECT_EQ(findSheets(end, endSides).size(), 1u);
}

namespace {

// The plate with boxes fused on (lo corner, size), its coplanar faces merged, scaled by s.
CadSolid plateWith(const std::vector<std::pair<gp_Pnt, gp_Pnt>>& boxes, double s) {
  TopoDS_Shape part = plate();
  for (const auto& [lo, size] : boxes)
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(lo, size.X(), size.Y(), size.Z()).Shape()).Shape();
  gp_Trsf scaling;
  scaling.SetScale(gp_Pnt(0, 0, 0), s);
  return solidOf(BRepBuilderAPI_Transform(part, scaling, true).Shape());
}

}  // namespace

// Posts and blocks of plane sides stand on the plate though no ray of theirs crosses a wall (a 4 x 4 post 8 above
// the plate, a 12 x 5 x 4 block, a 10 x 10 pad 1 high): each a column, its volume above the plate's top; at scales
// 1e-3, 1, 1e3.
TEST(SheetJunctions, PostsOfPlaneSidesAreColumns) {
  for (const double s : {1e-3, 1.0, 1e3}) {
    const CadSolid cad = plateWith({{gp_Pnt(28, 18, 1), gp_Pnt(4, 4, 9)},
                                    {gp_Pnt(5, 5, 1), gp_Pnt(12, 5, 5)},
                                    {gp_Pnt(40, 25, 1), gp_Pnt(10, 10, 2)}},
                                   s);
    const WallSides sides = classifyWallSides(cad);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 4u) << s;
    EXPECT_FALSE(sheets[0].column);
    const double volumes[] = {12 * 5 * 4, 4 * 4 * 8, 10 * 10 * 1};  // by decreasing area: block, post, pad
    const double areas[] = {2 * (12 + 5) * 4 + 60, 4 * 4 * 8 + 16, 4 * 10 + 100};
    for (int k = 0; k < 3; ++k) {
      const Sheet& c = sheets[k + 1];
      EXPECT_TRUE(c.column) << s;
      EXPECT_EQ(c.faces.size(), 5u) << s;
      EXPECT_NEAR(c.area / (s * s), areas[k], 1e-6 * areas[k]) << s;
      EXPECT_NEAR(c.volume / (s * s * s), volumes[k], 1e-6 * volumes[k]) << s;
    }
    EXPECT_NEAR(sheets[2].centre.x() / s, 30, 1e-6) << "the post's";
  }
}

// No column where nothing stands: a thickness step (a pad whose top's rays cross to the plate's bottom: a wall), a
// hole and a pocket (their sides meet the top in convex edges), a small nub (all its faces narrower than half the
// wall, within two walls: a small feature).
TEST(SheetJunctions, StepsHolesPocketsAndNubsAreNoColumns) {
  TopoDS_Shape part = BRepAlgoAPI_Fuse(plate(), BRepPrimAPI_MakeBox(gp_Pnt(5, 5, 1), 20, 20, 2).Shape()).Shape();
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(45, 20, -1), gp_Dir(0, 0, 1)), 3, 4)).Shape();
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeBox(gp_Pnt(35, 5, 1), 6, 6, 2).Shape()).Shape();
  part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(50, 30, 1), 0.8, 0.8, 1.6).Shape()).Shape();
  const CadSolid cad = solidOf(part);
  const WallSides sides = classifyWallSides(cad);
  EXPECT_TRUE(standingColumns(cad, sides).empty());
  EXPECT_EQ(findSheets(cad, sides).size(), 1u);
}

// A screw boss whose blind bore ends in a 118-degree drill point: the point's cone is a dent under the bore's floor
// (the volume it closes with the plane of its rim is negative), no column of its own (one was found, standing on the
// bore's wall, and refused). A pin R3 on a wider pin R5 (a shoulder) is one column: the narrower part, a sheet that
// stands on the wider's top alone, joins it. At scales 1e-3, 1, 1e3.
TEST(SheetJunctions, ADrillPointIsNoColumnAPinOnAShoulderIsOne) {
  for (const double s : {1e-3, 1.0, 1e3}) {
    gp_Trsf scaling;
    scaling.SetScale(gp_Pnt(0, 0, 0), s);
    auto scaled = [&](const TopoDS_Shape& shape) { return BRepBuilderAPI_Transform(shape, scaling, true).Shape(); };
    const TopoDS_Shape bore = BRepAlgoAPI_Fuse(
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 5), gp_Dir(0, 0, 1)), 1.8, 30).Shape(),
        BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(30, 20, 5), gp_Dir(0, 0, -1)), 1.8, 0, 1.8 / std::tan(59 * M_PI / 180))
            .Shape());
    const TopoDS_Shape boss =
        BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 1), gp_Dir(0, 0, 1)), 4.5, 20).Shape(), bore);
    const CadSolid drilled = solidOf(scaled(BRepAlgoAPI_Fuse(plate(), boss).Shape()));
    const WallSides drilledSides = classifyWallSides(drilled);
    for (const Sheet& column : standingColumns(drilled, drilledSides))
      for (int f : column.faces)
        EXPECT_NE(BRepAdaptor_Surface(TopoDS::Face(drilled.faces(f + 1))).GetType(), GeomAbs_Cone) << s;
    const TopoDS_Shape pins =
        BRepAlgoAPI_Fuse(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 1), gp_Dir(0, 0, 1)), 5, 9).Shape(),
                         BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 9), gp_Dir(0, 0, 1)), 3, 11).Shape());
    const CadSolid shouldered = solidOf(scaled(BRepAlgoAPI_Fuse(plate(), pins).Shape()));
    const std::vector<Sheet> sheets = findSheets(shouldered, classifyWallSides(shouldered));
    ASSERT_EQ(sheets.size(), 2u) << s;
    EXPECT_TRUE(sheets[1].column);
    int cylinders = 0;
    for (int f : sheets[1].faces)
      cylinders += BRepAdaptor_Surface(TopoDS::Face(shouldered.faces(f + 1))).GetType() == GeomAbs_Cylinder;
    EXPECT_EQ(cylinders, 2) << s;
  }
}

namespace {

// A 60 x 40 plate `thick` thick for x <= 30 (z 0 ... thick), `thin` thick beyond (z z0 ... z0 + thin), scaled by s.
CadSolid steppedPlate(double thick, double z0, double thin, double s) {
  TopoDS_Shape part = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 30, 40, thick).Shape(),
                                       BRepPrimAPI_MakeBox(gp_Pnt(30, 0, z0), 30, 40, thin).Shape())
                          .Shape();
  gp_Trsf scaling;
  scaling.SetScale(gp_Pnt(0, 0, 0), s);
  return solidOf(BRepBuilderAPI_Transform(part, scaling, true).Shape());
}

}  // namespace

// A plate 3 thick going on 1.5 thick past a step in both faces (0.75 each, or 0.5 and 1.0) is one sheet: the thin
// wall's faces meet the thick wall's rim face in concave edges, which made them a sheet standing on a rim. A step
// higher than the thin wall (a plate 6 thick going on 1.5 thick) is no thickness step: two sheets, as before. At
// scales 1e-3, 1, 1e3.
TEST(SheetJunctions, AThinnerWallPastAStepInBothFacesIsTheSameSheet) {
  for (const double s : {1e-3, 1.0, 1e3})
    for (const double z0 : {0.75, 0.5}) {
      const CadSolid cad = steppedPlate(3, z0, 1.5, s);
      const WallSides sides = classifyWallSides(cad);
      EXPECT_EQ(thicknessSteps(cad, sides).size(), 2u) << s << " " << z0 << ": one per face";
      const std::vector<Sheet> sheets = findSheets(cad, sides);
      ASSERT_EQ(sheets.size(), 1u) << s << " " << z0;
      EXPECT_EQ(sheets[0].faces.size(), 4u) << "the thick and the thin top and bottom";
    }
  for (const double s : {1e-3, 1.0, 1e3}) {
    const CadSolid cad = steppedPlate(6, 2.25, 1.5, s);
    const WallSides sides = classifyWallSides(cad);
    EXPECT_TRUE(thicknessSteps(cad, sides).empty()) << s;
    EXPECT_EQ(findSheets(cad, sides).size(), 2u) << s;
  }
}

// A boss with gussets: a gusset's top meets the gusset's side in a convex edge and the boss's round side in a concave
// one, but they face different ways there (and are as thick): no step, the gussets stay sheets of their own.
TEST(SheetJunctions, AGussetOnABossIsNoThicknessStep) {
  const gp_Ax2 axis(gp_Pnt(30, 20, 1), gp_Dir(0, 0, 1));
  TopoDS_Shape part = BRepAlgoAPI_Fuse(plate(), BRepPrimAPI_MakeCylinder(axis, 4, 11).Shape()).Shape();
  part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(29, 22, 1), 2, 10, 7).Shape()).Shape();
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 2), gp_Dir(0, 0, 1)), 2, 12)).Shape();
  const CadSolid cad = solidOf(part);
  const WallSides sides = classifyWallSides(cad);
  EXPECT_TRUE(thicknessSteps(cad, sides).empty());
  EXPECT_EQ(findSheets(cad, sides).size(), 3u) << "the plate, the boss, the gusset";
}

// A tube (R2, bore R1) fused onto the plate through it, the plate not bored (as FreeCAD's fuse of a tube and a plate
// gives): the plate's disc inside the tube lies on the plate's two planes and joins the plate's sheet; the tube's
// halves above and below stand on it (three sheets). A rib's segments either side of a crossing rib lie on one pair of
// planes too, but join no sheet but the largest: they stay segments (mergeCrossingRibs decides). At scales 1e-3, 1,
// 1e3.
TEST(SheetJunctions, APlatesDiscInsideATubeFusedThroughItIsThePlates) {
  for (const double s : {1e-3, 1.0, 1e3}) {
    const gp_Ax2 axis(gp_Pnt(30, 20, -4), gp_Dir(0, 0, 1));
    const TopoDS_Shape tube =
        BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(axis, 2, 14).Shape(), BRepPrimAPI_MakeCylinder(axis, 1, 14).Shape())
            .Shape();
    gp_Trsf scaling;
    scaling.SetScale(gp_Pnt(0, 0, 0), s);
    const CadSolid cad =
        solidOf(BRepBuilderAPI_Transform(BRepAlgoAPI_Fuse(plate(), tube).Shape(), scaling, true).Shape());
    const WallSides sides = classifyWallSides(cad);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 3u) << s;
    EXPECT_EQ(sheets[0].faces.size(), 4u) << s << ": the plate's top and bottom, the disc's top and bottom";
    EXPECT_NEAR(sheets[0].area / (s * s), 2 * 60 * 40 - 2 * M_PI * (4 - 1), 1e-4 * 4800) << s;  // areas as sampled
  }
  const CadSolid grid = plateWith({{gp_Pnt(0, 12, 1), gp_Pnt(60, 2, 6)}, {gp_Pnt(29, 0, 1), gp_Pnt(2, 40, 6)}}, 1);
  EXPECT_EQ(findSheets(grid, classifyWallSides(grid)).size(), 5u) << "the plate and four rib segments";
}

// The sides of the steps the sweep takes: a plate 3 thick going on 1.5 thick past a step in one face (z0 1.5: the top
// flush) has one, the face x = 30, z 0...1.5; past steps in both faces two, x = 30 below and above the thin wall; a
// step higher than the thin wall none. At scales 1e-3, 1, 1e3.
TEST(SheetJunctions, AThicknessStepsSideIsNamed) {
  for (const double s : {1e-3, 1.0, 1e3})
    for (const auto& [z0, thick, count] : {std::tuple{1.5, 3.0, 1}, {0.75, 3.0, 2}, {2.25, 6.0, 0}}) {
      const CadSolid cad = steppedPlate(thick, z0, 1.5, s);
      const WallSides sides = classifyWallSides(cad);
      const std::vector<char> stepSides = thicknessStepSides(cad, sides);
      ASSERT_EQ(stepSides.size(), static_cast<std::size_t>(cad.faces.Extent()));
      int found = 0;
      for (int f = 0; f < cad.faces.Extent(); ++f) {
        if (!stepSides[f]) continue;
        ++found;
        EXPECT_EQ(sides.faces[f].side, Side::Lateral) << s << " " << z0 << ": Face" << f + 1;
        Bnd_Box box;
        BRepBndLib::Add(cad.faces(f + 1), box);
        double x0, y0, z0b, x1, y1, z1;
        box.Get(x0, y0, z0b, x1, y1, z1);
        EXPECT_NEAR(0.5 * (x0 + x1), 30 * s * cad.unit, 1e-6 * s * cad.unit) << s << " " << z0 << ": Face" << f + 1;
      }
      EXPECT_EQ(found, count) << s << " " << z0;
    }
}

// An open tray 80 x 60 x 20 (walls and floor 1.5) with a flange 10 wide all round its top, its walls' inner faces split
// at z 17 (cut again by a box there, as CAD systems split faces): the strips above, under the bend's corner, have half
// their rays running into the flange. They are pieces of the walls: one sheet, no wall standing on the flange. At
// scales 1e-3, 1, 1e3.
TEST(SheetJunctions, AWallSplitJustUnderItsBendIsWallInEveryPiece) {
  for (const double s : {1e-3, 1.0, 1e3}) {
    TopoDS_Shape tray = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 80, 60, 20).Shape(),
                                         BRepPrimAPI_MakeBox(gp_Pnt(-10, -10, 18.5), 100, 80, 1.5).Shape())
                            .Shape();
    tray = BRepAlgoAPI_Cut(tray, BRepPrimAPI_MakeBox(gp_Pnt(1.5, 1.5, 1.5), 77, 57, 25).Shape()).Shape();
    ShapeUpgrade_UnifySameDomain unify(tray, true, true, false);  // the flange's top one face, as CAD exports it
    unify.Build();
    tray = BRepAlgoAPI_Cut(unify.Shape(), BRepPrimAPI_MakeBox(gp_Pnt(1.5, 1.5, 17), 77, 57, 5).Shape()).Shape();
    gp_Trsf scaling;
    scaling.SetScale(gp_Pnt(0, 0, 0), s);
    TopExp_Explorer solid(BRepBuilderAPI_Transform(tray, scaling, true).Shape(), TopAbs_SOLID);
    ASSERT_TRUE(solid.More());
    const CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()));
    const WallSides sides = classifyWallSides(cad);
    int strips = 0;
    for (int f = 0; f < cad.faces.Extent(); ++f) {
      Bnd_Box box;
      BRepBndLib::Add(cad.faces(f + 1), box);
      double x0, y0, z0, x1, y1, z1;
      box.Get(x0, y0, z0, x1, y1, z1);
      const double unit = s * cad.unit;
      if (z0 < 16.9 * unit || z1 > 20.1 * unit || z1 - z0 < 2.9 * unit) continue;  // the strips: z 17...20
      ++strips;
      EXPECT_NE(sides.faces[f].side, Side::Lateral) << s << ": Face" << f + 1 << ", share " << sides.faces[f].wallShare;
    }
    EXPECT_EQ(strips, 4) << s;
    EXPECT_EQ(findSheets(cad, sides).size(), 1u) << s;
  }
}
