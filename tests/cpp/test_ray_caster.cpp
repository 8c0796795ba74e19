// RayCaster (geometry/ray_caster.hpp): the hits of a line on a solid's faces, the nearest one, and inside or
// outside by the parity of a ray's crossings, against OpenCASCADE's intersector and classifier that try every face,
// on a plate with a grid of holes (many faces), its faces planes and B-splines (hits on those from their
// SurfaceGrid, Newton's method from the cells a line passes, where that decides), scaled by 1, 1e-3 and 1e3; its
// closed-form hits on planar faces against each face's own intersector on a plate with 77 holes, near its edges and
// vertices too, and on cylinders, spheres, cones and tori pierced by holes.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Tool.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "geometry/ray_caster.hpp"
#include "test_parts.hpp"

using namespace hexlayer;

namespace {

// A 60 x 40 x 2 plate with a 5 x 3 grid of Ø4 through holes at 10 pitch, all lengths times s.
TopoDS_Solid holedPlate(double s, bool bspline) {
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60 * s, 40 * s, 2 * s).Shape();
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      plate = BRepAlgoAPI_Cut(
                  plate, BRepPrimAPI_MakeCylinder(
                             gp_Ax2(gp_Pnt((10 + 10 * i) * s, (10 + 10 * j) * s, -s), gp_Dir(0, 0, 1)), 2 * s, 4 * s)
                             .Shape())
                  .Shape();
  if (bspline) plate = BRepBuilderAPI_NurbsConvert(plate, true).Shape();
  TopExp_Explorer solid(plate, TopAbs_SOLID);
  return TopoDS::Solid(solid.Current());
}

gp_Lin lineOf(const Vec3& p, const Vec3& d) { return gp_Lin(gp_Pnt(p.x(), p.y(), p.z()), gp_Dir(d.x(), d.y(), d.z())); }

}  // namespace

TEST(RayCaster, HitsAndTheNearestAsOpenCascadesIntersectorOfEveryFace) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      const CadSolid cad = prepareSolid(holedPlate(s, bspline));
      ASSERT_GE(cad.faces.Extent(), 6 + 15);
      const double tolerance = 1e-7 * cad.diagonal;
      RayCaster rays(cad, tolerance);
      IntCurvesFace_ShapeIntersector every;
      every.Load(cad.solid, tolerance);
      int compared = 0;
      for (int k = 0; k < 40; ++k) {  // lines through the plate at many angles, some through holes
        const Vec3 p = Vec3(3 + 1.37 * k, 2 + 0.91 * k, 1) * s;
        const Vec3 d = Vec3(std::cos(0.7 * k), std::sin(0.7 * k), 0.2 * std::sin(1.3 * k)).normalized();
        const std::vector<RayHit> hits = rays.all(p, d, -100 * s, 100 * s);
        every.Perform(lineOf(p, d), -100 * s, 100 * s);
        ASSERT_EQ(static_cast<int>(hits.size()), every.NbPnt());
        for (int i = 1; i <= every.NbPnt(); ++i) {
          EXPECT_NEAR(hits[i - 1].w, every.WParameter(i), 1e-9 * s);
          EXPECT_EQ(hits[i - 1].face, cad.faces.FindIndex(every.Face(i)) - 1);
        }
        const std::optional<RayHit> nearest = rays.nearest(p, d, 0, 100 * s);
        every.PerformNearest(lineOf(p, d), 0, 100 * s);
        ASSERT_EQ(nearest.has_value(), every.NbPnt() > 0);
        if (nearest) {
          EXPECT_NEAR(nearest->w, every.WParameter(1), 1e-9 * s);
          EXPECT_EQ(nearest->face, cad.faces.FindIndex(every.Face(1)) - 1);
          ++compared;
        }
      }
      EXPECT_GT(compared, 30);
    }
}

