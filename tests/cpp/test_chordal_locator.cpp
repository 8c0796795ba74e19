// Point location on the chordal surface (chordal/chordal_locator.hpp): the weights of a point on a facet (Eq. 4-7:
// barycentric on triangles, inverse bilinear on quads).
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "chordal/chordal_locator.hpp"

using namespace hexlayer;

namespace {

Vec3 bilinear(const std::array<Vec3, 4>& p, double u, double v) {
  return (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
}

}  // namespace

// Eq. 4-7: area (barycentric) weights of a point of a triangle.
TEST(ChordalLocator, TriangleWeightsAtVertexEdgeMidpointAndCentroid) {
  // A triangle tilted out of every coordinate plane.
  const Vec3 a(1, 0, 0.5), b(3, 1, 0), c(0, 2, 1.5);
  auto expectWeights = [&](const Vec3& p, const Eigen::Vector3d& w) {
    const Eigen::Vector3d got = triangleWeights(a, b, c, p);
    EXPECT_LT((got - w).norm(), 1e-12) << "at " << p.transpose() << ": got " << got.transpose();
  };
  expectWeights(a, {1, 0, 0});
  expectWeights(b, {0, 1, 0});
  expectWeights(c, {0, 0, 1});
  expectWeights(0.5 * (a + b), {0.5, 0.5, 0});  // Eq. 4-5 with u = 0.5
  expectWeights(0.5 * (b + c), {0, 0.5, 0.5});
  expectWeights(0.5 * (c + a), {0.5, 0, 0.5});
  expectWeights(0.25 * a + 0.75 * c, {0.25, 0, 0.75});
  expectWeights((a + b + c) / 3, {1.0 / 3, 1.0 / 3, 1.0 / 3});
  expectWeights(0.2 * a + 0.3 * b + 0.5 * c, {0.2, 0.3, 0.5});
  // Off the plane: the weights of the foot of the perpendicular.
  const Vec3 n = (b - a).cross(c - a).normalized();
  expectWeights((a + b + c) / 3 + 2.5 * n, {1.0 / 3, 1.0 / 3, 1.0 / 3});
  expectWeights(0.2 * a + 0.3 * b + 0.5 * c - 0.7 * n, {0.2, 0.3, 0.5});
}

TEST(ChordalLocator, TriangleWeightsClampPointsOutside) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  auto weights = [&](const Vec3& p) { return triangleWeights(a, b, c, p); };
  // Beyond a vertex along an edge, and behind a vertex: that vertex.
  EXPECT_LT((weights(a + 3 * (b - a)) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-12);
  EXPECT_LT((weights(Vec3(-1, -1, 0)) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  // Straight out of an edge: the foot on that edge.
  EXPECT_LT((weights(Vec3(1, -3, 0)) - Eigen::Vector3d(0.5, 0.5, 0)).norm(), 1e-12);
  EXPECT_LT((weights(Vec3(2, 2, 1)) - Eigen::Vector3d(0, 0.5, 0.5)).norm(), 1e-12);
  for (const Vec3& p : {Vec3(5, 7, 1), Vec3(-3, 0.5, 0), Vec3(1, 9, -2), Vec3(3, -1, 0)}) {
    const Eigen::Vector3d w = weights(p);
    EXPECT_NEAR(w.sum(), 1.0, 1e-12);
    EXPECT_GE(w.minCoeff(), 0.0) << "at " << p.transpose();
  }
}

// The header promises the weights of the point of the triangle *nearest* to p. Outside the
// triangle near a vertex but not along an edge's normal, the nearest point is that vertex.
TEST(ChordalLocator, TriangleWeightsGiveNearestPointOfTriangle) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  const Vec3 p(3, 1, 0);  // nearest point of the triangle: b (foot on line bc is beyond b)
  const Eigen::Vector3d w = triangleWeights(a, b, c, p);
  const Vec3 q = w[0] * a + w[1] * b + w[2] * c;
  EXPECT_LT((q - b).norm(), 1e-9) << "weights " << w.transpose() << " give " << q.transpose()
                                  << ", |p - q| = " << (p - q).norm() << " > |p - b| = " << (p - b).norm();
}

// Inverse bilinear map on a planar trapezoid (not a parallelogram) and a twisted quad.
TEST(ChordalLocator, InverseBilinearRecoversParameters) {
  const std::array<Vec3, 4> trapezoid = {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(3, 2, 0), Vec3(0.5, 1.5, 0)};
  const std::array<Vec3, 4> twisted = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.2, 1.1, 0.9), Vec3(-0.1, 1, 0)};
  const std::vector<Eigen::Vector2d> params = {{0.3, 0.7}, {0.9, 0.1}, {0.5, 0.5}, {0.05, 0.95}, {0.25, 0.8},
                                               {0, 0},     {1, 1},     {1, 0},     {0, 1},       {0.6, 0}};
  for (const auto* quad : {&trapezoid, &twisted})
    for (const Eigen::Vector2d& uv : params) {
      const Eigen::Vector2d got = inverseBilinear(*quad, bilinear(*quad, uv.x(), uv.y()));
      EXPECT_LT((got - uv).norm(), 1e-9) << (quad == &trapezoid ? "trapezoid" : "twisted")
                                         << " (u, v) = " << uv.transpose() << ", got " << got.transpose();
    }
  // Off a planar quad along its normal: the parameters of the foot point.
  for (const Eigen::Vector2d& uv : params) {
    const Eigen::Vector2d got = inverseBilinear(trapezoid, bilinear(trapezoid, uv.x(), uv.y()) + Vec3(0, 0, 0.8));
    EXPECT_LT((got - uv).norm(), 1e-9) << uv.transpose();
  }
}
