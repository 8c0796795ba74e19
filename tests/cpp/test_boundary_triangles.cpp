// The quick inside/outside test of the tet filter (triangles of the CAD's triangulation in a bounding
// volume hierarchy) and the point grid's queries the bubble packing relies on.
#include <gtest/gtest.h>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <random>
#include <vector>

#include "core/point_grid.hpp"
#include "core/triangle_tree.hpp"
#include "geometry/boundary_triangles.hpp"
#include "geometry/cad_solid.hpp"

using namespace hexlayer;

namespace {

// The 12 triangles of the box [0, 1]^3.
std::vector<Triangle> cubeTriangles() {
  std::vector<Triangle> t;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {0.0, 1.0}) {
      Vec3 c[4];
      for (int k = 0; k < 4; ++k) {
        c[k][axis] = side, c[k][(axis + 1) % 3] = k == 1 || k == 2, c[k][(axis + 2) % 3] = k >= 2;
      }
      t.push_back({c[0], c[1], c[2]}), t.push_back({c[0], c[2], c[3]});
    }
  return t;
}

// Every point of a grid over the solid's box (a little beyond it) that the triangles decide is
// decided as OpenCASCADE's classifier decides it; returns how many were decided.
int decidedAsOpenCascade(const CadSolid& cad, double lo, double hi, int steps) {
  const BoundaryTriangles triangles(cad);
  BRepClass3d_SolidClassifier exact(cad.solid);
  int decided = 0;
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; j <= steps; ++j)
      for (int k = 0; k <= steps; ++k) {
        const Vec3 p = Vec3::Constant(lo) + (hi - lo) / steps * Vec3(i, j, k) + Vec3(1e-3, 2e-3, 3e-3);
        const Containment quick = triangles.classify(p);
        if (quick == Containment::kUndecided) continue;
        ++decided;
        exact.Perform(gp_Pnt(p.x(), p.y(), p.z()), 1e-7 * cad.diagonal);
        EXPECT_EQ(quick == Containment::kInside, exact.State() == TopAbs_IN) << p.transpose();
      }
  return decided;
}

}  // namespace

TEST(TriangleTree, DistanceToATriangleFromItsFaceEdgesAndCorners) {
  const Triangle t = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(Vec3(0.5, 0.5, 3), t), 9);    // above the face
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(Vec3(1, -1, 0), t), 1);       // beside an edge
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(Vec3(2, 2, 0), t), 2);        // beside the long edge
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(Vec3(-1, -1, 0), t), 2);      // beyond a corner
  const Triangle segment = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};  // no area
  EXPECT_DOUBLE_EQ(squaredDistanceToTriangle(Vec3(1.5, 1, 0), segment), 1);
}

TEST(TriangleTree, RayCrossingsTellInsideFromOutsideAndEdgeHitsAreUnsure) {
  const TriangleTree tree(cubeTriangles());
  const Vec3 tilted = Vec3(1, 0.0917, 0.0533).normalized();
  EXPECT_EQ(tree.crossings(Vec3(0.3, 0.4, 0.6), tilted), 1);
  EXPECT_EQ(tree.crossings(Vec3(-1, 0.4, 0.6), tilted), 2);
  EXPECT_EQ(tree.crossings(Vec3(2, 0.4, 0.6), tilted), 0);
  // Through the diagonal shared by two triangles of the face x = 1: a crossing that could count twice.
  EXPECT_FALSE(tree.crossings(Vec3(0.5, 0.5, 0.5), Vec3(1, 1e-3, 1e-3).normalized()).has_value());
  EXPECT_TRUE(tree.anyWithin(Vec3(0.5, 0.5, 0.95), 0.06));
  EXPECT_FALSE(tree.anyWithin(Vec3(0.5, 0.5, 0.5), 0.49));
  EXPECT_TRUE(tree.anyWithin(Vec3(1.5, 0.5, 0.5), 0.51));
}

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

TEST(PointGrid, QueriesFindExactlyThePointsWithinTheRadiusInCellOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> along(-5, 5), across(0, 0.5);
  PointGrid grid(1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 400; ++i)
    points.push_back(Vec3(along(random), along(random), across(random))), grid.insert(i, points.back());
  for (int q = 0; q < 50; ++q) {
    const Vec3 p(along(random), along(random), along(random));
    std::vector<int> found, expected;
    grid.forEachNear(p, 1.7, [&](int id, const Vec3&) { found.push_back(id); });
    for (int i = 0; i < 400; ++i)
      if ((points[i] - p).squaredNorm() <= 1.7 * 1.7) expected.push_back(i);
    std::vector<int> sorted = found;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, expected);
    EXPECT_EQ(grid.anyNear(p, 1.7, [](int, const Vec3&) { return true; }), !expected.empty());
    int first = -1;
    grid.anyNear(p, 1.7, [&](int id, const Vec3&) { return first = id, true; });
    EXPECT_EQ(first, found.empty() ? -1 : found.front()) << "stops at the first point forEachNear visits";
  }
}
