// Structured block grids of the chordal surface (quadmesh/block_grids.hpp): the grids are all-quad, square and
// keep the surface's topology and extent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/union_find.hpp"
#include "quadmesh/block_grids.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "test_flat_surfaces.hpp"

using namespace hexlayer;
using hexlayer::test_flat_surfaces::rectangle;

namespace {

// A flat disc of radius `rings`: a fan round the centre, then rings of `around` quads.
ChordalSurface disc(int rings, int around) {
  ChordalSurface s;
  s.vertices.emplace_back(0, 0, 0);
  for (int k = 1; k <= rings; ++k)
    for (int j = 0; j < around; ++j)
      s.vertices.emplace_back(k * std::cos(2 * M_PI * j / around), k * std::sin(2 * M_PI * j / around), 0);
  s.normals.assign(s.vertices.size(), Vec3::UnitZ());
  auto v = [&](int k, int j) { return 1 + (k - 1) * around + j % around; };
  for (int j = 0; j < around; ++j) s.facets.push_back({0, v(1, j), v(1, j + 1), -1});
  for (int k = 1; k < rings; ++k)
    for (int j = 0; j < around; ++j) s.facets.push_back({v(k, j), v(k + 1, j), v(k + 1, j + 1), v(k, j + 1)});
  return s;
}

long euler(const BlockGrid& g) {
  std::set<std::uint64_t> edges;
  for (const auto& q : g.quads)
    for (int k = 0; k < 4; ++k) edges.insert(edgeKey(q[k], q[(k + 1) % 4]));
  return static_cast<long>(g.nodes.size()) - static_cast<long>(edges.size()) + static_cast<long>(g.quads.size());
}

struct Quality {
  double worst = 1, mean = 0, area = 0;
};

// Quad scaled Jacobians (each quad counter-clockwise seen from +z: a flipped quad counts negative)
// and the total area.
Quality quality(const BlockGrid& g) {
  Quality q;
  for (const auto& quad : g.quads) {
    const std::array<Vec3, 4> p{g.nodes[quad[0]], g.nodes[quad[1]], g.nodes[quad[2]], g.nodes[quad[3]]};
    const Vec3 n = (p[2] - p[0]).cross(p[3] - p[1]);
    const double sj = (n.z() > 0 ? 1 : -1) * quadScaledJacobian(p);
    q.worst = std::min(q.worst, sj), q.mean += sj / g.quads.size(), q.area += 0.5 * n.norm();
  }
  return q;
}

const SizeField unit = [](const Vec3&) { return 1.0; };

}  // namespace

TEST(BlockGrids, GridWithAPocketRoundTheHole) {
  const SurfaceMap map = mapToPlane(rectangle(20, 10, {{8, 12, 3, 7}}), 1.0, MapBoundary::Square);
  const BlockGrid g = holedGrid(map, unit);
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.blocks, 5u);
  EXPECT_EQ(euler(g), 0);  // an annulus, like the surface
  const Quality q = quality(g);
  EXPECT_GT(q.worst, 0.6);
  EXPECT_GT(q.mean, 0.95);
  EXPECT_NEAR(q.area, 200 - 16, 1e-9);
  EXPECT_NEAR(static_cast<double>(g.quads.size()), 184, 30);  // unit quads
}

TEST(BlockGrids, OGridOfADisc) {
  const SurfaceMap map = mapToPlane(disc(10, 64), 1.0, MapBoundary::Circle);
  EXPECT_FALSE(map.sharpCorners);
  const BlockGrid g = oGrid(map, unit);
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.blocks, 5u);
  EXPECT_EQ(euler(g), 1);
  const Quality q = quality(g);
  EXPECT_GT(q.worst, 0.6);
  EXPECT_GT(q.mean, 0.9);
  const double polygon = 0.5 * 64 * 100 * std::sin(2 * M_PI / 64);  // the disc's area
  EXPECT_NEAR(q.area, polygon, 0.02 * polygon);
  for (const Vec3& p : g.nodes) EXPECT_LE(p.norm(), 10 + 1e-9);
  EXPECT_TRUE(
      oGrid(mapToPlane(rectangle(20, 10, {{8, 12, 3, 7}}), 1.0, MapBoundary::Circle), unit).empty());  // has a hole
}

TEST(BlockGrids, PocketsThatMeetAreRefused) {
  // two holes one cell apart: their pockets (one cell beyond each hole) overlap
  const ChordalSurface s = rectangle(20, 10, {{6, 9, 3, 7}, {10, 13, 3, 7}});
  const SurfaceMap map = mapToPlane(s, 1.0, MapBoundary::Square);
  ASSERT_EQ(map.holes.size(), 2u);
  EXPECT_TRUE(holedGrid(map, unit).empty());
}
