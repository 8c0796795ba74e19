// Distances to the CAD faces (geometry/cad_faces.hpp): CadFaceProbe's distance to a trimmed
// face is BRepExtrema_DistShapeShape's, to the last bit on planes, cylinders, spheres (and up to the rounding of
// their Newton steps, 1e-8, on B-splines), and whether a point lies on a face (within its tolerance) is always
// BRepExtrema's, on the faces (inside, at and near their edges and vertices), just off them and far away, also where
// a B-spline's nearest point is outside the face (over a hole).
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "geometry/cad_faces.hpp"

using namespace hexlayer;

namespace {

Vec3 vec(const gp_Pnt& p) { return Vec3(p.X(), p.Y(), p.Z()); }

// BRepExtrema_DistShapeShape from a vertex at p to the face, as CadFaces used to measure it.
double reference(const CadFaces& faces, int face, const Vec3& p) {
  BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z())).Vertex(), faces.face(face).face);
  return d.IsDone() && d.NbSolution() > 0 ? d.Value() : std::numeric_limits<double>::infinity();
}

// Points on a grid over the face's parameter range (outside the trimmed face too), moved along the
// normal by 0, 1e-13, 2e-7 and 0.3, and points on its edges (their ends too) and just off them.
std::vector<Vec3> probePoints(const CadFaces::Face& f) {
  std::vector<Vec3> points;
  const BRepAdaptor_Surface s(f.face);
  const double* b = f.uvBounds;
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j <= 5; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      s.D1(b[0] + (b[1] - b[0]) * i / 5.0, b[2] + (b[3] - b[2]) * j / 5.0, p, du, dv);
      const gp_Vec n = du.Crossed(dv);
      const Vec3 normal = n.Magnitude() > 1e-12 ? vec(gp_Pnt(n.XYZ() / n.Magnitude())) : Vec3::UnitZ();
      for (double offset : {0.0, 1e-13, 2e-7, 0.3}) points.push_back(vec(p) + offset * normal);
    }
  for (TopExp_Explorer e(f.face, TopAbs_EDGE); e.More(); e.Next()) {
    if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) continue;
    const BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
    for (int k = 0; k <= 4; ++k) {
      const Vec3 p = vec(c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / 4.0));
      for (const Vec3& off : {Vec3(0, 0, 0), Vec3(1e-9, -1e-9, 1e-9), Vec3(3e-6, 2e-6, -1e-6)})
        points.push_back(p + off);
    }
  }
  return points;
}

// The faces whose nearest points Extrema_ExtPS finds in closed form (on other surfaces it walks its grid or tree).
bool analytic(const CadFaces::Face& f) {
  const GeomAbs_SurfaceType type = BRepAdaptor_Surface(f.face).GetType();
  return type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone || type == GeomAbs_Sphere ||
         type == GeomAbs_Torus;
}

// Checks every probe point of every face against its face and the faces around it; returns how many.
int expectSameAsBRepExtrema(const CadSolid& cad) {
  const CadFaces faces(cad);
  CadFaceProbe probe(faces);
  int checked = 0;
  for (int f = 0; f < faces.count(); ++f)
    for (const Vec3& p : probePoints(faces.face(f))) {
      std::vector<int> around = faces.face(f).neighbours;
      around.push_back(f);
      for (int g : around) {
        const double fast = probe.distance(g, p), exact = reference(faces, g, p);
        if (analytic(faces.face(g)))
          EXPECT_EQ(std::memcmp(&fast, &exact, sizeof fast), 0)
              << "face " << g << " at (" << p.transpose() << "): " << fast << " against BRepExtrema's " << exact;
        else  // Extrema's tree search and BRepExtrema's grid walk end their Newton steps a little apart
          EXPECT_NEAR(fast, exact, 1e-8) << "face " << g << " at (" << p.transpose() << ")";
        EXPECT_EQ(probe.lies(g, p),
                  !faces.face(g).box.IsOut(gp_Pnt(p.x(), p.y(), p.z())) && exact < faces.tolerance(g));
        ++checked;
      }
    }
  return checked;
}

CadSolid readPart(const std::string& path) {
  const std::vector<TopoDS_Solid> solids = readSolids(path);
  EXPECT_FALSE(solids.empty()) << path;
  return prepareSolid(solids.at(0));
}

}  // namespace

