// Inside / outside of a trimmed face in its parameter plane (geometry/uv_boundary.hpp): the top of a plate with
// a hole, decided away from the face's edges, undecided next to them; the clearance from its edges; points on its
// straight and circular edges.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <ElSLib.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <tuple>
#include <utility>

#include "geometry/uv_boundary.hpp"

using namespace hexlayer;

namespace {

// The top face (z = 2) of a 40 x 30 x 2 plate with a cylinder of radius 5 about (x, y) cut out, and its plane.
std::pair<TopoDS_Face, gp_Pln> plateTop(double x, double y) {
  const TopoDS_Shape plate =
      BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(40, 30, 2).Shape(),
                      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp_Dir(0, 0, 1)), 5, 4).Shape())
          .Shape();
  for (TopExp_Explorer e(plate, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face face = TopoDS::Face(e.Current());
    BRepAdaptor_Surface s(face);
    if (s.GetType() == GeomAbs_Plane && std::abs(s.Plane().Location().Z() - 2) < 1e-9) return {face, s.Plane()};
  }
  return {};
}

}  // namespace

TEST(UvBoundary, PlateWithAHoleDecidesAwayFromItsEdges) {
  const auto [face, plane] = plateTop(20, 15);
  ASSERT_FALSE(face.IsNull()) << "no top face";
  const UvBoundary boundary(face, 1e-3, 1e-3);
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
  for (const auto& [x, y, d] : {std::tuple{6.0, 3e-3, 3.0}, {25.001, 15.0, 1.0}, {5.0, 0.0, 0.0}, {12.0, 15.0, 3e3}}) {
    EXPECT_LE(clearance(x, y), d) << x << " " << y;
    EXPECT_GE(clearance(x, y), d - 0.25) << x << " " << y;
  }
  EXPECT_EQ(boundary.margin(), 1e-3);
}

// On a straight or circular edge within the tolerance, in closed form: the plate's top with a notch, a half disc cut
// from its rim (an arc of 180 degrees). A point on the arc's circle beyond the arc is not on it; every point called on
// an edge is ON for BRepClass_FaceClassifier.
TEST(UvBoundary, OnLineOrCircleIsOnForTheFaceClassifier) {
  const auto [face, plane] = plateTop(20, 0);
  ASSERT_FALSE(face.IsNull()) << "no top face";
  const UvBoundary boundary(face, 1e-3, 1e-3);
  constexpr double kTolerance = 1e-7;
  auto at = [&](double x, double y) {
    double u = 0, v = 0;
    ElSLib::Parameters(plane, gp_Pnt(x, y, 2), u, v);
    return gp_Pnt2d(u, v);
  };
  auto on = [&](double x, double y) {
    const gp_Pnt2d p = at(x, y);
    return boundary.onLineOrCircle(p.X(), p.Y(), kTolerance);
  };
  const double c = std::cos(0.7), sn = std::sin(0.7);
  EXPECT_TRUE(on(5, 0)) << "the rim";
  EXPECT_TRUE(on(5, 0.5 * kTolerance));
  EXPECT_FALSE(on(5, 3 * kTolerance));
  EXPECT_FALSE(on(20, 0)) << "the gap of the notch: the rim's line runs on, its edges do not";
  EXPECT_TRUE(on(40, 12)) << "the far end";
  EXPECT_TRUE(on(20 + 5 * c, 5 * sn)) << "the arc";
  EXPECT_TRUE(on(20 + (5 + 0.5 * kTolerance) * c, (5 + 0.5 * kTolerance) * sn));
  EXPECT_FALSE(on(20 + (5 + 3 * kTolerance) * c, (5 + 3 * kTolerance) * sn));
  EXPECT_FALSE(on(20 + 5 * c, -5 * sn)) << "the arc's circle beyond the arc";
  EXPECT_TRUE(on(25, 0)) << "the arc's end, the rim's";
  EXPECT_FALSE(on(10, 10)) << "inside";
  int checked = 0;
  for (const auto& [x, y] : {std::pair{5.0, 0.0},
                             {5.0, 0.5 * kTolerance},
                             {40.0, 12.0},
                             {20 + 5 * c, 5 * sn},
                             {25.0, 0.0},
                             {15.0, 0.0},
                             {0.0, 30.0}}) {
    if (!on(x, y)) continue;
    BRepClass_FaceClassifier classifier(face, at(x, y), kTolerance);
    EXPECT_EQ(classifier.State(), TopAbs_ON) << x << " " << y;
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}
