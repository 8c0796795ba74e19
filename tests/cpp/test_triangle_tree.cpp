// The triangles' bounding volume hierarchy (core/triangle_tree.hpp): the distance to a triangle, and ray crossings
// and nearness on the 12 triangles of a cube.
#include <gtest/gtest.h>

#include <vector>

#include "core/triangle_tree.hpp"

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
