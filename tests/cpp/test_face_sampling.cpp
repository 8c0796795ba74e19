// Points on a CAD face (geometry/face_sampling.hpp), spread over its triangulation and put on the exact surface.
#include <gtest/gtest.h>
#include <BRepAdaptor_Surface.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>

#include "geometry/cad_solid.hpp"
#include "geometry/face_sampling.hpp"

using namespace hexlayer;

// The top of a 40 x 30 x 2 box (the face whose plane is z = 2), sampled every 1: the samples' areas add up to
// 1200, every point is on the plane inside the rectangle, every normal is +z (out of the solid), and there are
// about 1200 of them (at least one per triangle, about one per square of the spacing).
TEST(FaceSampling, TheTopOfABoxIsCoveredOutwardAndOnItsPlane) {
  const CadSolid box = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  int top = -1;
  for (int f = 1; f <= box.faces.Extent(); ++f) {
    const BRepAdaptor_Surface s(TopoDS::Face(box.faces(f)));
    if (s.GetType() == GeomAbs_Plane && std::abs(s.Plane().Location().Z() - 2) < 1e-12 &&
        std::abs(std::abs(s.Plane().Axis().Direction().Z()) - 1) < 1e-12)
      top = f;
  }
  ASSERT_GT(top, 0);
  EXPECT_NEAR(triangulatedArea(box.faces(top)), 1200, 1e-9);
  const std::vector<FaceSample> samples = sampleFace(box.faces(top), 1.0);
  double area = 0;
  for (const FaceSample& s : samples) {
    area += s.area;
    EXPECT_NEAR(s.point.z(), 2, 1e-12);
    EXPECT_GE(s.point.x(), -1e-12);
    EXPECT_LE(s.point.x(), 40 + 1e-12);
    EXPECT_GE(s.point.y(), -1e-12);
    EXPECT_LE(s.point.y(), 30 + 1e-12);
    EXPECT_NEAR((s.normal - Vec3::UnitZ()).norm(), 0, 1e-12);
  }
  EXPECT_NEAR(area, 1200, 1e-9);
  EXPECT_GT(samples.size(), 600u);
  EXPECT_LT(samples.size(), 2400u);
}

// The side of a cylinder of radius 5 and height 10: every sample on the exact surface (radius 5, not the
// triangulation's chords) with the radial normal outward; the areas add up to the triangulation's area, within
// 1 % of 2 pi 5 x 10.
TEST(FaceSampling, ACylinderIsSampledOnItsExactSurface) {
  const CadSolid cylinder =
      prepareSolid(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 5, 10).Solid());
  int side = -1;
  for (int f = 1; f <= cylinder.faces.Extent(); ++f)
    if (BRepAdaptor_Surface(TopoDS::Face(cylinder.faces(f))).GetType() == GeomAbs_Cylinder) side = f;
  ASSERT_GT(side, 0);
  const std::vector<FaceSample> samples = sampleFace(cylinder.faces(side), 1.0);
  double area = 0;
  for (const FaceSample& s : samples) {
    area += s.area;
    const Vec3 radial(s.point.x(), s.point.y(), 0);
    EXPECT_NEAR(radial.norm(), 5, 1e-9);
    EXPECT_NEAR((s.normal - radial.normalized()).norm(), 0, 1e-9);
  }
  EXPECT_NEAR(area, triangulatedArea(cylinder.faces(side)), 1e-9);
  EXPECT_NEAR(area, 2 * M_PI * 5 * 10, 0.01 * 2 * M_PI * 5 * 10);
}
