// Smoothing of the quad mesh on the chordal surface (quadmesh/quad_smoothing.hpp): the quad quality measures on
// known quads, the doublet removal and renumbering, and a perturbed grid on a flat surface smoothed back towards
// squares with its corners kept, its rim nodes on the rim and every node on the surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "chordal/chordal_locator.hpp"
#include "quadmesh/quad_smoothing.hpp"

using namespace hexlayer;

namespace {

// An n x n grid of unit quads on z = 0, counter-clockwise seen from +z; node (i, j) has id i + (n + 1) j.
QuadMesh grid(int n) {
  QuadMesh q;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) q.nodes.emplace_back(i, j, 0);
  auto id = [&](int i, int j) { return i + (n + 1) * j; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) q.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return q;
}

// The grid as a chordal surface (its quads the facets, normal +z, radius 1).
ChordalSurface surfaceOf(const QuadMesh& q) {
  ChordalSurface s;
  s.vertices = q.nodes;
  s.facets = q.quads;
  s.normals.assign(q.nodes.size(), Vec3::UnitZ());
  s.radius.assign(q.nodes.size(), 1.0);
  s.quads = q.quads.size();
  return s;
}

// The grid's nodes strictly inside x in (0, xMax), y in (0, n) pushed up to 0.35 in the plane (fixed seed).
QuadMesh perturbed(const QuadMesh& grid, int n, double xMax, unsigned seed) {
  QuadMesh q = grid;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> push(-0.35, 0.35);
  for (Vec3& p : q.nodes)
    if (p.x() > 0 && p.x() < xMax && p.y() > 0 && p.y() < n) p += Vec3(push(random), push(random), 0);
  return q;
}

double worstQuad(const QuadMesh& q) {
  double worst = 1;
  for (const auto& f : q.quads)
    worst = std::min(worst, quadScaledJacobian({q.nodes[f[0]], q.nodes[f[1]], q.nodes[f[2]], q.nodes[f[3]]}));
  return worst;
}

}  // namespace

TEST(QuadSmoothing, ScaledJacobianAndSmoothingQualityOfKnownQuads) {
  const std::array<Vec3, 4> square{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  EXPECT_NEAR(quadScaledJacobian(square), 1, 1e-15);
  EXPECT_NEAR(quadSmoothingQuality(square), 1, 1e-15);
  // A rhombus of 60 and 120 degree corners: sin 60 at every corner.
  const Vec3 e(std::cos(M_PI / 3), std::sin(M_PI / 3), 0);
  EXPECT_NEAR(quadScaledJacobian({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0) + e, e}), std::sin(M_PI / 3), 1e-12);
  // Rectangles: square corners; penalized by 4 x shortest / longest edge only beyond 4:1.
  const std::array<Vec3, 4> long3{Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(0, 1, 0)};
  const std::array<Vec3, 4> long5{Vec3(0, 0, 0), Vec3(5, 0, 0), Vec3(5, 1, 0), Vec3(0, 1, 0)};
  EXPECT_NEAR(quadScaledJacobian(long5), 1, 1e-15);
  EXPECT_NEAR(quadSmoothingQuality(long3), 1, 1e-15);
  EXPECT_NEAR(quadSmoothingQuality(long5), 0.8, 1e-15);
  // A bow tie (its diagonals parallel) and a quad with a collapsed edge: -1.
  EXPECT_EQ(quadScaledJacobian({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}), -1);
  EXPECT_EQ(quadScaledJacobian({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}), -1);
}

// Facing a normal: a square facing +z keeps 1, turned over -1; the bow tie Gmsh once left round a foot's corner (two
// corners turning back seen along +z, whose own diagonals' normal points down: turned over, half its corners look
// right, and negated it looked good at 0.87) is below 0 whichever way it is turned.
TEST(QuadSmoothing, ScaledJacobianFacingANormalFindsTurnedAndCrossedQuads) {
  const std::array<Vec3, 4> square{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  const Vec3 up = Vec3::UnitZ();
  EXPECT_NEAR(quadScaledJacobian(square, up), 1, 1e-15);
  EXPECT_NEAR(quadScaledJacobian(square, -up), -1, 1e-15);
  const std::array<Vec3, 4> bowTie{Vec3(43, 26, 0), Vec3(43, 24, 0), Vec3(41, 24, 0), Vec3(41.44, 23.24, 0)};
  EXPECT_GT(-quadScaledJacobian(bowTie), 0.8) << "through its own diagonals: negative, so negated it looks good";
  EXPECT_LT(quadScaledJacobian(bowTie, up), 0);
  EXPECT_LT(quadScaledJacobian(bowTie, -up), 0);
  const std::array<Vec3, 4> tilted{Vec3(0, 0, 0), Vec3(1, 0, 0.2), Vec3(1, 1, 0.1), Vec3(0, 1, -0.1)};
  EXPECT_EQ(quadScaledJacobian(tilted, up), quadScaledJacobian(tilted)) << "a good quad: as through its diagonals";
}

TEST(QuadSmoothing, DropUnusedNodesRenumbersTheRestInOrder) {
  std::vector<Vec3> nodes{Vec3(0, 0, 0), Vec3(9, 9, 9), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(8, 8, 8), Vec3(0, 1, 0)};
  std::vector<std::array<int, 4>> quads{{0, 2, 3, 5}, {5, 3, 2, 0}};
  dropUnusedNodes(nodes, quads);
  EXPECT_EQ(nodes, (std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}));
  EXPECT_EQ(quads, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}, {3, 2, 1, 0}}));
}

