// The CAD solid as the pipeline reads it (geometry/cad_solid.hpp): its volume, the mesh's reference, exact also
// on B-spline faces (OpenCASCADE's default rule is 1 % off there), run at scales 1, 1e-3 and 1e3; a file that
// holds only a closed shell, read as the solid it bounds; and the vertices' parameters on a face, BRep_Tool's to the
// last bit on a plate with many holes (analytic and B-spline faces, x1, 1e-3, 1e3); the faces' triangulation, each
// face covered once (Delabella's on a face of more than kManyEdges edges, Watson's on the rest); the cylinder a
// B-spline face lies on.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "geometry/cad_solid.hpp"
#include "test_parts.hpp"

using namespace hexlayer;

namespace {

// The upper half of a spherical shell of radii 10 s and 12 s.
TopoDS_Solid hemisphereShell(double s) {
  const TopoDS_Shape outer = BRepPrimAPI_MakeSphere(12 * s, 0, M_PI / 2).Shape();
  const TopoDS_Shape inner = BRepPrimAPI_MakeSphere(10 * s, 0, M_PI / 2).Shape();
  TopExp_Explorer solid(BRepAlgoAPI_Cut(outer, inner).Shape(), TopAbs_SOLID);
  return TopoDS::Solid(solid.Current());
}

// A 60 x 40 x 2 plate with a 6 x 4 grid of holes of radius 2, scaled by s.
TopoDS_Shape plateWithHoles(double s) {
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(60, 40, 2).Shape();
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 4; ++k)
      plate = BRepAlgoAPI_Cut(
                  plate, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5 + 10 * i, 5 + 10 * k, -1), gp::DZ()), 2, 4).Shape())
                  .Shape();
  gp_Trsf scale;
  scale.SetScale(gp::Origin(), s);
  return BRepBuilderAPI_Transform(plate, scale, true).Shape();
}

// The triangles of a face's triangulation, placed, with their normals (length: twice their area).
std::vector<gp_Vec> triangleNormals(const TopoDS_Face& face) {
  TopLoc_Location place;
  const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, place);
  std::vector<gp_Vec> normals;
  if (mesh.IsNull()) return normals;
  for (int t = 1; t <= mesh->NbTriangles(); ++t) {
    int a, b, c;
    mesh->Triangle(t).Get(a, b, c);
    const gp_Pnt pa = mesh->Node(a).Transformed(place), pb = mesh->Node(b).Transformed(place),
                 pc = mesh->Node(c).Transformed(place);
    normals.push_back(gp_Vec(pa, pb).Crossed(gp_Vec(pa, pc)));
  }
  return normals;
}

}  // namespace

// A plate with 120 holes (test_parts, 12 x 10): its top and bottom have 124 edges (Delabella's), its sides and the
// holes' walls a few (Watson's). Every face gets triangles that cover it once: their area is the face's but for the
// holes' polygons (within 1 %), and on the flat faces they all turn the same way (no triangle folded over another).
TEST(CadSolid, TriangulationCoversEveryFaceOnce) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = test_parts::plateWithManyHoles(s, 12, 10);
    int manyEdged = 0;
    for (int f = 1; f <= cad.faces.Extent(); ++f) {
      const TopoDS_Face face = TopoDS::Face(cad.faces(f));
      TopTools_IndexedMapOfShape edges;
      TopExp::MapShapes(face, TopAbs_EDGE, edges);
      manyEdged += edges.Extent() > kManyEdges;
      const std::vector<gp_Vec> normals = triangleNormals(face);
      ASSERT_FALSE(normals.empty()) << "face " << f << " has no triangles";
      GProp_GProps props;
      BRepGProp::SurfaceProperties(face, props);
      double area = 0;
      gp_Vec sum(0, 0, 0);
      for (const gp_Vec& n : normals) area += n.Magnitude() / 2, sum += n / 2;
      EXPECT_NEAR(area / props.Mass(), 1, 0.01) << "face " << f;
      if (BRepAdaptor_Surface(face).GetType() == GeomAbs_Plane) EXPECT_NEAR(sum.Magnitude() / area, 1, 1e-9);
    }
    EXPECT_EQ(manyEdged, 2);
  }
}