TEST(RayCaster, InsideAsOpenCascadesClassifier) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      const CadSolid cad = prepareSolid(holedPlate(s, bspline));
      const double tolerance = 1e-7 * cad.diagonal;
      RayCaster rays(cad, tolerance);
      BRepClass3d_SolidClassifier exact(cad.solid);
      int inside = 0, outside = 0, unsure = 0;
      for (int i = 0; i <= 61; i += 2)  // a grid through the plate, its holes and beside it
        for (int j = 0; j <= 41; j += 4)
          for (double z : {-0.5, 0.3, 1.0, 1.9, 2.5}) {
            const Vec3 p = Vec3(i - 0.5, j + 0.25, z) * s;
            const std::optional<bool> in = rays.inside(p, tolerance, 2 * cad.diagonal);
            if (!in) {
              ++unsure;
              continue;
            }
            exact.Perform(gp_Pnt(p.x(), p.y(), p.z()), tolerance);
            EXPECT_EQ(*in, exact.State() == TopAbs_IN) << p.transpose() / s;
            (*in ? inside : outside) += 1;
          }
      // on B-splines rays are counted where each face's SurfaceGrid decides its hits (not near its edges)
      EXPECT_GT(inside, bspline ? 100 : 150);
      EXPECT_GT(outside, 150);
      EXPECT_LT(unsure, bspline ? 200 : 10) << inside << " inside, " << outside << " outside";
      if (bspline) EXPECT_GT(rays.gridAnswers(), 1000);
    }
}

// Gmsh's periodic curved shell (B-spline faces, one with a degenerated edge): near its edges OpenCASCADE's intersector
// throws on some rays (its ON test projects on the degenerated edge's missing curve); such a ray counts nothing, and
// the points are inside or outside as the classifier has them, or undecided, never an error.
TEST(RayCaster, InsideNearTheEdgesOfBSplineFacesNeverThrows) {
  const CadSolid cad =
      prepareSolid(readSolids(std::string(HEXLAYER_SHARED_PARTS) + "/gmsh_periodic_u_cst_curved_shell.step").at(0));
  const double tolerance = 1e-7 * cad.diagonal;
  RayCaster rays(cad, tolerance);
  BRepClass3d_SolidClassifier exact(cad.solid);
  int answered = 0, points = 0;
  for (TopExp_Explorer e(cad.solid, TopAbs_EDGE); e.More(); e.Next()) {
    if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) continue;
    const BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
    for (int k = 0; k <= 40; ++k) {
      const gp_Pnt q = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / 40.0);
      for (double dx : {-0.05, -0.01, 0.0, 0.01, 0.05})
        for (double dz : {-0.05, 0.0, 0.05}) {
          const Vec3 p(q.X() + dx, q.Y() + 0.7 * dz, q.Z() + dz);
          std::optional<bool> in;
          ASSERT_NO_THROW(in = rays.inside(p, tolerance, 2 * cad.diagonal)) << p.transpose();
          if (!in || ++points % 10) continue;  // every tenth answer against the classifier (milliseconds a point)
          exact.Perform(gp_Pnt(p.x(), p.y(), p.z()), tolerance);
          EXPECT_EQ(*in, exact.State() == TopAbs_IN) << p.transpose();
          ++answered;
        }
    }
  }
  EXPECT_GT(answered, 100);
}

namespace {

// Every hit of the line on every face by its own IntCurvesFace_Intersector, as RayCaster::all orders them.
std::vector<RayHit> everyFacesHits(std::vector<std::unique_ptr<IntCurvesFace_Intersector>>& faces, const gp_Lin& line,
                                   double wMin, double wMax) {
  std::vector<RayHit> hits;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    IntCurvesFace_Intersector& on = *faces[f];
    on.Perform(line, wMin, wMax);
    for (int i = 1; on.IsDone() && i <= on.NbPnt(); ++i) {
      const gp_Pnt& p = on.Pnt(i);
      hits.push_back({on.WParameter(i), static_cast<int>(f), Vec3(p.X(), p.Y(), p.Z()), on.UParameter(i),
                      on.VParameter(i), on.Transition(i)});
    }
  }
  std::sort(hits.begin(), hits.end(),
            [](const RayHit& a, const RayHit& b) { return a.w < b.w || (a.w == b.w && a.face < b.face); });
  return hits;
}

// How many hits two ray casts compared, and on how many lines OpenCASCADE's intersector threw.
struct Compared {
  std::size_t hits = 0;
  int intersectorThrew = 0;
};

