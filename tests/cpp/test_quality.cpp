// Quality measures (quality/quality.hpp, paper §8) of hexes and hex meshes, and the boundary / conformity checks
// of a hex mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "quality/quality.hpp"
#include "test_hex_blocks.hpp"

using namespace hexlayer;
using hexlayer::test_hex_blocks::block;
using hexlayer::test_hex_blocks::box;
using hexlayer::test_hex_blocks::Hex;
using hexlayer::test_hex_blocks::singleHex;

namespace {

// Hex spanned by edge vectors a, b, c from the origin.
Hex parallelepiped(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 o = Vec3::Zero();
  return {o, a, a + b, b, c, a + c, a + b + c, b + c};
}

Vec3 centroid(const HexMesh& m, const std::array<int, 4>& face) {
  Vec3 c = Vec3::Zero();
  for (int n : face) c += m.nodes[n] / 4.0;
  return c;
}

}  // namespace

TEST(Quality, HexUnitCubeIsPerfect) {
  const Hex x = box(1, 1, 1);
  EXPECT_DOUBLE_EQ(hexScaledJacobian(x), 1.0);
  EXPECT_NEAR(hexVolume(x), 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(hexAspectRatio(x), 1.0);
}

TEST(Quality, HexFlatBoxHasAspectRatioOfSizeOverThickness) {
  const Hex x = box(4, 4, 1);
  EXPECT_DOUBLE_EQ(hexAspectRatio(x), 4.0);
  EXPECT_DOUBLE_EQ(hexScaledJacobian(x), 1.0);
  EXPECT_NEAR(hexVolume(x), 16.0, 1e-13);
}

TEST(Quality, HexShearedHexScaledJacobianIsCosineOfShearAngle) {
  const double angle = M_PI / 6;  // 30 degrees: the sweep edges lean by tan(30°) in x
  const Hex x = parallelepiped(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(std::tan(angle), 0, 1));
  EXPECT_NEAR(hexScaledJacobian(x), std::cos(angle), 1e-14);
  EXPECT_NEAR(hexScaledJacobian(x), 0.8660254, 1e-7);
  EXPECT_NEAR(hexVolume(x), 1.0, 1e-14);  // shear keeps the volume
}

TEST(Quality, HexParallelepipedVolumeIsTripleProduct) {
  const Vec3 a(2, 0, 0), b(1, 3, 0), c(0.5, -0.5, 4);
  EXPECT_NEAR(hexVolume(parallelepiped(a, b, c)), a.dot(b.cross(c)), 1e-12);
  EXPECT_NEAR(hexVolume(parallelepiped(a, b, c)), 24.0, 1e-12);
}

TEST(Quality, HexFrustumVolumeIsExact) {
  // Square 2x2 at z=0 under a centred 1x1 square at z=1: V = h/3 (A1 + A2 + sqrt(A1 A2)) = 7/3.
  Hex x = box(2, 2, 1);
  for (int i = 4; i < 8; ++i) x[i] = Vec3(0.5 + 0.5 * x[i].x(), 0.5 + 0.5 * x[i].y(), 1);
  EXPECT_NEAR(hexVolume(x), 7.0 / 3.0, 1e-14);
}

TEST(Quality, HexNonPlanarTrilinearHexVolumeMatchesSimpsonRule) {
  Hex x = box(1, 1, 1);
  x[6] += Vec3(0.3, 0.2, 0.4);  // warps three faces
  x[0] += Vec3(-0.1, 0.05, -0.2);
  auto X = [&](double s, double t, double r) {  // trilinear map of [0,1]^3
    return ((1 - s) * (1 - t) * (1 - r)) * x[0] + (s * (1 - t) * (1 - r)) * x[1] + (s * t * (1 - r)) * x[2] +
           ((1 - s) * t * (1 - r)) * x[3] + ((1 - s) * (1 - t) * r) * x[4] + (s * (1 - t) * r) * x[5] +
           (s * t * r) * x[6] + ((1 - s) * t * r) * x[7];
  };
  // det J has degree <= 2 in each coordinate, so 3-point Simpson per direction is exact; X is linear in
  // each coordinate, so central differences give exact derivatives.
  const double pts[3] = {0, 0.5, 1}, w[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6}, h = 0.25;
  double ref = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) {
        const double u = pts[a], v = pts[b], r = pts[c];
        Eigen::Matrix3d J;
        J.col(0) = (X(u + h, v, r) - X(u - h, v, r)) / (2 * h);
        J.col(1) = (X(u, v + h, r) - X(u, v - h, r)) / (2 * h);
        J.col(2) = (X(u, v, r + h) - X(u, v, r - h)) / (2 * h);
        ref += w[a] * w[b] * w[c] * J.determinant();
      }
  EXPECT_NEAR(hexVolume(x), ref, 1e-13);
  EXPECT_GT(std::abs(ref - 1.0), 0.05);  // really differs from the cube
}