TEST(CadFaces, DistancesAreBRepExtremasOnTheSamples) {
  for (const char* name : {"plate_holes", "hat_holes", "spherical_cap", "twisted_strip", "cylinder_shell"})
    EXPECT_GT(
        expectSameAsBRepExtrema(readPart(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/" + name + ".step")),
        500)
        << name;
}

// The lines through plate_holes' hole centres run through the holes' seams, where a circle's pcurve
// ends meet a few ulps apart: a point there was once classified outside its face (10 mm off).
TEST(CadFaces, PointsOnTheLinesThroughTheHoleCentresAreBRepExtremas) {
  const CadSolid cad = readPart(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/plate_holes.step");
  const CadFaces faces(cad);
  CadFaceProbe probe(faces);
  int onFace = 0;
  for (int f = 0; f < faces.count(); ++f)
    for (double z : {0.0, 2.0})
      for (double centre : {12.0, 38.0})
        for (int ulps = -4; ulps <= 4; ++ulps) {  // y a few ulps either side of the centre line
          double y = centre;
          for (int k = 0; k < std::abs(ulps); ++k) y = std::nextafter(y, ulps < 0 ? 0.0 : 100.0);
          for (int x = 1; x < 80; ++x) {
            const Vec3 p(x, y, z);
            const double fast = probe.distance(f, p), exact = reference(faces, f, p);
            EXPECT_EQ(std::memcmp(&fast, &exact, sizeof fast), 0)
                << "face " << f << " at (" << p.transpose() << "): " << fast << " against " << exact;
            onFace += exact == 0;
          }
        }
  EXPECT_GT(onFace, 2000);  // the points off the holes, on the top and bottom faces
}

// The same plate with every face a B-spline: on the lines through the holes' centres the surface's nearest point
// lies in a hole (outside the face) for many points, and the face's distance is BRepExtrema's from all its extrema.
TEST(CadFaces, PointsOverTheHolesOfBSplineFacesAreBRepExtremas) {
  const CadSolid plate = readPart(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/plate_holes.step");
  const CadSolid cad = prepareSolid(TopoDS::Solid(BRepBuilderAPI_NurbsConvert(plate.solid, true).Shape()));
  const CadFaces faces(cad);
  CadFaceProbe probe(faces);
  int overHoles = 0;
  for (int f = 0; f < faces.count(); ++f)
    for (double z : {0.0, 0.5, 2.0})
      for (double y : {12.0, 38.0})
        for (double x = 0.5; x < 80; x += 0.5) {
          const Vec3 p(x, y, z);
          const double exact = reference(faces, f, p);
          EXPECT_NEAR(probe.distance(f, p), exact, 1e-8) << "face " << f << " at (" << p.transpose() << ")";
          overHoles += (z == 0.0 || z == 2.0) && exact > 0.1 && exact < 10;
        }
  EXPECT_GT(overHoles, 20);
  EXPECT_GT(expectSameAsBRepExtrema(cad), 500);
}

TEST(CadFaces, DistancesAreBRepExtremasOnARealSheetMetalPart) {
  const std::string path = std::string(HEXLAYER_SHARED_PARTS) + "/analysissitus_sheet_metal_54_SHELLONLY.brep";
  EXPECT_GT(expectSameAsBRepExtrema(readPart(path)), 500);
}

// A periodic B-spline shell from Gmsh's benchmarks, whose edges and vertices have tolerances of about 4e-3 mm: the
// quick test's margin is 3 x the face's largest tolerance there (was 1000 x: every foot point within 4 mm of an edge
// or the seam went to the exact classifier, 7 of the 45 s of meshing it).
TEST(CadFaces, DistancesAreBRepExtremasOnFacesWithLargeTolerances) {
  const std::string path = std::string(HEXLAYER_SHARED_PARTS) + "/gmsh_periodic_u_cst_curved_shell.step";
  EXPECT_GT(expectSameAsBRepExtrema(readPart(path)), 300);
}

// On the axis of a cylinder face, beyond its end, the face's vertices are nearest, two of them as far
// up to rounding: BRepExtrema keeps the first vertex's distance if the other is nearer by less than
// 1e-7 (its vertex pairs are split over its thread pool's threads), and so does CadFaceProbe.
TEST(CadFaces, NearlyEquidistantVerticesAreBRepExtremas) {
  for (int k = 180; k < 200; ++k) {
    const gp_Ax2 axis(gp_Pnt(0.1 * k, 0.37, -0.2), gp_Dir(std::sin(0.1 + 0.013 * k), 0.3, std::cos(0.1 + 0.013 * k)));
    const CadSolid cad =
        prepareSolid(TopoDS::Solid(BRepPrimAPI_MakeCylinder(axis, 10 + 0.1 * k, 40, 0.9 + 0.01 * k).Shape()));
    const CadFaces faces(cad);
    CadFaceProbe probe(faces);
    const Vec3 p = vec(axis.Location().Translated(gp_Vec(axis.Direction()) * (43.0 + 0.01 * k)));
    for (int f = 0; f < faces.count(); ++f) {
      const double fast = probe.distance(f, p), exact = reference(faces, f, p);
      EXPECT_EQ(std::memcmp(&fast, &exact, sizeof fast), 0)
          << "k " << k << " face " << f << ": " << fast << " against " << exact;
    }
  }
}

// A face's exact box (BRepBndLib::AddOptimal: 20 ms on a torus) is measured once for the solids that share the face:
// CadFaces keeps the boxes it measures in FaceBoxes and takes those kept before, the same boxes to the last bit as
// measured anew; a copy of the solid (its faces new shapes) shares none. The Ender-3 box's rounded corners are tori.
TEST(CadFaces, ExactBoxesOfSharedFacesAreMeasuredOnce) {
  const CadSolid cad = readPart(std::string(HEXLAYER_SHARED_PARTS) + "/ender3_power_holder_box.step");
  FaceBoxes boxes;
  const CadFaces first(cad, &boxes), again(cad, &boxes), alone(cad);
  int tori = 0;
  for (int f = 0; f < alone.count(); ++f) {
    ASSERT_NE(boxes.find(alone.face(f).face), nullptr) << "face " << f;
    tori += BRepAdaptor_Surface(alone.face(f).face).GetType() == GeomAbs_Torus;
    std::array<double, 6> expected{}, kept{}, taken{};
    alone.face(f).exactBox.Get(expected[0], expected[1], expected[2], expected[3], expected[4], expected[5]);
    first.face(f).exactBox.Get(kept[0], kept[1], kept[2], kept[3], kept[4], kept[5]);
    again.face(f).exactBox.Get(taken[0], taken[1], taken[2], taken[3], taken[4], taken[5]);
    EXPECT_EQ(kept, expected) << "face " << f;
    EXPECT_EQ(taken, expected) << "face " << f;
  }
  EXPECT_GE(tori, 4);
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(cad.solid).Shape();
  for (TopExp_Explorer it(copy, TopAbs_FACE); it.More(); it.Next())
    EXPECT_EQ(boxes.find(TopoDS::Face(it.Current())), nullptr);
}

namespace {

// Checks every ring torus face's exact box against BRepBndLib::AddOptimal's, which it replaces: it holds that box
// (within 1e-9 of the solid's size) and is at most Precision::Confusion() larger (AddOptimal enlarges some sides by
// it, not all). [in] cad. Returns how many torus faces.
int expectTorusBoxesHoldAddOptimals(const CadSolid& cad) {
  const CadFaces faces(cad);
  int tori = 0;
  for (int f = 0; f < faces.count(); ++f) {
    if (BRepAdaptor_Surface(faces.face(f).face).GetType() != GeomAbs_Torus) continue;
    ++tori;
    Bnd_Box optimal;
    BRepBndLib::AddOptimal(faces.face(f).face, optimal, false, false);
    std::array<double, 6> expected{}, box{};
    optimal.Get(expected[0], expected[1], expected[2], expected[3], expected[4], expected[5]);
    faces.face(f).exactBox.Get(box[0], box[1], box[2], box[3], box[4], box[5]);
    for (int k = 0; k < 6; ++k) {
      const double outwards = k < 3 ? expected[k] - box[k] : box[k] - expected[k];
      EXPECT_GE(outwards, -1e-9 * cad.diagonal) << "face " << f << " bound " << k;
      EXPECT_LE(outwards, Precision::Confusion() + 1e-9 * cad.diagonal) << "face " << f << " bound " << k;
    }
  }
  return tori;
}

// A torus about a tilted axis off the origin, all lengths times `scale`: whole, or its ring angle and tube angles cut.
CadSolid torus(double scale, bool whole) {
  const gp_Ax2 axis(gp_Pnt(3 * scale, -2 * scale, 5 * scale), gp_Dir(1, 2, 3));
  BRepPrimAPI_MakeTorus make = whole ? BRepPrimAPI_MakeTorus(axis, 10 * scale, 2 * scale)
                                     : BRepPrimAPI_MakeTorus(axis, 10 * scale, 2 * scale, -0.4, 2.3, 2.5);
  return prepareSolid(TopoDS::Solid(make.Shape()));
}

}  // namespace

// A torus face's box comes from its extreme points, not BndLib's optimization (20 ms a face): it holds that box.
TEST(CadFaces, TorusFaceBoxesHoldAddOptimals) {
  for (double scale : {1e-3, 1.0, 1e3})
    for (bool whole : {true, false}) EXPECT_EQ(expectTorusBoxesHoldAddOptimals(torus(scale, whole)), 1) << scale;
  EXPECT_GE(
      expectTorusBoxesHoldAddOptimals(readPart(std::string(HEXLAYER_SHARED_PARTS) + "/ender3_power_holder_box.step")),
      17);
}
