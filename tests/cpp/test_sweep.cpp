// Sweep (sweep/sweep.hpp, paper §7): layer offsets and the nodes on a sweep line (§7.2), the interpolated sweep
// direction (§7.1) and the hexes built from quads (§7.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "chordal/chordal_locator.hpp"
#include "quality/quality.hpp"
#include "sweep/sweep.hpp"

using namespace hexlayer;

namespace {

// Flat chordal surface on the grid [0, nx] x [0, ny] at z = 0: unit quads, counter-clockwise
// seen from +z, normal +z and radius given per vertex. Vertex (i, j) has id i + (nx + 1) j.
ChordalSurface flatGrid(int nx, int ny, double (*radius)(const Vec3&)) {
  ChordalSurface s;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      s.vertices.emplace_back(i, j, 0);
      s.tetEdge.push_back({0, 0});
      s.normals.push_back(Vec3::UnitZ());
      s.radius.push_back(radius(s.vertices.back()));
    }
  auto id = [&](int i, int j) { return i + (nx + 1) * j; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) s.facets.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  s.quads = s.facets.size();
  return s;
}

double unitRadius(const Vec3&) { return 1.0; }
double growingRadius(const Vec3& p) { return 1.0 + 0.5 * p.x(); }

QuadMesh sameQuads(const ChordalSurface& s) {
  QuadMesh q;
  q.nodes = s.vertices;
  q.quads = s.facets;
  return q;
}

// The quad node a hex node was swept from: the one with the same x and y.
int quadNodeBelow(const QuadMesh& q, const Vec3& h) {
  for (size_t i = 0; i < q.nodes.size(); ++i)
    if (std::abs(q.nodes[i].x() - h.x()) < 1e-12 && std::abs(q.nodes[i].y() - h.y()) < 1e-12)
      return static_cast<int>(i);
  return -1;
}

std::set<int> sharedNodes(const std::array<int, 8>& a, const std::array<int, 8>& b) {
  std::set<int> out;
  for (int x : a)
    if (std::find(b.begin(), b.end(), x) != b.end()) out.insert(x);
  return out;
}

}  // namespace

// §7.2: m + 1 offsets from -r to +r, step 2r/m; a node on the chordal surface only for even m.
TEST(Sweep, LayerOffsetsSpanRadiusEvenlyAndHitMidSurfaceForEvenLayers) {
  for (int m = 1; m <= 5; ++m) {
    SCOPED_TRACE(testing::Message() << "m = " << m);
    const std::vector<double> o = layerOffsets(m);
    ASSERT_EQ(o.size(), static_cast<size_t>(m + 1));
    EXPECT_DOUBLE_EQ(o.front(), -1.0);
    EXPECT_DOUBLE_EQ(o.back(), 1.0);
    for (int k = 0; k < m; ++k) EXPECT_NEAR(o[k + 1] - o[k], 2.0 / m, 1e-15) << "step " << k;
    const bool onSurface = std::any_of(o.begin(), o.end(), [](double x) { return std::abs(x) < 1e-15; });
    EXPECT_EQ(onSurface, m % 2 == 0);
    if (m % 2 == 1) {  // odd: the two middle nodes at +-s/2 = +-1/m
      EXPECT_NEAR(o[(m - 1) / 2], -1.0 / m, 1e-15);
      EXPECT_NEAR(o[(m + 1) / 2], 1.0 / m, 1e-15);
    }
    for (int k = 0; k <= m; ++k) EXPECT_NEAR(o[k], -o[m - k], 1e-15) << "symmetric about the chordal surface";
  }
}

TEST(Sweep, LayerNodesFollowAnAsymmetricLine) {
  const Vec3 q(1, 2, 3);
  const SweepLine line{Vec3(1, 2, 2), Vec3(1, 2, 6)};  // 1 below, 3 above the chordal surface
  const std::vector<double> offsets = layerOffsets(4);
  const double expected[] = {2, 2.5, 3, 4.5, 6};
  for (int k = 0; k <= 4; ++k) EXPECT_NEAR(layerNode(q, line, offsets[k]).z(), expected[k], 1e-12) << k;
  const SweepLine even = radiusSweepLine(q, Vec3::UnitZ(), 1.5);
  EXPECT_NEAR((layerNode(q, even, -1) - Vec3(1, 2, 1.5)).norm(), 0, 1e-12);  // §7.2: q - r n̄
  EXPECT_NEAR((layerNode(q, even, 1) - Vec3(1, 2, 4.5)).norm(), 0, 1e-12);
}