TEST(Quality, HexInvertedHexHasNegativeScaledJacobian) {
  const Hex up = box(1, 1, 1);
  Hex mirrored;  // top and bottom swapped: left-handed
  for (int i = 0; i < 4; ++i) {
    mirrored[i] = up[i + 4];
    mirrored[i + 4] = up[i];
  }
  EXPECT_DOUBLE_EQ(hexScaledJacobian(mirrored), -1.0);
  EXPECT_NEAR(hexVolume(mirrored), -1.0, 1e-14);

  Hex folded = up;  // one corner pushed through the opposite face
  folded[6] = Vec3(0.2, 0.2, -0.5);
  EXPECT_LT(hexScaledJacobian(folded), 0.0);
}

TEST(Quality, HexDegenerateEdgeIsFlaggedMinusOne) {
  Hex x = box(1, 1, 1);
  x[1] = x[0];
  EXPECT_EQ(hexScaledJacobian(x), -1.0);
}

TEST(Quality, ReportBlockOfPerfectHexes) {
  const HexMesh m = block({0, 1, 2, 3}, {0, 1, 2}, {0, 0.5, 1});
  const QualityReport q = measureQuality(m);
  ASSERT_EQ(q.scaledJacobian.size(), 12u);
  EXPECT_DOUBLE_EQ(q.sjMin, 1.0);
  EXPECT_DOUBLE_EQ(q.sjAvg, 1.0);
  EXPECT_DOUBLE_EQ(q.arMin, 2.0);
  EXPECT_DOUBLE_EQ(q.arMax, 2.0);
  EXPECT_NEAR(q.volume, 6.0, 1e-12);
  EXPECT_EQ(q.sjHistogram.counts.size(), 10u);
  EXPECT_EQ(q.sjHistogram.counts[9], 12);
  EXPECT_EQ(q.sjHistogram.lo, 0.0);
  EXPECT_EQ(q.sjHistogram.hi, 1.0);
}

TEST(Quality, ReportCountsInvertedHexesAndLocatesTheWorst) {
  HexMesh m = block({0, 1, 2, 3}, {0, 1}, {0, 1});
  EXPECT_EQ(measureQuality(m).inverted, 0u);
  // Swap top and bottom of the middle hex: it turns left-handed, the others stay perfect.
  auto& h = m.hexes[1];
  for (int i = 0; i < 4; ++i) std::swap(h[i], h[i + 4]);
  const QualityReport q = measureQuality(m);
  EXPECT_EQ(q.inverted, 1u);
  EXPECT_DOUBLE_EQ(q.sjMin, -1.0);
  EXPECT_LT((q.worstAt - Vec3(1.5, 0.5, 0.5)).norm(), 1e-12);
}

TEST(Quality, ReportHistogramSumsToHexCountAndMatchesPerHexValues) {
  HexMesh m = block({0, 1, 2, 3, 4}, {0, 1, 2, 3}, {0, 1, 2});
  m.nodes[27] += Vec3(0.4, -0.3, 0.2);  // distort the hexes around interior node (2,1,1)
  m.nodes[31] += Vec3(-0.9, 0.9, 1.5);  // fold those around interior node (1,2,1)
  const QualityReport q = measureQuality(m);
  EXPECT_EQ(std::accumulate(q.sjHistogram.counts.begin(), q.sjHistogram.counts.end(), 0),
            static_cast<int>(m.hexes.size()));
  EXPECT_DOUBLE_EQ(q.sjMin, *std::min_element(q.scaledJacobian.begin(), q.scaledJacobian.end()));
  EXPECT_LT(q.sjMin, 0.0);
  EXPECT_GE(q.sjHistogram.counts[0], 1);  // negative values land in bin 0
  for (std::size_t h = 0; h < m.hexes.size(); ++h) EXPECT_EQ(q.scaledJacobian[h], hexScaledJacobian(hexCorners(m, h)));
  EXPECT_NEAR(q.volume, 24.0, 1e-12);  // interior moves keep the total volume
  const QualityReport again = measureQuality(m);
  EXPECT_EQ(again.scaledJacobian, q.scaledJacobian);
  EXPECT_EQ(again.sjAvg, q.sjAvg);
  EXPECT_EQ(again.volume, q.volume);
}

