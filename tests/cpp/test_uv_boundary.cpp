// Inside / outside of a trimmed face in its parameter plane (geometry/uv_boundary.hpp): the top of a plate with
// a hole, decided away from the face's edges, undecided next to them; the clearance from its edges.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <ElSLib.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <tuple>

#include "geometry/uv_boundary.hpp"

using namespace hexlayer;

TEST(UvBoundary, PlateWithAHoleDecidesAwayFromItsEdges) {
  const TopoDS_Shape plate =
      BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(40, 30, 2).Shape(),
                      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 15, -1), gp_Dir(0, 0, 1)), 5, 4).Shape())
          .Shape();
  for (TopExp_Explorer e(plate, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face face = TopoDS::Face(e.Current());
    BRepAdaptor_Surface s(face);
    if (s.GetType() != GeomAbs_Plane || std::abs(s.Plane().Location().Z() - 2) > 1e-9) continue;
    const UvBoundary boundary(face, 1e-3, 1e-3);
    const gp_Pln plane = s.Plane();
    auto side = [&](double x, double y) {  // of the point (x, y, 2)
      double u = 0, v = 0;
      ElSLib::Parameters(plane, gp_Pnt(x, y, 2), u, v);
      return boundary.side(u, v);
    };
    EXPECT_EQ(side(5, 5), UvBoundary::Side::Inside);
    EXPECT_EQ(side(20, 15), UvBoundary::Side::Outside) << "the hole";
    EXPECT_EQ(side(50, 15), UvBoundary::Side::Outside);
    EXPECT_EQ(side(25 + 2e-4, 15), UvBoundary::Side::Undecided) << "by the hole's edge";
    EXPECT_EQ(side(5, 1e-4), UvBoundary::Side::Undecided) << "by the rim";
    EXPECT_EQ(side(25.01, 15), UvBoundary::Side::Inside);
    // The clearance (in margins of 1e-3) is a lower bound on the distance to the nearest edge, short of it by at
    // most the polylines' sag (a quarter margin): 3 to the rim at y = 0, 1 to the hole, 0 on an edge.
    auto clearance = [&](double x, double y) {
      double u = 0, v = 0;
      ElSLib::Parameters(plane, gp_Pnt(x, y, 2), u, v);
      return boundary.clearance(u, v);
    };
    for (const auto& [x, y, d] :
         {std::tuple{6.0, 3e-3, 3.0}, {25.001, 15.0, 1.0}, {5.0, 0.0, 0.0}, {12.0, 15.0, 3e3}}) {
      EXPECT_LE(clearance(x, y), d) << x << " " << y;
      EXPECT_GE(clearance(x, y), d - 0.25) << x << " " << y;
    }
    EXPECT_EQ(boundary.margin(), 1e-3);
    return;
  }
  FAIL() << "no top face";
}