// §7.1: normal and radius are the weighted corner values of the facet (Eq. 4-7), normal re-normalized.
TEST(Sweep, InterpolateSweepWeighsTheFacetsCornerValues) {
  ChordalSurface s;
  s.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0.2), Vec3(2, 0, 0)};
  s.normals = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -0.6, 0.8), Vec3(0.6, 0, 0.8)};
  s.radius = {1.0, 2.0, 4.0, 3.0, 0.5};
  s.facets = {{0, 1, 2, -1}, {1, 4, 3, 2}};
  s.tetEdge.assign(s.vertices.size(), {0, 0});
  s.triangles = 1, s.quads = 1;

  auto at = [](int facet, std::array<double, 4> w) {
    ChordalPoint p;
    p.facet = facet;
    p.weights = w;
    return p;
  };
  // On a vertex: that vertex's normal and radius.
  SweepDirection d = interpolateSweep(s, at(0, {0, 1, 0, 0}));
  EXPECT_LT((d.normal - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(d.radius, 2.0);
  // Middle of edge 0-1 (Eq. 4-5).
  d = interpolateSweep(s, at(0, {0.5, 0.5, 0, 0}));
  EXPECT_LT((d.normal - Vec3(1, 0, 1).normalized()).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(d.radius, 1.5);
  // Inside the triangle (Eq. 6-7).
  d = interpolateSweep(s, at(0, {0.5, 0.25, 0.25, 0}));
  EXPECT_LT((d.normal - Vec3(0.25, 0.25, 0.5).normalized()).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(d.radius, 0.5 * 1 + 0.25 * 2 + 0.25 * 4);
  // The quad facet's corners are 1, 4, 3, 2: weight k belongs to corner facets[1][k].
  d = interpolateSweep(s, at(1, {0, 1, 0, 0}));
  EXPECT_LT((d.normal - Vec3(0.6, 0, 0.8)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(d.radius, 0.5);
  d = interpolateSweep(s, at(1, {0.1, 0.2, 0.3, 0.4}));
  const Vec3 n = 0.1 * s.normals[1] + 0.2 * s.normals[4] + 0.3 * s.normals[3] + 0.4 * s.normals[2];
  EXPECT_LT((d.normal - n.normalized()).norm(), 1e-15);
  EXPECT_NEAR(d.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(d.radius, 0.1 * 2.0 + 0.2 * 0.5 + 0.3 * 3.0 + 0.4 * 4.0, 1e-15);
}

// §7.2-7.3 on a flat surface: two unit quads over [0,2] x [0,1] at z = 0, normal +z, radius 1.
TEST(Sweep, SweepQuadsOnFlatSurfaceBuildsConformalLayers) {
  const ChordalSurface s = flatGrid(2, 1, unitRadius);
  const ChordalLocator locator(s);
  const QuadMesh q = sameQuads(s);
  ASSERT_EQ(q.nodes.size(), 6u);
  for (int m : {2, 3}) {
    SCOPED_TRACE(testing::Message() << "m = " << m);
    const HexMesh h = sweepQuads(q, locator, m).mesh;
    const std::vector<double> offsets = layerOffsets(m);
    EXPECT_EQ(h.layers, m);
    ASSERT_EQ(h.hexes.size(), q.quads.size() * m);
    ASSERT_EQ(h.nodes.size(), q.nodes.size() * (m + 1));
    ASSERT_EQ(h.nodeLayer.size(), h.nodes.size());
    ASSERT_EQ(h.nodeOnRim.size(), h.nodes.size());

    // Every quad node gives one hex node per layer, at z = r * offset of the layer, straight above it.
    std::map<std::pair<int, int>, int> seen;  // (quad node, layer) -> count
    for (size_t i = 0; i < h.nodes.size(); ++i) {
      const int layer = h.nodeLayer[i];
      ASSERT_GE(layer, 0);
      ASSERT_LE(layer, m);
      EXPECT_NEAR(h.nodes[i].z(), offsets[layer], 1e-12) << "node " << i;
      const int below = quadNodeBelow(q, h.nodes[i]);
      ASSERT_GE(below, 0) << "node " << i << " not above a quad node";
      ++seen[{below, layer}];
      EXPECT_EQ(h.nodeOnRim[i], 1) << "every node of a 2 x 1 strip is on its rim";
    }
    EXPECT_EQ(seen.size(), h.nodes.size());
    for (const auto& [key, count] : seen) EXPECT_EQ(count, 1);
    if (m % 2 == 0) {
      int onSurface = 0;
      for (const Vec3& p : h.nodes) onSurface += std::abs(p.z()) < 1e-12;
      EXPECT_EQ(onSurface, 6) << "even m: one node per quad node on the chordal surface";
    }

    double volume = 0;
    for (size_t e = 0; e < h.hexes.size(); ++e) {
      const auto& hex = h.hexes[e];
      for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(h.nodeLayer[hex[c + 4]], h.nodeLayer[hex[c]] + 1) << "hex " << e;
        EXPECT_LT((h.nodes[hex[c + 4]] - h.nodes[hex[c]] - Vec3(0, 0, 2.0 / m)).norm(), 1e-12) << "hex " << e;
      }
      const auto x = hexCorners(h, e);
      EXPECT_NEAR(hexVolume(x), 2.0 / m, 1e-12) << "hex " << e;
      EXPECT_NEAR(hexScaledJacobian(x), 1.0, 1e-12) << "hex " << e;
      volume += hexVolume(x);
    }
    EXPECT_NEAR(volume, 2.0 * 2.0, 1e-12) << "area 2 times thickness 2r";

    // Conformal: no duplicated nodes, neighbours share a face, a closed boundary.
    EXPECT_EQ(countCoincidentNodes(h, 1e-6), 0u);
    std::map<size_t, size_t> sharedCounts;  // shared node count -> hex pairs
    for (size_t a = 0; a < h.hexes.size(); ++a)
      for (size_t b = a + 1; b < h.hexes.size(); ++b) ++sharedCounts[sharedNodes(h.hexes[a], h.hexes[b]).size()];
    // Face neighbours: same quad in consecutive layers (2 (m - 1)) and the two quads in one layer (m).
    EXPECT_EQ(sharedCounts[4], static_cast<size_t>(2 * (m - 1) + m));
    const BoundaryCheck boundary = checkBoundary(h);
    EXPECT_TRUE(boundary.watertight());
    EXPECT_EQ(boundary.faces, static_cast<size_t>(2 * 2 + 6 * m)) << "2 quads at top and bottom, 6 rim edges per layer";
  }
}

TEST(Sweep, SweepQuadsMarksOnlyRimNodesOnRim) {
  const ChordalSurface s = flatGrid(2, 2, unitRadius);  // centre vertex (1, 1) has id 4
  const ChordalLocator locator(s);
  const HexMesh h = sweepQuads(sameQuads(s), locator, 2).mesh;
  ASSERT_EQ(h.nodes.size(), 27u);
  int inner = 0;
  for (size_t i = 0; i < h.nodes.size(); ++i) {
    const bool centre = std::abs(h.nodes[i].x() - 1) < 1e-12 && std::abs(h.nodes[i].y() - 1) < 1e-12;
    EXPECT_EQ(h.nodeOnRim[i], centre ? 0 : 1) << "node " << i << " at " << h.nodes[i].transpose();
    inner += centre;
  }
  EXPECT_EQ(inner, 3);
}

// The quad mesh's orientation is Gmsh's: clockwise quads must be turned, not give inverted hexes.
TEST(Sweep, SweepQuadsTurnsClockwiseQuads) {
  const ChordalSurface s = flatGrid(2, 1, unitRadius);
  const ChordalLocator locator(s);
  QuadMesh q = sameQuads(s);
  for (auto& quad : q.quads) std::swap(quad[1], quad[3]);  // clockwise seen from +z
  for (int m : {1, 2, 3}) {
    const HexMesh h = sweepQuads(q, locator, m).mesh;
    ASSERT_EQ(h.hexes.size(), 2u * m);
    for (size_t e = 0; e < h.hexes.size(); ++e) {
      const auto x = hexCorners(h, e);
      EXPECT_NEAR(hexVolume(x), 2.0 / m, 1e-12) << "m = " << m << ", hex " << e;
      EXPECT_GT(hexScaledJacobian(x), 0.99);
    }
    EXPECT_TRUE(checkBoundary(h).watertight());
  }
}

// A wall's foot node on the sheet's top wall 0.8 beside the top of quad node (1, 1)'s column (a bend's inside corner
// between walls of different thickness): that end is put there, the column's nodes above the chordal surface on the
// new half line at their offsets, those below left. A foot node under the sheet moves the bottom end. Both ends are
// reported, and with `near` beyond their distances both are reported but neither is moved; a lap's (FootEnd::lap) is
// moved however near. No feet: nothing.
TEST(Sweep, PlaceFootEndsPutsTheNearerEndOnTheWallsFootNode) {
  const ChordalSurface s = flatGrid(2, 2, unitRadius);  // centre vertex (1, 1) has id 4
  const ChordalLocator locator(s);
  const QuadMesh q = sameQuads(s);
  for (const int m : {2, 3}) {
    SCOPED_TRACE("layers " + std::to_string(m));
    const HexMesh before = sweepQuads(q, locator, m).mesh;
    HexMesh h = before;
    EXPECT_TRUE(placeFootEnds(h, q, {}, 0).empty());
    const int first = 4 * (m + 1), last = first + m;
    const Vec3 top(1.8, 1, 1), bottom(0.4, 0, -1);
    const std::vector<FootEnd> feet{{4, top}, {0, bottom}};
    const std::vector<char> near = placeFootEnds(h, q, feet, 1.0);
    EXPECT_EQ(h.nodes, before.nodes);
    const std::vector<char> placed = placeFootEnds(h, q, feet, 0.1);
    EXPECT_EQ(near, placed);
    const std::vector<double> offsets = layerOffsets(m);
    for (int k = 0; k <= m; ++k) {
      const Vec3 on = Vec3(1, 1, 0) + offsets[k] * (top - Vec3(1, 1, 0));
      EXPECT_LT((h.nodes[first + k] - (offsets[k] > 0 ? on : before.nodes[first + k])).norm(), 1e-12) << k;
    }
    EXPECT_EQ(h.nodes[last], top);
    EXPECT_EQ(h.nodes[0], bottom);
    EXPECT_EQ(std::count(placed.begin(), placed.end(), 1), 2);
    EXPECT_TRUE(placed[last] && placed[0]);
    for (std::size_t n = 0; n < h.nodes.size(); ++n)
      if (n / (m + 1) != 4 && n / (m + 1) != 0) EXPECT_EQ(h.nodes[n], before.nodes[n]);
    HexMesh lap = before;  // a lap's foot node is put there however near
    placeFootEnds(lap, q, {{4, top, true}}, 1.0);
    EXPECT_EQ(lap.nodes[last], top);
  }
}

// The hex node offsets scale with the interpolated radius (§7.2: s = 2r / m).
TEST(Sweep, SweepQuadsScalesLayersWithTheRadius) {
  const ChordalSurface s = flatGrid(2, 1, growingRadius);  // r = 1 + x / 2
  const ChordalLocator locator(s);
  const QuadMesh q = sameQuads(s);
  const int m = 4;
  const HexMesh h = sweepQuads(q, locator, m).mesh;
  const std::vector<double> offsets = layerOffsets(m);
  for (size_t i = 0; i < h.nodes.size(); ++i) {
    const double r = 1 + 0.5 * h.nodes[i].x();
    EXPECT_NEAR(h.nodes[i].z(), r * offsets[h.nodeLayer[i]], 1e-12) << "node " << i;
  }
  double volume = 0;
  for (size_t e = 0; e < h.hexes.size(); ++e) {
    const double v = hexVolume(hexCorners(h, e));
    EXPECT_GT(v, 0);
    volume += v;
  }
  // Thickness 2 r(x) = 2 + x over [0, 2] x [0, 1]: volume = 4 + 2.
  EXPECT_NEAR(volume, 6.0, 1e-12);
}
