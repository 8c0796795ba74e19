// Parts built in code for the unit tests (header-only, no test of its own): CAD solids that several test files
// mesh or classify, so that each is written once.
#pragma once
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_ShapeDivideArea.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"

namespace hexlayer::test_parts {

// [in] dx, dy, dz. The box [0, dx] x [0, dy] x [0, dz], prepared as the pipeline prepares a solid (unit 1).
inline CadSolid box(double dx, double dy, double dz) {
  return prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), dx, dy, dz).Solid());
}

// [in] s: the scale; [in] columns, rows: of the holes. A 5 (columns + 1) x 5 (rows + 1) x 2 plate with a grid of Ø2
// through holes at 5 pitch (by default 60 x 40 with 11 x 7 = 77 holes: its top and bottom faces have 78 wires), all
// lengths times s, prepared as the pipeline prepares a solid.
inline CadSolid plateWithManyHoles(double s, int columns = 11, int rows = 7) {
  TopoDS_Compound holes;
  BRep_Builder builder;
  builder.MakeCompound(holes);
  for (int i = 1; i <= columns; ++i)
    for (int j = 1; j <= rows; ++j)
      builder.Add(
          holes, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5 * i * s, 5 * j * s, -s), gp_Dir(0, 0, 1)), s, 4 * s).Shape());
  const TopoDS_Shape plate = BRepAlgoAPI_Cut(
      BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 5 * (columns + 1) * s, 5 * (rows + 1) * s, 2 * s).Shape(), holes);
  TopExp_Explorer solid(plate, TopAbs_SOLID);
  return prepareSolid(TopoDS::Solid(solid.Current()));
}

// [in] s: the scale. A tube R12 outside, R10 inside, 30 long along z, with 6 x 3 radial Ø3 holes (6 around from 0.3
// rad, 1 rad apart, at z = 6, 15, 24), all lengths times s: its faces cylinders and planes.
inline TopoDS_Solid perforatedTube(double s) {
  TopoDS_Shape tube = BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(12 * s, 30 * s).Shape(),
                                      BRepPrimAPI_MakeCylinder(10 * s, 30 * s).Shape())
                          .Shape();
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) {
      const double a = 0.3 + i * 1.0;
      const gp_Ax2 axis(gp_Pnt(0, 0, (6 + 9 * k) * s), gp_Dir(std::cos(a), std::sin(a), 0));
      tube = BRepAlgoAPI_Cut(tube, BRepPrimAPI_MakeCylinder(axis, 1.5 * s, 40 * s).Shape()).Shape();
    }
  TopExp_Explorer solid(tube, TopAbs_SOLID);
  return TopoDS::Solid(solid.Current());
}

// [in] s: the scale. The first solid of a shape (a boolean's result).
inline TopoDS_Solid firstSolid(const TopoDS_Shape& shape) {
  TopExp_Explorer solid(shape, TopAbs_SOLID);
  return TopoDS::Solid(solid.Current());
}

// [in] s: the scale. A 60 x 40 x 2 plate with a Ø2 hole through it at (30, 20), its top and bottom faces split by
// circles R2 and R4 round the hole (fused from a plate with a Ø8 hole and two rings, the faces not unified: as a
// CAD system leaves faces split): a ring 1 wide (half the wall) round the hole on each side, all lengths times s.
inline TopoDS_Solid plateSplitRoundAHole(double s) {
  auto cylinder = [&](double r) {
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30 * s, 20 * s, 0), gp_Dir(0, 0, 1)), r * s, 2 * s).Shape();
  };
  const TopoDS_Shape plate =
      BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60 * s, 40 * s, 2 * s).Shape(), cylinder(4));
  const TopoDS_Shape outer = BRepAlgoAPI_Cut(cylinder(4), cylinder(2)),
                     inner = BRepAlgoAPI_Cut(cylinder(2), cylinder(1));
  return firstSolid(BRepAlgoAPI_Fuse(BRepAlgoAPI_Fuse(plate, outer).Shape(), inner).Shape());
}

// [in] s: the scale. A 60 x 40 x 2 plate with a hollow boss at (30, 20): R5 outside, 10 high above the plate, a
// bore R3 down to the plate's top, and a hole R2 through the plate under it (the plate's top round the hole a ring 1
// wide, half the wall), all lengths times s.
inline TopoDS_Solid bossOverAHole(double s) {
  auto cylinder = [&](double r, double z0, double h) {
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30 * s, 20 * s, z0 * s), gp_Dir(0, 0, 1)), r * s, h * s).Shape();
  };
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60 * s, 40 * s, 2 * s).Shape();
  const TopoDS_Shape boss = BRepAlgoAPI_Cut(cylinder(5, 1, 11), cylinder(3, 2, 12));
  return firstSolid(BRepAlgoAPI_Cut(BRepAlgoAPI_Fuse(plate, boss).Shape(), cylinder(2, -1, 4)).Shape());
}

// [in] s: the scale. A 60 x 40 x 2 plate with a hollow boss at (30, 20): R4 outside, 10 high above the plate, a
// blind bore R2 from the top whose bottom is `bottom` above the plate's top (a cup; 0: down to the plate), all lengths
// times s.
inline TopoDS_Solid cuppedBoss(double bottom, double s) {
  auto cylinder = [&](double r, double z0, double h) {
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30 * s, 20 * s, z0 * s), gp_Dir(0, 0, 1)), r * s, h * s).Shape();
  };
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60 * s, 40 * s, 2 * s).Shape();
  return firstSolid(BRepAlgoAPI_Cut(BRepAlgoAPI_Fuse(plate, cylinder(4, 1, 11)).Shape(), cylinder(2, 2 + bottom, 11)));
}