// Checks RayCaster::all's hits of each line (point, direction) on the solid against each face's own OpenCASCADE
// intersector (what RayCaster asked before): the same hits, faces, parameters, points and transitions, to the last
// bit; where the intersector throws, that RayCaster does not. [in] cad; [in,out] rays: its caster; [in] lines;
// [in] reach: w in [-reach, reach].
Compared expectHitsAsTheIntersectors(const CadSolid& cad, RayCaster& rays,
                                     const std::vector<std::pair<Vec3, Vec3>>& lines, double reach) {
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> faces;
  for (int f = 1; f <= cad.faces.Extent(); ++f)
    faces.push_back(std::make_unique<IntCurvesFace_Intersector>(TopoDS::Face(cad.faces(f)), 1e-7 * cad.diagonal));
  Compared compared;
  for (const auto& [p, d] : lines) {
    std::vector<RayHit> expected;
    try {
      expected = everyFacesHits(faces, lineOf(p, d), -reach, reach);
    } catch (const Standard_Failure&) {  // an edge without a 3D curve (a sphere's pole) met near the face's boundary
      ++compared.intersectorThrew;
      EXPECT_NO_THROW(rays.all(p, d, -reach, reach));  // classified exactly instead
      continue;
    }
    const std::vector<RayHit> hits = rays.all(p, d, -reach, reach);
    EXPECT_EQ(hits.size(), expected.size()) << p.transpose() << " along " << d.transpose();
    if (hits.size() != expected.size()) continue;
    for (std::size_t i = 0; i < hits.size(); ++i) {
      EXPECT_EQ(hits[i].face, expected[i].face);
      EXPECT_EQ(hits[i].w, expected[i].w);
      EXPECT_EQ(hits[i].u, expected[i].u);
      EXPECT_EQ(hits[i].v, expected[i].v);
      EXPECT_EQ(hits[i].point, expected[i].point);
      EXPECT_EQ(hits[i].transition, expected[i].transition);
    }
    compared.hits += hits.size();
  }
  return compared;
}

// A shell between two elementary surfaces pierced by holes: a tube (test_parts::perforatedTube), a spherical shell (R
// 12 / 10) with 8 radial holes, a conical one (R 12 -> 6 outside, 10 -> 4 inside, 20 high) with 6, a toroidal one (R
// 20, r 5 / 3) with 8 holes along z through its tube; all lengths times s.
TopoDS_Solid pierced(const std::string& kind, double s) {
  TopoDS_Shape shell;
  std::vector<gp_Ax2> holes;  // each a Ø3 hole 40 long from its axis' origin
  auto radial = [&](double angle, double z, double tilt) {
    const gp_Dir d(std::cos(angle) * std::cos(tilt), std::sin(angle) * std::cos(tilt), std::sin(tilt));
    holes.emplace_back(gp_Pnt(0, 0, z * s), d);
  };
  if (kind == "tube") {
    return test_parts::perforatedTube(s);
  } else if (kind == "sphere") {
    shell = BRepAlgoAPI_Cut(BRepPrimAPI_MakeSphere(12 * s).Shape(), BRepPrimAPI_MakeSphere(10 * s).Shape()).Shape();
    for (int i = 0; i < 8; ++i) radial(0.3 + i * 0.8, 0, -0.9 + 0.25 * i);
  } else if (kind == "cone") {
    shell = BRepAlgoAPI_Cut(BRepPrimAPI_MakeCone(12 * s, 6 * s, 20 * s).Shape(),
                            BRepPrimAPI_MakeCone(10 * s, 4 * s, 20 * s).Shape())
                .Shape();
    for (int i = 0; i < 6; ++i) radial(0.2 + i * 1.05, 4 + 2.5 * i, 0);
  } else {  // torus
    shell = BRepAlgoAPI_Cut(BRepPrimAPI_MakeTorus(20 * s, 5 * s).Shape(), BRepPrimAPI_MakeTorus(20 * s, 3 * s).Shape())
                .Shape();
    for (int i = 0; i < 8; ++i) {
      const double a = 0.1 + i * 0.79, r = 20 + 3.5 * std::cos(2.0 * i);
      holes.emplace_back(gp_Pnt(r * std::cos(a) * s, r * std::sin(a) * s, -20 * s), gp_Dir(0, 0, 1));
    }
  }
  for (const gp_Ax2& axis : holes)
    shell = BRepAlgoAPI_Cut(shell, BRepPrimAPI_MakeCylinder(axis, 1.5 * s, 40 * s).Shape());
  TopExp_Explorer solid(shell, TopAbs_SOLID);
  return TopoDS::Solid(solid.Current());
}