// vertexParameters walks a face's edges once; BRep_Tool::Parameters walks them for every vertex: the same answers.
TEST(CadSolid, VertexParametersAreBRepToolsOnEveryFace) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      const TopoDS_Shape plate = plateWithHoles(s);
      const TopoDS_Shape part = bspline ? BRepBuilderAPI_NurbsConvert(plate, true).Shape() : plate;
      std::size_t vertices = 0;
      for (TopExp_Explorer f(part, TopAbs_FACE); f.More(); f.Next()) {
        const TopoDS_Face& face = TopoDS::Face(f.Current());
        const std::vector<gp_Pnt2d> uvs = vertexParameters(face);
        std::size_t i = 0;
        for (TopExp_Explorer v(face, TopAbs_VERTEX); v.More(); v.Next(), ++i) {
          ASSERT_LT(i, uvs.size());
          const gp_Pnt2d expected = BRep_Tool::Parameters(TopoDS::Vertex(v.Current()), face);
          EXPECT_EQ(uvs[i].X(), expected.X());
          EXPECT_EQ(uvs[i].Y(), expected.Y());
        }
        EXPECT_EQ(i, uvs.size());
        vertices += i;
      }
      EXPECT_GT(vertices, 24u * 2 * 2 * 2);  // each hole's two circles, each with a vertex on the top or bottom face
    }
}

// A part drawn in metres is met at the size of the same part in millimetres (x 1000), one in microns at 1e-3:
// a power of 1000 brings the diagonal into [10, 10 000), and a part inside is left as it is.
TEST(CadSolid, NormalizingUnitIsThePowerOfAThousandIntoRange) {
  auto unitOf = [](double diagonal) {  // a cube with that diagonal
    const double side = diagonal / std::sqrt(3.0);
    return normalizingUnit(TopoDS::Solid(BRepPrimAPI_MakeBox(side, side, side).Shape()));
  };
  for (const auto& [diagonal, unit] : std::vector<std::pair<double, double>>{{0.011, 1e3},
                                                                             {0.11, 1e3},
                                                                             {9.5, 1e3},
                                                                             {10.5, 1},
                                                                             {100, 1},
                                                                             {9000, 1},
                                                                             {0.5, 1e3},
                                                                             {5e-4, 1e6},
                                                                             {2e4, 1e-3},
                                                                             {5e6, 1e-3},
                                                                             {2e7, 1e-6},
                                                                             {9.0, 1e3}}) {
    SCOPED_TRACE("diagonal " + std::to_string(diagonal));
    EXPECT_EQ(unitOf(diagonal), unit);
    EXPECT_GE(diagonal * unit * (1 + 1e-6), 10.0);
    EXPECT_LT(diagonal * unit, 10000.0 * (1 + 1e-6));
  }
}

TEST(CadSolid, VolumeIsExactOnAnalyticAndBSplineFaces) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      const TopoDS_Solid shell = hemisphereShell(s);
      const CadSolid cad =
          prepareSolid(bspline ? TopoDS::Solid(BRepBuilderAPI_NurbsConvert(shell, true).Shape()) : shell);
      const double exact = 2.0 / 3 * M_PI * (12 * 12 * 12 - 10 * 10 * 10) * s * s * s;
      EXPECT_NEAR(cad.volume / exact, 1, 1e-6);
    }
}