// The solid with its faces listed in the reverse order, as another CAD system may write the same part: [in] solid.
inline TopoDS_Solid withFacesReversed(const TopoDS_Solid& solid) {
  std::vector<TopoDS_Shape> faces;
  for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next()) faces.push_back(it.Current());
  BRep_Builder build;
  TopoDS_Shell shell;
  build.MakeShell(shell);
  for (auto f = faces.rbegin(); f != faces.rend(); ++f) build.Add(shell, *f);
  TopoDS_Solid reversed;
  build.MakeSolid(reversed);
  build.Add(reversed, shell);
  return reversed;
}

// The solid with its faces divided so that none is larger than 1/pieces of its surface (ShapeUpgrade_ShapeDivideArea),
// as a CAD system may write a plate in pieces: [in] solid; [in] pieces.
inline TopoDS_Solid inPieces(const TopoDS_Solid& solid, double pieces) {
  GProp_GProps surface;
  BRepGProp::SurfaceProperties(solid, surface);
  ShapeUpgrade_ShapeDivideArea divide(solid);
  divide.MaxArea() = surface.Mass() / pieces;
  divide.Perform();
  return firstSolid(divide.Result());
}

// [in] s: the scale. An open box 40 x 45 x 12, walls and floor 2.5, the outer half of its walls cut away over the top
// 3.9 (a lid's lip 1.25 thick): the walls' outer faces 8.1 high, the wall 2.2 thicknesses above the floor under the
// ledge; all lengths times s.
inline TopoDS_Solid shortWalledLippedBox(double s) {
  auto block = [&](double x, double y, double z, double dx, double dy, double dz) {
    return BRepPrimAPI_MakeBox(gp_Pnt(x * s, y * s, z * s), dx * s, dy * s, dz * s).Shape();
  };
  const TopoDS_Shape open = BRepAlgoAPI_Cut(block(0, 0, 0, 40, 45, 12), block(2.5, 2.5, 2.5, 35, 40, 10));
  const TopoDS_Shape ring = BRepAlgoAPI_Cut(block(-1, -1, 8.1, 42, 47, 5), block(1.25, 1.25, 7, 37.5, 42.5, 7));
  return firstSolid(BRepAlgoAPI_Cut(open, ring).Shape());
}

// [in] s: the scale; [in] pieces: faces of the pin's round; [in] tip: the pin's radius at its top. A 40 x 40 x 2 plate
// with a solid pin at (20, 20) standing on it, R2 at its foot, `tip` at its top 10 above the plate (a cone if tip < 2),
// fused from `pieces` wedges of it without unifying faces (as CAD systems write a round in halves or quarters), all
// lengths times s.
inline TopoDS_Solid plateWithSplitPin(double s, int pieces, double tip = 2) {
  TopoDS_Shape part = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40 * s, 40 * s, 2 * s).Shape();
  const double angle = 2 * M_PI / pieces;
  for (int k = 0; k < pieces; ++k) {  // the pin reaches 1 into the plate: 11 long from z = 1
    const gp_Ax2 axis(gp_Pnt(20 * s, 20 * s, s), gp_Dir(0, 0, 1), gp_Dir(std::cos(k * angle), std::sin(k * angle), 0));
    const TopoDS_Shape wedge =
        tip < 2 ? BRepPrimAPI_MakeCone(axis, (2 + (2 - tip) / 10) * s, tip * s, 11 * s, angle).Shape()
                : BRepPrimAPI_MakeCylinder(axis, 2 * s, 11 * s, angle).Shape();
    part = BRepAlgoAPI_Fuse(part, wedge).Shape();
  }
  return firstSolid(part);
}

// [in] s: the scale. Points of plateWithManyHoles(s) on and near its edges and vertices: on the holes' rims, the
// plate's edges and a corner, and 1e-12 .. 0.3 (times s) off them in and out.
inline std::vector<Vec3> pointsNearEdges(double s) {
  std::vector<Vec3> points;
  for (double off : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-7, -1e-7, 1e-5, -1e-5, 1e-3, -1e-3, 0.3, -0.3}) {
    for (int k = 0; k < 8; ++k) {  // round the rim of the hole at (25, 15), and at (5, 5) by the plate's corner
      const double a = 0.61 + k * M_PI / 4;
      points.push_back(Vec3(25 + (1 + off) * std::cos(a), 15 + (1 + off) * std::sin(a), 2) * s);
      points.push_back(Vec3(5 + (1 + off) * std::cos(a), 5 + (1 + off) * std::sin(a), 0) * s);
    }
    points.push_back(Vec3(off, off, 2) * s);          // the corner
    points.push_back(Vec3(60 - off, 17.3, 0) * s);    // an edge
    points.push_back(Vec3(31.7, 40 + off, 2) * s);    // an edge
    points.push_back(Vec3(25 + 1 + off, 15, 2) * s);  // a circle's seam
  }
  return points;
}

}  // namespace hexlayer::test_parts
