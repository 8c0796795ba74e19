// WallRays (π_t, π_b along a line, §3): where a ray first leaves the solid, on the wall asked for or a rim face,
// also when the ray runs along a face it starts on. Run on a strip with a 45° cut end, its faces planes as drawn
// and B-spline surfaces (as exporters and scalings write them), scaled by 1, 1e-3 and 1e3.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopoDS.hxx>

#include <string>

#include "geometry/wall_rays.hpp"

using namespace hexlayer;

namespace {

// A 60 x 20 x 2 strip (x, y, z) whose ends are cut at 45° about y: the parallelogram (0,0) (60,0) (62,2) (2,2)
// in xz, extruded 20 along y, all lengths times s.
TopoDS_Solid obliqueStrip(double s, bool bspline) {
  BRepBuilderAPI_MakePolygon outline(gp_Pnt(0, 0, 0), gp_Pnt(60 * s, 0, 0), gp_Pnt(62 * s, 0, 2 * s),
                                     gp_Pnt(2 * s, 0, 2 * s), true);
  const TopoDS_Shape prism =
      BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(outline.Wire()).Face(), gp_Vec(0, 20 * s, 0)).Shape();
  return TopoDS::Solid(bspline ? BRepBuilderAPI_NurbsConvert(prism, true).Shape() : prism);
}

}  // namespace

TEST(WallRays, RaysFromTheMidPlaneEndOnTopAndBottomOnlyThroughThem) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallSides sides = classifyWallSides(cad);
  WallRays rays(cad, sides);
  const Vec3 mid(10, 10, 1), tilted = Vec3(1, 0, 1).normalized();
  const auto top = rays.cast(Side::Top, mid, Vec3::UnitZ(), 5),
             bottom = rays.cast(Side::Bottom, mid, -Vec3::UnitZ(), 5);
  ASSERT_TRUE(top && bottom);
  EXPECT_NEAR((top->point - Vec3(10, 10, 2)).norm(), 0, 1e-9);
  EXPECT_NEAR((bottom->point - Vec3(10, 10, 0)).norm(), 0, 1e-9);
  EXPECT_EQ(top->face, 5) << "Face6, z = 2";
  EXPECT_EQ(bottom->face, 4) << "Face5, z = 0";
  EXPECT_NEAR((rays.cast(Side::Top, mid, tilted, 5)->point - Vec3(11, 10, 2)).norm(), 0, 1e-9);
  EXPECT_FALSE(rays.cast(Side::Bottom, mid, Vec3::UnitZ(), 5)) << "the first wall up is the top";
  EXPECT_FALSE(rays.cast(Side::Top, mid, Vec3::UnitZ(), 0.5)) << "beyond the reach";
  EXPECT_FALSE(rays.cast(Side::Top, Vec3(39.5, 10, 1), Vec3(1, 0, 0.2).normalized(), 5)) << "out through the rim";
}

TEST(WallRays, RaysAcrossTheWallsAndAlongAFace) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      const CadSolid cad = prepareSolid(obliqueStrip(s, bspline));
      const WallSides sides = classifyWallSides(cad);
      WallRays rays(cad, sides);
      // Inside, up and down: the walls.
      const std::optional<FacePoint> top = rays.cast(Side::Top, Vec3(30, 10, 1) * s, Vec3(0, 0, 1), 5 * s);
      ASSERT_TRUE(top);
      EXPECT_NEAR((top->point - Vec3(30, 10, 2) * s).norm(), 0, 1e-9 * s);
      EXPECT_EQ(sides.faces[top->face].side, Side::Top);
      const std::optional<FacePoint> bottom = rays.cast(Side::Bottom, Vec3(30, 10, 1) * s, Vec3(0, 0, -1), 5 * s);
      ASSERT_TRUE(bottom);
      EXPECT_NEAR((bottom->point - Vec3(30, 10, 0) * s).norm(), 0, 1e-9 * s);
      // Up from under the cut: the cut (a rim face), not the top wall it would reach beyond.
      EXPECT_FALSE(rays.cast(Side::Top, Vec3(1.5, 10, 1) * s, Vec3(0, 0, 1), 5 * s)) << "a rim face is not a wall";
      const std::optional<FacePoint> cut = rays.cast(Side::Top, Vec3(1.5, 10, 1) * s, Vec3(0, 0, 1), 5 * s, true);
      ASSERT_TRUE(cut);
      EXPECT_NEAR((cut->point - Vec3(1.5, 10, 1.5) * s).norm(), 0, 1e-9 * s);
      // The same ray in the side face y = 0: it runs along that face (a B-spline face meets it at many tangent
      // points) and leaves the solid where it crosses the cut.
      const std::optional<FacePoint> along = rays.cast(Side::Top, Vec3(1.5, 0, 1) * s, Vec3(0, 0, 1), 5 * s, true);
      ASSERT_TRUE(along);
      EXPECT_NEAR((along->point - Vec3(1.5, 0, 1.5) * s).norm(), 0, 1e-6 * s);
      EXPECT_EQ(sides.faces[along->face].side, Side::Lateral);
      // The line through a point of the side face along the cut's normal meets the cut there.
      const Vec3 normal = Vec3(-1, 0, 1).normalized();
      const std::optional<FacePoint> rim = rays.nearestOnLine(Side::Lateral, Vec3(1.5, 0, 1) * s, normal, 2 * s);
      ASSERT_TRUE(rim);
      EXPECT_NEAR((rim->point - Vec3(1.25, 0, 1.25) * s).norm(), 0, 1e-6 * s);
    }
}
