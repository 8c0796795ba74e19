// WallProjector (π_t, π_b for points, §3): nearest point of the top or the bottom CAD wall, on the
// trimmed faces (their edges when the point lies beyond them), exact on curved walls; on planar faces its closed form
// as BRepExtrema's to the last bit.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/cad_faces.hpp"
#include "geometry/wall_projector.hpp"
#include "test_parts.hpp"

using namespace hexlayer;

TEST(WallProjector, PlateWallsAndTheirEdges) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallProjector walls(cad, classifyWallSides(cad));
  EXPECT_NEAR((walls.project(Side::Top, Vec3(10, 10, 1.4))->point - Vec3(10, 10, 2)).norm(), 0, 1e-9);
  EXPECT_NEAR((walls.project(Side::Bottom, Vec3(10, 10, 1.4))->point - Vec3(10, 10, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR((walls.project(Side::Top, Vec3(10, 10, -3))->point - Vec3(10, 10, 2)).norm(), 0, 1e-9)
      << "from the far side";
  EXPECT_NEAR((walls.project(Side::Top, Vec3(41, 10, 2.5))->point - Vec3(40, 10, 2)).norm(), 0, 1e-9)
      << "beyond the rim: its edge";
  EXPECT_NEAR((walls.project(Side::Lateral, Vec3(39.8, 10, 1.3))->point - Vec3(40, 10, 1.3)).norm(), 0, 1e-9)
      << "the rim";
  // MakeBox numbers its faces like FreeCAD's Part box: Face1 x = 0, Face2 x = 40, ..., Face5 z = 0, Face6 z = 2.
  EXPECT_EQ(walls.project(Side::Top, Vec3(10, 10, 1.4))->face, 5);
  EXPECT_EQ(walls.project(Side::Bottom, Vec3(10, 10, 1.4))->face, 4);
  EXPECT_EQ(walls.project(Side::Lateral, Vec3(39.8, 10, 1.3))->face, 1);
}

TEST(WallProjector, CylinderShellWallsAreHitExactly) {
  // Quarter of a tube: radii 10 and 12, height 40. Its inner and outer faces are the two walls.
  const TopoDS_Shape outer = BRepPrimAPI_MakeCylinder(12, 40, M_PI / 2).Shape();
  const TopoDS_Shape inner = BRepPrimAPI_MakeCylinder(10, 40, M_PI / 2).Shape();
  const TopoDS_Shape tube = BRepAlgoAPI_Cut(outer, inner).Shape();
  TopExp_Explorer solid(tube, TopAbs_SOLID);
  ASSERT_TRUE(solid.More());
  const CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()));
  const WallProjector walls(cad, classifyWallSides(cad));
  const double angle = 0.3;
  const Vec3 chordMidpoint(11.2 * std::cos(angle), 11.2 * std::sin(angle), 17);
  double radii[2];
  for (int s = 0; s < 2; ++s) {
    const std::optional<FacePoint> hit = walls.project(s ? Side::Top : Side::Bottom, chordMidpoint);
    ASSERT_TRUE(hit);
    const Vec3& p = hit->point;
    radii[s] = std::hypot(p.x(), p.y());
    EXPECT_NEAR(std::atan2(p.y(), p.x()), angle, 1e-9);
    EXPECT_NEAR(p.z(), 17, 1e-9);
    EXPECT_EQ(BRepAdaptor_Surface(TopoDS::Face(cad.faces(hit->face + 1))).GetType(), GeomAbs_Cylinder);
  }
  EXPECT_NEAR(std::min(radii[0], radii[1]), 10, 1e-9);
  EXPECT_NEAR(std::max(radii[0], radii[1]), 12, 1e-9);
}

