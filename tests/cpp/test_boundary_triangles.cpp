// The quick inside/outside test of the tet filter (geometry/boundary_triangles.hpp: triangles of the CAD's
// triangulation in a bounding volume hierarchy), against OpenCASCADE's classifier.
#include <gtest/gtest.h>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <Bnd_Box.hxx>
#include <TopoDS.hxx>

#include <string>
#include <vector>

#include "geometry/boundary_triangles.hpp"
#include "geometry/cad_solid.hpp"

using namespace hexlayer;

namespace {

// Every point of a grid over the solid's box (a little beyond it) that the triangles decide is
// decided as OpenCASCADE's classifier decides it; returns how many were decided.
int decidedAsOpenCascade(const CadSolid& cad, const Vec3& lo, const Vec3& hi, int steps) {
  const BoundaryTriangles triangles(cad);
  BRepClass3d_SolidClassifier exact(cad.solid);
  int decided = 0;
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; j <= steps; ++j)
      for (int k = 0; k <= steps; ++k) {
        const Vec3 p = lo + (hi - lo).cwiseProduct(Vec3(i, j, k)) / steps + Vec3(1e-3, 2e-3, 3e-3);
        const Containment quick = triangles.classify(p);
        if (quick == Containment::kUndecided) continue;
        ++decided;
        exact.Perform(gp_Pnt(p.x(), p.y(), p.z()), 1e-7 * cad.diagonal);
        EXPECT_EQ(quick == Containment::kInside, exact.State() == TopAbs_IN) << p.transpose();
      }
  return decided;
}

int decidedAsOpenCascade(const CadSolid& cad, double lo, double hi, int steps) {
  return decidedAsOpenCascade(cad, Vec3::Constant(lo), Vec3::Constant(hi), steps);
}

}  // namespace

TEST(BoundaryTriangles, ABoxIsDecidedEverywhereButNextToItsFaces) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 10, 10, 2).Solid());
  const BoundaryTriangles triangles(cad);
  EXPECT_LT(triangles.margin(), 1e-4) << "plane faces: the triangles are the faces";
  EXPECT_EQ(triangles.classify(Vec3(5, 5, 1)), Containment::kInside);
  EXPECT_EQ(triangles.classify(Vec3(5, 5, 2.5)), Containment::kOutside);
  EXPECT_EQ(triangles.classify(Vec3(-3, 12, 1)), Containment::kOutside);
  EXPECT_EQ(triangles.classify(Vec3(5, 5, 2)), Containment::kUndecided);
  EXPECT_TRUE(triangles.fartherThan(Vec3(5, 5, 1), 0.9));
  EXPECT_FALSE(triangles.fartherThan(Vec3(5, 5, 1), 1.1));
  EXPECT_GT(decidedAsOpenCascade(cad, -1, 11, 12), 2000);
}

TEST(BoundaryTriangles, CurvedAndFreeformSolidsAreDecidedAsOpenCascadeDecides) {
  // A sphere: its poles, where the surface's parameters interpolate badly, do not blow up the margin.
  const CadSolid ball = prepareSolid(BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 10).Solid());
  EXPECT_LT(BoundaryTriangles(ball).margin(), 0.5);
  EXPECT_GT(decidedAsOpenCascade(ball, -12, 12, 12), 1800);
  // The box as B-spline faces: triangulated again, finer, for the test.
  const TopoDS_Shape nurbs =
      BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 10, 10, 2).Solid()).Shape();
  const CadSolid freeform = prepareSolid(TopoDS::Solid(nurbs));
  EXPECT_LT(BoundaryTriangles(freeform).margin(), 1e-2);
  EXPECT_GT(decidedAsOpenCascade(freeform, -1, 11, 12), 2000);
}

// Gmsh's periodic curved shell (a B-spline face whose parameters run unevenly over the triangles): measured at
// the same parameters, its triangles lay 0.19 off the surface, a margin of 0.39 on a wall 1.0 thick, and most tet
// centres went to OpenCASCADE's classifier (78 of the mesher's 136 s); measured to the nearest surface point where
// the parameters say more than twice the deflection, 0.03 (at a deflection of 1e-4 of the diagonal: a margin of 0.06;
// at 2e-4, three times faster to triangulate, 0.12, and the tet filter takes as long: the tets' centres lie about
// half a wall from its faces).
TEST(BoundaryTriangles, AFreeformShellsMarginIsItsTrianglesDistance) {
  const CadSolid shell =
      prepareSolid(readSolids(std::string(HEXLAYER_SHARED_PARTS) + "/gmsh_periodic_u_cst_curved_shell.step").at(0));
  const BoundaryTriangles triangles(shell);
  EXPECT_LT(triangles.margin(), 0.15) << "well inside the wall (1.0 thick)";
  Bnd_Box box;
  BRepBndLib::Add(shell.solid, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  EXPECT_GT(decidedAsOpenCascade(shell, Vec3(x0, y0, z0), Vec3(x1, y1, z1), 12), 1800);
}
