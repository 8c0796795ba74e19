// Sheets and junctions (geometry/sheet_junctions): a boss or a rib standing on a plate is a sheet of
// its own, found from the CAD faces; a sharp L bend is not.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

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

// A rib across the plate: two walls meeting the plate at concave edges only.
TEST(SheetJunctions, RibOnAPlateIsASecondSheet) {
  const TopoDS_Shape rib = BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 2), 2, 40, 12).Shape();
  const CadSolid cad = solidOf(BRepAlgoAPI_Fuse(plate(), rib).Shape());
  const std::vector<Sheet> sheets = findSheets(cad, classifyWallSides(cad));
  ASSERT_EQ(sheets.size(), 2u);
  EXPECT_NEAR(sheets[1].area, 2 * 40 * 12, 1.0);
}
