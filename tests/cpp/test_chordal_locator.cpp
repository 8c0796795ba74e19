// Point location on the chordal surface (chordal/chordal_locator.hpp): the weights of a point on a facet (Eq. 4-7:
// barycentric on triangles, inverse bilinear on quads), and the nearest facet, point, normal and radius of points
// around a small folded surface.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "chordal/chordal_locator.hpp"

using namespace hexlayer;

namespace {

Vec3 bilinear(const std::array<Vec3, 4>& p, double u, double v) {
  return (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
}

// A tiny chordal surface folded along x = 2: the quad facet 0 (vertices 0 1 2 3) on z = 0 over [0, 2] x [0, 1],
// and the triangle facet 1 (vertices 1 4 2) rising from its edge x = 2 to vertex 4 at (3, 0, 1), in the plane
// x - z = 2. Vertex normals: +z on the flat side, the triangle's normal at 4, between the two on the fold;
// radii 1 to 5.
ChordalSurface foldedSurface() {
  ChordalSurface s;
  s.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0), Vec3(3, 0, 1)};
  const Vec3 up = Vec3::UnitZ(), tilted = Vec3(-1, 0, 1).normalized(), fold = (up + tilted).normalized();
  s.normals = {up, fold, fold, up, tilted};
  s.radius = {1, 2, 3, 4, 5};
  s.tetEdge.assign(s.vertices.size(), {0, 0});
  s.facets = {{0, 1, 2, 3}, {1, 4, 2, -1}};
  s.quads = 1, s.triangles = 1;
  return s;
}

// The radius function at a located point: the facet corners' radii by the point's weights (Eq. 4-7).
double radiusAt(const ChordalSurface& s, const ChordalPoint& at) {
  double r = 0;
  for (int k = 0; k < 4; ++k)
    if (s.facets[at.facet][k] >= 0) r += at.weights[k] * s.radius[s.facets[at.facet][k]];
  return r;
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

// Points above the quad, off the triangle along its normal and beyond the surface's edge: each is located on
// the facet nearest to it, at its foot there, with the weights, normal and radius of that foot.
TEST(ChordalLocator, LocatesPointsOnTheNearestFacetOfAFoldedSurface) {
  const ChordalSurface s = foldedSurface();
  const ChordalLocator locator(s);
  const Vec3 up = Vec3::UnitZ(), tilted = Vec3(-1, 0, 1).normalized(), fold = (up + tilted).normalized();

  // 0.7 above (0.5, 0.25) of the quad: u = 0.25 along 0-1, v = 0.25 along 0-3.
  const ChordalPoint onQuad = locator.locate(Vec3(0.5, 0.25, 0.7));
  ASSERT_EQ(onQuad.facet, 0);
  const std::array<double, 4> w{0.75 * 0.75, 0.25 * 0.75, 0.25 * 0.25, 0.75 * 0.25};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(onQuad.weights[k], w[k], 1e-12) << "corner " << k;
  EXPECT_LT((onQuad.point - Vec3(0.5, 0.25, 0)).norm(), 1e-12);
  EXPECT_LT((normalAt(s, onQuad) - ((w[0] + w[3]) * up + (w[1] + w[2]) * fold)).norm(), 1e-12);
  EXPECT_LT(normalAt(s, onQuad).norm(), 1) << "the normals differ: their mean is shorter";
  EXPECT_NEAR(radiusAt(s, onQuad), w[0] * 1 + w[1] * 2 + w[2] * 3 + w[3] * 4, 1e-12);

  // 0.4 off the triangle's point 0.2 v1 + 0.5 v4 + 0.3 v2 = (2.5, 0.3, 0.5), along its normal: 0.81 from the quad.
  const Vec3 foot(2.5, 0.3, 0.5);
  const ChordalPoint onTriangle = locator.locate(foot + 0.4 * tilted);
  ASSERT_EQ(onTriangle.facet, 1);
  const std::array<double, 4> barycentric{0.2, 0.5, 0.3, 0};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(onTriangle.weights[k], barycentric[k], 1e-12) << "corner " << k;
  EXPECT_LT((onTriangle.point - foot).norm(), 1e-12);
  EXPECT_LT((normalAt(s, onTriangle) - (0.5 * fold + 0.5 * tilted)).norm(), 1e-12);
  EXPECT_NEAR(radiusAt(s, onTriangle), 0.2 * 2 + 0.5 * 5 + 0.3 * 3, 1e-12);

  // Beyond the quad's edge x = 0: the middle of that edge, halfway between vertices 0 and 3.
  const ChordalPoint beyond = locator.locate(Vec3(-1, 0.5, 0.3));
  ASSERT_EQ(beyond.facet, 0);
  EXPECT_LT((beyond.point - Vec3(0, 0.5, 0)).norm(), 1e-12);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(beyond.weights[k], k == 0 || k == 3 ? 0.5 : 0, 1e-12) << "corner " << k;
  EXPECT_LT((normalAt(s, beyond) - up).norm(), 1e-12);
  EXPECT_NEAR(radiusAt(s, beyond), 2.5, 1e-12);
}

// With a hint (the facet of a point asked before) the located point is the same to the last bit, whether the
// hint is the answer, a neighbour, a facet across the surface or not a facet: on a wavy 20 x 20 grid of quads and
// triangles, for points above, below and beside it.
TEST(ChordalLocator, AHintFindsTheSamePoint) {
  ChordalSurface s;
  const int n = 20;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) s.vertices.emplace_back(i, j, 0.8 * std::sin(0.5 * i) * std::cos(0.3 * j));
  auto at = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if ((i + j) % 3 == 0) {
        s.facets.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), -1});
        s.facets.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1), -1});
      } else {
        s.facets.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  const ChordalLocator locator(s);
  const int facets = static_cast<int>(s.facets.size());
  int compared = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 p(-2 + 24 * std::fmod(0.618 * k, 1.0), -2 + 24 * std::fmod(0.382 * k + 0.1, 1.0), 2 * std::sin(k));
    const ChordalPoint plain = locator.locate(p);
    ASSERT_GE(plain.facet, 0);
    for (int hint : {plain.facet, std::max(plain.facet - 1, 0), (plain.facet + facets / 2) % facets, -1, facets + 5}) {
      const ChordalPoint hinted = locator.locate(p, hint);
      EXPECT_EQ(hinted.facet, plain.facet) << p.transpose() << " hint " << hint;
      EXPECT_EQ(hinted.point, plain.point) << p.transpose() << " hint " << hint;
      EXPECT_EQ(hinted.weights, plain.weights);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 2000);
}