// Points on the solid's edges (two along each) and off them by 1e-12 .. 0.3 (times s) along a slant.
std::vector<Vec3> pointsNearEdgesOf(const CadSolid& cad, double s) {
  std::vector<Vec3> points;
  for (TopExp_Explorer e(cad.solid, TopAbs_EDGE); e.More(); e.Next()) {
    if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) continue;
    const BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
    for (double t : {0.17, 0.62}) {
      const Vec3 at = toVec(c.Value(c.FirstParameter() + t * (c.LastParameter() - c.FirstParameter())));
      for (double off : {0.0, 1e-12, -1e-7, 1e-5, 0.3}) points.push_back(at + off * s * Vec3(0.6, -0.48, 0.64));
    }
  }
  return points;
}

}  // namespace

// The closed-form hits on planar faces against each face's own OpenCASCADE intersector (what RayCaster asked before):
// the same hits, faces, parameters, points and transitions, to the last bit, for lines through the plate at many
// angles and through points on and near its edges and vertices (those near the boundary left to the intersector).
TEST(RayCaster, ClosedFormPlaneHitsAsTheIntersectorsOnAPlateWithManyHoles) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = test_parts::plateWithManyHoles(s);
    ASSERT_EQ(cad.faces.Extent(), 6 + 77);
    RayCaster rays(cad, 1e-7 * cad.diagonal);
    std::vector<std::pair<Vec3, Vec3>> lines;  // point, direction
    for (int k = 0; k < 60; ++k)               // through the plate at many angles, some through holes
      lines.emplace_back(Vec3(3 + 0.97 * k, 2 + 0.61 * k, 1) * s,
                         Vec3(std::cos(0.7 * k), std::sin(0.7 * k), 0.2 + std::sin(1.3 * k)).normalized());
    for (const Vec3& p : test_parts::pointsNearEdges(s))  // near the edges: across the plate, oblique and along it
      for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0.3, -0.2, 1).normalized(), Vec3(1, 0.4, 1e-3).normalized()})
        lines.emplace_back(p, d);
    EXPECT_GT(expectHitsAsTheIntersectors(cad, rays, lines, 100 * s).hits, 500u);
    EXPECT_GT(rays.closedFormAnswers(), 300);  // the closed form was used (most rays are far from the edges)
  }
}

// The same on cylinders, spheres, cones and tori pierced by holes (a perforated tube's faces: the intersector's
// classification walked its 150 holes' edges at every hit): lines through the shell at many angles, through the
// holes, and through points on and near every edge. Where the intersector throws (an edge without a 3D curve, a
// sphere's pole, near a hit), RayCaster classifies the hits exactly instead.
TEST(RayCaster, ClosedFormHitsOnCylindersSpheresConesAndToriAsTheIntersectors) {
  int threw = 0;
  for (const std::string kind : {"tube", "sphere", "cone", "torus"})
    for (double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE(kind + " x " + std::to_string(s));
      const CadSolid cad = prepareSolid(pierced(kind, s));
      RayCaster rays(cad, 1e-7 * cad.diagonal);
      std::vector<std::pair<Vec3, Vec3>> lines;
      for (int k = 0; k < 80; ++k)  // through the shell's middle at many angles
        lines.emplace_back(Vec3(std::sin(0.9 * k), 3 * std::cos(1.1 * k), 6 + 0.2 * k) * s,
                           Vec3(std::cos(0.7 * k), std::sin(0.7 * k), 0.4 * std::sin(1.3 * k)).normalized());
      for (const Vec3& p : pointsNearEdgesOf(cad, s))
        for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0.8, -0.3, 0.2).normalized()}) lines.emplace_back(p, d);
      const Compared compared = expectHitsAsTheIntersectors(cad, rays, lines, 100 * s);
      EXPECT_GT(compared.hits, 200u);
      EXPECT_GT(rays.closedFormAnswers(), 200);  // decided in closed form, away from the edges
      threw += compared.intersectorThrew;
    }
  EXPECT_GT(threw, 0);  // the intersector threw on some lines by the sphere's poles: RayCaster did not
}