// A solid of planes only turned 30 degrees about a skew axis (every edge oblique to its planes' axes, where the
// Gauss-Kronrod rule took 100 s on a box with a lip): its exact volume and centre of mass, at x1, 1e-3 and 1e3, its
// planes as planes and as B-splines. An L-shaped block (40 x 20 x 10 with a 20 x 20 x 10 step on one half) with a 6 x 4
// hole through it.
TEST(CadSolid, VolumeIsExactOnASolidOfPlanesTurnedObliquely) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(40, 20, 20)).Shape();
      block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeBox(gp_Pnt(20, -1, 10), gp_Pnt(41, 21, 21)).Shape()).Shape();
      block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeBox(gp_Pnt(5, 8, -1), gp_Pnt(11, 12, 21)).Shape()).Shape();
      gp_Trsf turn, scale;
      turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 30 * M_PI / 180);
      scale.SetScale(gp_Pnt(0, 0, 0), s);
      TopoDS_Shape placed = BRepBuilderAPI_Transform(block, scale * turn, true).Shape();
      if (bspline) placed = BRepBuilderAPI_NurbsConvert(placed, true).Shape();
      TopExp_Explorer solid(placed, TopAbs_SOLID);
      ASSERT_TRUE(solid.More());
      const double exact = (40 * 20 * 10 + 20 * 20 * 10 - 6 * 4 * 20) * s * s * s;
      const auto [volume, centre] = volumeOf(solid.Current());
      EXPECT_NEAR(volume / exact, 1, 1e-9);
      // the centre: the pieces' centres weighted by their volumes, turned and scaled as the block
      const gp_XYZ c = (gp_XYZ(20, 10, 5) * 8000 + gp_XYZ(10, 10, 15) * 4000 - gp_XYZ(8, 10, 10) * 480) / (12000 - 480);
      const gp_Pnt expected = gp_Pnt(c).Transformed(scale * turn);
      EXPECT_NEAR((Vec3(expected.X(), expected.Y(), expected.Z()) - centre).norm(), 0, 1e-9 * s * 50);
    }
}

// A file holding only the closed shell of a part (as sheet-metal exports often do) gives its solid.
TEST(CadSolid, ClosedShellFileIsReadAsTheSolidItBounds) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 2).Solid();
  TopExp_Explorer shell(box, TopAbs_SHELL);
  ASSERT_TRUE(shell.More());
  const std::string path = ::testing::TempDir() + "hexlayer_shell_only.brep";
  ASSERT_TRUE(BRepTools::Write(shell.Current(), path.c_str()));
  const std::vector<TopoDS_Solid> solids = readSolids(path);
  std::remove(path.c_str());
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(prepareSolid(solids[0]).volume, 2400.0, 1e-6);
}

// The cylinder of a face: a cylinder's own; a boss's side converted to a B-spline trimmed to part of a turn (as
// OpenCASCADE's NURBS conversion and scaling write it) gives back its axis and radius, at scales 1, 1e-3 and 1e3; a
// plane, a sphere and a cone converted alike give none.
TEST(CadSolid, CylinderOfABSplineFaceIsTheCylinderItLiesOn) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const gp_Ax2 axis(gp_Pnt(3 * s, -2 * s, s), gp_Dir(1, 2, 2));
    const double r = 4 * s, tolerance = 1e-7 * s;
    const TopoDS_Shape boss = BRepPrimAPI_MakeCylinder(axis, r, 10 * s, 5.5).Shape();  // 5.5 of 2 pi rad
    int cylinders = 0;
    for (const bool nurbs : {false, true}) {
      const TopoDS_Shape shape = nurbs ? BRepBuilderAPI_NurbsConvert(boss, true).Shape() : boss;
      for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
        const std::optional<gp_Cylinder> c = cylinderOf(f.Current(), tolerance);
        if (planeOf(f.Current(), tolerance)) {
          EXPECT_FALSE(c) << "a plane";
          continue;
        }
        EXPECT_EQ(BRepAdaptor_Surface(TopoDS::Face(f.Current())).GetType(),
                  nurbs ? GeomAbs_BSplineSurface : GeomAbs_Cylinder);
        ASSERT_TRUE(c);
        ++cylinders;
        EXPECT_NEAR(c->Radius() / r, 1, 1e-9);
        EXPECT_TRUE(c->Axis().Direction().IsParallel(axis.Direction(), 1e-9));
        EXPECT_LT(gp_Lin(c->Axis()).Distance(axis.Location()), tolerance);
      }
    }
    EXPECT_EQ(cylinders, 2);
    for (const TopoDS_Shape& other :
         {BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), r).Shape(), BRepPrimAPI_MakeCone(axis, r, 0.5 * r, 10 * s).Shape()})
      for (TopExp_Explorer f(BRepBuilderAPI_NurbsConvert(other, true).Shape(), TopAbs_FACE); f.More(); f.Next())
        EXPECT_FALSE(cylinderOf(f.Current(), tolerance)) << "a sphere, a cone or their flat ends";
  }
}
