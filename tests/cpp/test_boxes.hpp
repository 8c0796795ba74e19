// Test parts made of boxes (header-only, no test of its own): a plate with ribs standing on it, as a CAD system
// models it, shared by test_junction_cut.cpp and test_junction_mesh.cpp.
#pragma once
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Trsf.hxx>

#include <vector>

namespace hexlayer::test_boxes {

struct Box {
  double x0, y0, z0, dx, dy, dz;
  double volume() const { return dx * dy * dz; }
};

// The solid scaled by s about the origin.
inline TopoDS_Solid scaled(const TopoDS_Shape& solid, double s) {
  gp_Trsf scale;
  scale.SetScale(gp_Pnt(0, 0, 0), s);
  TopExp_Explorer it(BRepBuilderAPI_Transform(solid, scale, true).Shape(), TopAbs_SOLID);
  return TopoDS::Solid(it.Current());
}

// The union of boxes (faces unified, as a CAD system models a plate with ribs), scaled by s.
inline TopoDS_Solid boxes(const std::vector<Box>& parts, double s) {
  TopoDS_Shape all =
      BRepPrimAPI_MakeBox(gp_Pnt(parts[0].x0, parts[0].y0, parts[0].z0), parts[0].dx, parts[0].dy, parts[0].dz).Shape();
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const Box& b = parts[i];
    all = BRepAlgoAPI_Fuse(all, BRepPrimAPI_MakeBox(gp_Pnt(b.x0, b.y0, b.z0), b.dx, b.dy, b.dz).Shape()).Shape();
  }
  ShapeUpgrade_UnifySameDomain unify(all);
  unify.Build();
  return scaled(unify.Shape(), s);
}

// An open box 100 x 60 x 40 along x, walls 2 thick (a floor, two side walls), closed at x = 0 by an end wall
// `thickness` thick and `height` high between the side walls, on the floor: its outside, the side walls' ends and the
// floor's are one face (unified).
inline std::vector<Box> boxWithEndWall(double height, double thickness = 2) {
  return {{0, 0, 0, 100, 60, 2}, {0, 0, 0, 100, 2, 40}, {0, 58, 0, 100, 2, 40}, {0, 2, 2, thickness, 56, height - 2}};
}

// An L-bracket: a plate 80 x 60 x 2 and a flange 2 thick, 40 high and 30 wide at its end x = 0, its outside flush with
// the plate's end face.
inline std::vector<Box> narrowFlangeBracket() { return {{0, 0, 0, 80, 60, 2}, {0, 15, 0, 2, 30, 40}}; }

// The solid with a triangular gusset fused into it: the triangle corner, corner + legA, corner + legB, extruded by
// `thickness` (a vector); scaled by s.
inline TopoDS_Solid withGusset(const TopoDS_Solid& solid, const gp_Pnt& corner, const gp_Vec& legA, const gp_Vec& legB,
                               const gp_Vec& thickness, double s) {
  const TopoDS_Wire triangle =
      BRepBuilderAPI_MakePolygon(corner, corner.Translated(legA), corner.Translated(legB), true).Wire();
  const TopoDS_Shape gusset = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(triangle).Face(), thickness);
  return scaled(BRepAlgoAPI_Fuse(solid, gusset).Shape(), s);
}

}  // namespace hexlayer::test_boxes
