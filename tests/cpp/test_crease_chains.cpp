// Quads made to follow creases (quadmesh/crease_chains.hpp) on a flat 10 x 10 grid of unit quads (the chordal surface
// and its quads alike), in mm and scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "quadmesh/crease_chains.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "test_flat_surfaces.hpp"

using namespace hexlayer;

namespace {

// The grid scaled by `scale`: its chordal surface and its quads.
struct Grid {
  ChordalSurface surface;
  QuadMesh quads;
};
Grid grid(double scale) {
  Grid g;
  g.surface = test_flat_surfaces::rectangle(10, 10);
  for (Vec3& v : g.surface.vertices) v *= scale;
  g.surface.radius.assign(g.surface.vertices.size(), scale);
  g.quads.nodes = g.surface.vertices;
  for (const auto& f : g.surface.facets) g.quads.quads.push_back({f[0], f[1], f[2], f[3]});
  return g;
}

// The node at p.
int nodeAt(const QuadMesh& quads, const Vec3& p) {
  for (std::size_t n = 0; n < quads.nodes.size(); ++n)
    if ((quads.nodes[n] - p).norm() <= 1e-12 * (1 + p.norm())) return static_cast<int>(n);
  return -1;
}

// The quads not on the grid's first or last row with corners on both sides of the line x = a (beyond `tolerance`).
int straddling(const QuadMesh& quads, double a, double scale) {
  int count = 0;
  for (const auto& q : quads.quads) {
    bool left = false, right = false, rim = false;
    for (int n : q) {
      const Vec3& p = quads.nodes[n];
      left |= p.x()<a - 1e-9 * scale, right |= p.x()> a + 1e-9 * scale;
      rim |= p.y() < 1e-9 * scale || p.y() > 10 * scale - 1e-9 * scale;
    }
    count += left && right && !rim;
  }
  return count;
}

}  // namespace

// A crease along x = 4.4 (on a wall above the surface, 0.5 off it), ending on the rim: the column of nodes at x = 4 is
// the chain, its nine inner nodes put on x = 4.4 (0.4 of a quad), its two rim nodes slid along the rim onto the
// crease's ends; no quad has corners on both sides of it, and the quads stay good.
TEST(CreaseChains, AGridColumnIsPutOnACreaseAlongIt) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    Grid g = grid(scale);
    const ChordalLocator locator(g.surface);
    EXPECT_EQ(straddling(g.quads, 4.4 * scale, scale), 8);
    const std::vector<std::vector<Vec3>> creases{
        {Vec3(4.4, 0, 0.5) * scale, Vec3(4.4, 5, 0.5) * scale, Vec3(4.4, 10, 0.5) * scale}};
    std::vector<int> column;  // the nodes at x = 4, from y = 0 to 10
    for (int j = 0; j <= 10; ++j) column.push_back(nodeAt(g.quads, Vec3(4, j, 0) * scale));
    const CreaseChainStats s = followCreases(g.quads, locator, creases);
    EXPECT_EQ(s.chains, 1u);
    EXPECT_EQ(s.dropped, 0u);
    EXPECT_EQ(s.nodesMoved, 11u);
    EXPECT_NEAR(s.farthest, 0.4, 1e-9);
    for (int j = 0; j <= 10; ++j) EXPECT_NEAR(g.quads.nodes[column[j]].x(), 4.4 * scale, 1e-9 * scale);
    EXPECT_NEAR(g.quads.nodes[column[0]].y(), 0, 1e-12 * scale);  // on the rim still
    EXPECT_NEAR(g.quads.nodes[column[10]].y(), 10 * scale, 1e-9 * scale);
    EXPECT_EQ(straddling(g.quads, 4.4 * scale, scale), 0);
    EXPECT_GT(s.worstQuad, 0.9);
    for (const Vec3& p : g.quads.nodes) EXPECT_NEAR(p.z(), 0, 1e-12 * scale);  // on the surface
  }
}

// A crease from (4.4, 1.7) to (4.4, 8.3), ending 1.7 quads inside the rim, and one from (0.3, 0) to (0.3, 10), its ends
// on the rim 0.3 from the grid's corners (0, 0) and (0, 10): the first's chain runs from the node at (4, 2) to the one
// at (4, 8), no rim node slid; the second's ends are nearest the corners, where the rim turns 90 degrees: they stay.
TEST(CreaseChains, OnlyACreaseEndingOnTheRimSlidesARimNode) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    Grid g = grid(scale);
    const std::vector<Vec3> before = g.quads.nodes;
    std::vector<int> column;  // the nodes at x = 4, from y = 2 to 8
    for (int j = 2; j <= 8; ++j) column.push_back(nodeAt(g.quads, Vec3(4, j, 0) * scale));
    const std::vector<int> rimEnds{nodeAt(g.quads, Vec3(4, 0, 0) * scale), nodeAt(g.quads, Vec3(4, 10, 0) * scale)};
    const CreaseChainStats s =
        followCreases(g.quads, ChordalLocator(g.surface), {{Vec3(4.4, 1.7, 0) * scale, Vec3(4.4, 8.3, 0) * scale}});
    EXPECT_EQ(s.chains, 1u);
    EXPECT_EQ(s.nodesMoved, 7u);
    for (int j = 2; j <= 8; ++j) {
      EXPECT_NEAR(g.quads.nodes[column[j - 2]].x(), 4.4 * scale, 1e-9 * scale);
      EXPECT_NEAR(g.quads.nodes[column[j - 2]].y(), j * scale, 1e-9 * scale);
    }
    for (const int n : rimEnds) {  // smoothed along the rim (towards the chain) only, not slid onto x = 4.4
      EXPECT_GT(std::abs(g.quads.nodes[n].x() - 4.4 * scale), 0.05 * scale);
      EXPECT_NEAR(g.quads.nodes[n].y(), before[n].y(), 1e-9 * scale);
    }
    Grid h = grid(scale);
    const int corner = nodeAt(h.quads, Vec3(0, 0, 0)), top = nodeAt(h.quads, Vec3(0, 10, 0) * scale);
    followCreases(h.quads, ChordalLocator(h.surface), {{Vec3(0.3, 0, 0) * scale, Vec3(0.3, 10, 0) * scale}});
    EXPECT_EQ(h.quads.nodes[corner], Vec3(0, 0, 0));
    EXPECT_EQ(h.quads.nodes[top], Vec3(0, 10, 0) * scale);
  }
}

// A crease oblique to the grid (from (2.3, 0) to (7.7, 10)): no chain of its quads' edges runs along it without
// turning inside a quad, whose three nodes on the crease would flatten it; the chain is dropped, the quads left as
// they were.
TEST(CreaseChains, ACreaseObliqueToTheGridIsNotFollowed) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    Grid g = grid(scale);
    const std::vector<Vec3> before = g.quads.nodes;
    const CreaseChainStats s =
        followCreases(g.quads, ChordalLocator(g.surface), {{Vec3(2.3, 0, 0) * scale, Vec3(7.7, 10, 0) * scale}});
    EXPECT_EQ(s.chains, 0u);
    EXPECT_EQ(s.dropped, 1u);
    EXPECT_EQ(g.quads.nodes, before);
  }
}