// The middle node of a 2 x 2 grid split off into a doublet: node 9 inside quad (4, 5, 8, 7), in two quads
// sharing its edges 4-9 and 9-8. They become the quad (4, 5, 8, 7) again and node 9 is dropped.
TEST(QuadSmoothing, RemoveDoubletsMergesTheTwoQuadsOfANodeInTwoQuads) {
  QuadMesh q = grid(2);
  q.nodes.push_back(Vec3(1.5, 1.5, 0));  // 9
  q.quads[3] = {9, 4, 5, 8};
  q.quads.push_back({9, 8, 7, 4});
  EXPECT_EQ(removeDoublets(q), 1);
  ASSERT_EQ(q.quads.size(), 4u);
  ASSERT_EQ(q.nodes.size(), 9u);
  const QuadMesh expected = grid(2);
  EXPECT_EQ(q.nodes, expected.nodes);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(q.quads[k], expected.quads[k]);
  std::array<int, 4> merged = q.quads[3], corners = expected.quads[3];
  std::sort(merged.begin(), merged.end()), std::sort(corners.begin(), corners.end());
  EXPECT_EQ(merged, corners) << "the quad round the doublet";
  EXPECT_EQ(removeDoublets(q), 0) << "a grid has none";
}

// A 6 x 6 grid on its own flat surface, its interior nodes pushed up to 0.35 in the plane (fixed seed): the
// smoothing brings the worst quad from below 0.6 to above 0.9; the four corners stay, the rim nodes stay on
// their side of the square, every node on the surface (z = 0); the same result twice.
TEST(QuadSmoothing, PerturbedGridIsSmoothedBackKeepingItsCornersAndRim) {
  const QuadMesh square = grid(6);
  const ChordalSurface surface = surfaceOf(square);
  const ChordalLocator locator(surface);
  QuadMesh q = perturbed(square, 6, 6, 3);
  const double before = worstQuad(q);
  ASSERT_LT(before, 0.6);
  QuadMesh again = q;
  smoothQuadMesh(q, locator, 10);
  EXPECT_GT(worstQuad(q), 0.9) << "from " << before;
  for (std::size_t i = 0; i < q.nodes.size(); ++i) {
    const Vec3 &p = q.nodes[i], &start = square.nodes[i];
    EXPECT_NEAR(p.z(), 0, 1e-12) << "node " << i;
    EXPECT_TRUE(p.x() >= -1e-12 && p.x() <= 6 + 1e-12 && p.y() >= -1e-12 && p.y() <= 6 + 1e-12) << "node " << i;
    const bool onX = start.x() == 0 || start.x() == 6, onY = start.y() == 0 || start.y() == 6;
    if (onX && onY) EXPECT_EQ(p, start) << "corner " << i;
    if (onX) EXPECT_NEAR(p.x(), start.x(), 1e-12) << "rim node " << i;
    if (onY) EXPECT_NEAR(p.y(), start.y(), 1e-12) << "rim node " << i;
  }
  smoothQuadMesh(again, locator, 10);
  EXPECT_EQ(again.nodes, q.nodes) << "deterministic";
}

// A 64 x 64 grid (past the size from which a sweep visits two halves side by side), its interior nodes pushed up to
// 0.35 in the plane on its left third only (the poor quads: the cut between the halves runs through them): smoothed
// on one thread and on two, the same nodes to the bit, and the worst quad from below 0.6 to above 0.9.
TEST(QuadSmoothing, LargeGridIsSmoothedTheSameOnOneThreadAndOnTwo) {
  const QuadMesh square = grid(64);
  const ChordalSurface surface = surfaceOf(square);
  const ChordalLocator locator(surface);
  QuadMesh q = perturbed(square, 64, 21, 5);
  const double before = worstQuad(q);
  ASSERT_LT(before, 0.6);
  QuadMesh two = q;
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
#endif
  smoothQuadMesh(q, locator, 10);
#ifdef _OPENMP
  omp_set_num_threads(2);
#endif
  smoothQuadMesh(two, locator, 10);
#ifdef _OPENMP
  omp_set_num_threads(threads);
#endif
  EXPECT_EQ(two.nodes, q.nodes);
  EXPECT_GT(worstQuad(q), 0.9) << "from " << before;
}