TEST(Quality, ReportEmptyMeshIsAllZero) {
  const QualityReport q = measureQuality(HexMesh{});
  EXPECT_EQ(q.sjMin, 0.0);
  EXPECT_EQ(q.volume, 0.0);
  EXPECT_EQ(q.sjHistogram.counts, std::vector<int>(10, 0));
  EXPECT_TRUE(q.scaledJacobian.empty());
}

TEST(Quality, HexCornersReturnsNodesInHexOrder) {
  const HexMesh m = block({0, 1, 2}, {0, 1}, {0, 1});
  const Hex x = hexCorners(m, 1);
  EXPECT_EQ(x[0], Vec3(1, 0, 0));
  EXPECT_EQ(x[6], Vec3(2, 1, 1));
}

TEST(Quality, BoundaryFacesBlockOf8HexesHas24OutwardFaces) {
  const HexMesh m = block({0, 1, 2}, {0, 1, 2}, {0, 1, 2});
  const std::vector<BoundaryFace> faces = boundaryFaces(m);
  ASSERT_EQ(faces.size(), 24u);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const BoundaryFace& f = faces[i];
    if (i > 0) {
      EXPECT_LT(std::make_pair(faces[i - 1].hex, faces[i - 1].localFace), std::make_pair(f.hex, f.localFace));
    }
    const Vec3 normal = (m.nodes[f.nodes[2]] - m.nodes[f.nodes[0]]).cross(m.nodes[f.nodes[3]] - m.nodes[f.nodes[1]]);
    const Vec3 out = centroid(m, f.nodes) - Vec3(1, 1, 1);  // block centre
    EXPECT_GT(normal.dot(out), 0.0) << "face " << i << " points inward";
    for (int k = 0; k < 4; ++k) EXPECT_EQ(f.nodes[k], m.hexes[f.hex][kHexFaces[f.localFace][k]]);
  }
  const BoundaryCheck c = checkBoundary(m);
  EXPECT_EQ(c.faces, 24u);
  EXPECT_TRUE(c.watertight());
  EXPECT_EQ(countCoincidentNodes(m, 1e-9), 0u);
}

TEST(Quality, BoundaryFacesSingleHexFacesPointOutward) {
  const HexMesh m = singleHex(box(1, 1, 1));
  const std::vector<BoundaryFace> faces = boundaryFaces(m);
  ASSERT_EQ(faces.size(), 6u);
  for (const BoundaryFace& f : faces) {
    const Vec3 normal = (m.nodes[f.nodes[1]] - m.nodes[f.nodes[0]]).cross(m.nodes[f.nodes[2]] - m.nodes[f.nodes[1]]);
    EXPECT_GT(normal.dot(centroid(m, f.nodes) - Vec3(0.5, 0.5, 0.5)), 0.0) << "local face " << f.localFace;
  }
  EXPECT_TRUE(checkBoundary(m).watertight());
}

TEST(Quality, BoundaryCheckEdgeSharedByFourFacesIsNonManifold) {
  HexMesh m = block({0, 1, 2}, {0, 1, 2}, {0, 1});
  m.hexes = {m.hexes[0], m.hexes[3]};  // diagonal pair: they touch along one vertical edge
  const BoundaryCheck c = checkBoundary(m);
  EXPECT_EQ(c.faces, 12u);
  EXPECT_EQ(c.nonManifoldEdges, 1u);
  EXPECT_FALSE(c.watertight());
}