// The middle between the walls' rim edges (rimMiddle): on a box's flat rim, its middle line; on the strip cut at
// 70.5 degrees, the middle of the cut (between its bottom edge at x = 0 and its top edge at x = 5.66); on the
// plate with a near-full-round hole (R6, fillets 0.98 on both edges), the fillets' axis at radius 6.98.
TEST(WallProjector, RimMiddleIsHalfWayBetweenTheWallsRimEdges) {
  const CadSolid box = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallProjector plate(box, classifyWallSides(box));
  EXPECT_NEAR((*plate.rimMiddle(Vec3(39.5, 10, 0.7)) - Vec3(40, 10, 1)).norm(), 0, 1e-9);
  auto sample = [](const char* name) {
    return prepareSolid(readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/rims/" + name).at(0));
  };
  const CadSolid strip = sample("strip_oblique_3x.step");
  const WallProjector oblique(strip, classifyWallSides(strip));
  EXPECT_NEAR((*oblique.rimMiddle(Vec3(2.5, 10, 1)) - Vec3(2 * std::sqrt(2.0), 10, 1)).norm(), 0, 1e-6);
  const CadSolid hole = sample("plate_hole_full_round.step");
  const WallProjector round(hole, classifyWallSides(hole));
  const Vec3 m = *round.rimMiddle(Vec3(25 + 5.3, 15, 1.1));
  EXPECT_NEAR(m.x(), 25 + 6.98, 1e-6);
  EXPECT_NEAR(m.y(), 15, 1e-6);
  EXPECT_NEAR(m.z(), 1, 1e-6);
}

// The closed form on planar faces (CadFaceProbe::planeFoot) against BRepExtrema_DistShapeShape built for the query
// (what WallProjector asked before): the same distance and point, to the last bit, for points above, below and in
// the plate with 77 holes, on and near its edges and vertices and at heights from 0 to 30 x the wall.
TEST(WallProjector, PlaneFeetAreBRepExtremasOnAPlateWithManyHoles) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = test_parts::plateWithManyHoles(s);
    const WallProjector walls(cad, classifyWallSides(cad));
    std::vector<Vec3> points;
    for (int k = 0; k < 80; ++k) points.push_back(Vec3(0.77 * k - 1, 0.53 * k - 1, 0.9 + 0.4 * std::sin(k)) * s);
    for (const Vec3& p : test_parts::pointsNearEdges(s))
      for (double z : {0.0, 1e-9, 0.5, 1.3, 60.0}) points.push_back(p + Vec3(0, 0, z * s));
    CadFaces cadFaces(cad);
    CadFaceProbe probe(cadFaces);
    int faces = 0, closedForm = 0;
    for (const Vec3& p : points)
      for (int f : {0, 1, 2, 3, 4, 5, 40}) {  // the box's faces and a hole's
        const TopoDS_Vertex v = BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z())).Vertex();
        BRepExtrema_DistShapeShape exact(v, cad.faces(f + 1));
        ASSERT_TRUE(exact.IsDone() && exact.NbSolution() > 0);
        const std::optional<FacePoint> on = walls.projectOntoFace(f, p);
        ASSERT_TRUE(on);
        const gp_Pnt q = exact.PointOnShape2(1);
        EXPECT_EQ(on->point, Vec3(q.X(), q.Y(), q.Z())) << p.transpose() / s << " on face " << f;
        EXPECT_EQ(on->face, f);
        ++faces;
        if (const auto foot = probe.planeFoot(f, gp_Pnt(p.x(), p.y(), p.z()))) {
          EXPECT_EQ(foot->first, exact.Value());
          EXPECT_TRUE(foot->second.IsEqual(q, 0));
          ++closedForm;
        }
      }
    EXPECT_GT(faces, 1000);
    EXPECT_GT(closedForm, 300);  // the closed form was used (not near an edge, not beside a face)
  }
}

// On B-spline faces (the twisted strip's walls) the foot point comes from the face's own extrema tool
// (CadFaceProbe::foot) where the face's edges and vertices are farther: BRepExtrema_DistShapeShape's distance and
// point up to its Newton steps' rounding, for points on, between and beyond the walls, inside and near the rim.
TEST(WallProjector, FeetOnBSplineFacesAreBRepExtremas) {
  const CadSolid cad =
      prepareSolid(readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/twisted_strip.step").at(0));
  const WallProjector walls(cad, classifyWallSides(cad));
  CadFaces cadFaces(cad);
  CadFaceProbe probe(cadFaces);
  int faces = 0, feet = 0;
  for (int f = 0; f < cadFaces.count(); ++f) {
    const BRepAdaptor_Surface s(cadFaces.face(f).face);
    if (s.GetType() != GeomAbs_BSplineSurface) continue;
    const double* b = cadFaces.face(f).uvBounds;
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j) {
        gp_Pnt on;
        gp_Vec du, dv;
        s.D1(b[0] + (b[1] - b[0]) * i / 8.0, b[2] + (b[3] - b[2]) * j / 8.0, on, du, dv);
        const gp_Vec n = du.Crossed(dv).Normalized();
        for (double offset : {0.0, 1e-9, 0.4, -0.7, 1.5}) {
          const gp_Pnt p = on.Translated(offset * n);
          BRepExtrema_DistShapeShape exact(BRepBuilderAPI_MakeVertex(p).Vertex(), cad.faces(f + 1));
          ASSERT_TRUE(exact.IsDone() && exact.NbSolution() > 0);
          const std::optional<FacePoint> got = walls.projectOntoFace(f, Vec3(p.X(), p.Y(), p.Z()));
          ASSERT_TRUE(got);
          const gp_Pnt q = exact.PointOnShape2(1);
          EXPECT_NEAR((got->point - Vec3(q.X(), q.Y(), q.Z())).norm(), 0, 1e-6) << "face " << f << " " << i << " " << j;
          EXPECT_EQ(got->face, f);
          if (const auto foot = probe.foot(f, p)) {
            EXPECT_NEAR(foot->first, exact.Value(), 1e-8);
            ++feet;
          }
          ++faces;
        }
      }
  }
  EXPECT_GT(faces, 400);
  EXPECT_GT(feet, faces / 2);  // the foot was used inside the faces, BRepExtrema near their edges
}
