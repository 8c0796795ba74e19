// Quads made to follow creases (quadmesh/crease_chains.hpp) on a flat 10 x 10 grid of unit quads (the chordal surface
// and its quads alike), in mm and scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>

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

// A crease along x = 4.4 (on a wall above the surface, 0.5 off it): the column of nodes at x = 4 is the chain, its nine
// inner nodes put on x = 4.4 (0.4 of a quad), its two rim nodes left (the rim's capture puts their columns on the
// crease's ends); no quad but the first and last rows' has corners on both sides of it, and the quads stay good.
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
    EXPECT_EQ(s.nodesMoved, 9u);
    EXPECT_NEAR(s.farthest, 0.4, 1e-9);
    for (int j = 1; j < 10; ++j) EXPECT_NEAR(g.quads.nodes[column[j]].x(), 4.4 * scale, 1e-9 * scale);
    EXPECT_EQ(g.quads.nodes[column[0]], Vec3(4, 0, 0) * scale);  // the rim's
    EXPECT_EQ(g.quads.nodes[column[10]], Vec3(4, 10, 0) * scale);
    EXPECT_EQ(straddling(g.quads, 4.4 * scale, scale), 0);
    EXPECT_GT(s.worstQuad, 0.9);
    for (const Vec3& p : g.quads.nodes) EXPECT_NEAR(p.z(), 0, 1e-12 * scale);  // on the surface
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