TEST(Quality, BoundaryCheckInvertedHexGivesInconsistentOrientation) {
  HexMesh m = block({0, 1, 2}, {0, 1}, {0, 1});
  auto& h = m.hexes[1];
  h = {h[4], h[5], h[6], h[7], h[0], h[1], h[2], h[3]};  // left-handed: its faces point inward
  const BoundaryCheck c = checkBoundary(m);
  EXPECT_EQ(c.faces, 10u);
  EXPECT_EQ(c.openEdges, 0u);
  EXPECT_EQ(c.inconsistentlyOrientedEdges, 4u);  // the 4 edges around the shared face
  EXPECT_FALSE(c.watertight());
}

TEST(Quality, BoundaryCheckFaceSharedByThreeHexesLeavesOpenEdges) {
  HexMesh m = block({0, 1, 2}, {0, 1}, {0, 1});
  m.hexes.push_back(m.hexes[1]);  // an overlapping copy: the face x=1 is used 3 times, hex 1's others twice
  const BoundaryCheck c = checkBoundary(m);
  EXPECT_EQ(c.faces, 5u);  // hex 0 without its x=1 face: an open box
  EXPECT_EQ(c.openEdges, 4u);
  EXPECT_FALSE(c.watertight());
}

TEST(Quality, BoundaryCheckNonConformalTouchingBlocksAreClosedShellsButShowAsExtraFaces) {
  // A 2x2x2 hex beside a 2x2 column of unit hexes, sharing only the outer corners of the x=2 face: every hex
  // shell is closed, so the boundary is edge-balanced, but the touching faces are not matched.
  HexMesh m = block({2, 3}, {0, 1, 2}, {0, 1, 2});
  auto id = [](int j, int k) { return 2 * (j + 3 * k); };  // grid node at x = 2
  const int base = static_cast<int>(m.nodes.size());
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 2), Vec3(0, 2, 2)}) m.nodes.push_back(p);
  m.hexes.push_back({base, id(0, 0), id(2, 0), base + 1, base + 2, id(0, 2), id(2, 2), base + 3});
  EXPECT_GT(hexScaledJacobian(hexCorners(m, 4)), 0.99);
  const BoundaryCheck c = checkBoundary(m);
  EXPECT_EQ(c.faces, 6u + 16u);  // conformal it would be 16 + 4 (big hex minus its x=2 face, small minus 4)
  EXPECT_TRUE(c.watertight());
}

TEST(Quality, CoincidentNodesDuplicatedNodeIsCounted) {
  HexMesh m = singleHex(box(1, 1, 1));
  m.nodes.push_back(m.nodes[3]);  // node 8 duplicates node 3 and replaces it in the hex
  m.hexes[0][3] = 8;
  EXPECT_EQ(countCoincidentNodes(m, 1e-9), 1u);
  EXPECT_EQ(countCoincidentNodes(m, 0.0), 0u);
  EXPECT_EQ(boundaryFaces(m).size(), 6u);
}

TEST(Quality, CoincidentNodesSeparateHexesShareFourNodePositions) {
  HexMesh m = singleHex(box(1, 1, 1));
  for (int i = 0; i < 8; ++i) m.nodes.push_back(m.nodes[i] + Vec3(1, 0, 0));
  m.hexes.push_back({8, 9, 10, 11, 12, 13, 14, 15});
  EXPECT_EQ(countCoincidentNodes(m, 1e-9), 4u);
  EXPECT_EQ(checkBoundary(m).faces, 12u);      // not conformal: no shared face
  EXPECT_TRUE(checkBoundary(m).watertight());  // but two closed shells
}

TEST(Quality, CoincidentNodesToleranceIsStrictAndFarCoordinatesWork) {
  HexMesh m;
  const Vec3 far(1e6, -2e6, 3e5);
  m.nodes = {far, far + Vec3(1e-4, 0, 0), far + Vec3(0, 3e-4, 0), far + Vec3(5, 5, 5)};
  EXPECT_EQ(countCoincidentNodes(m, 0.99e-4), 0u);
  EXPECT_EQ(countCoincidentNodes(m, 1.01e-4), 1u);
  EXPECT_EQ(countCoincidentNodes(m, 2e-4), 1u);
  EXPECT_EQ(countCoincidentNodes(m, 4e-4), 3u);
}
