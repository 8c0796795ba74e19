#include "quadmesh/patch_grids.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "test_flat_surfaces.hpp"

namespace hexlayer {
namespace {

// The chordal surface of an open box: a floor L x W of unit cells at z = 0 and four walls H high standing on its
// edges, folded from the box's net (a cross of cells) with sharp creases. `jitter`: each node on a crease moves
// into the box by up to that much along each coordinate it shares with the crease (randomly, fixed seed), as the
// chordal surface of a bend with a sharp inside edge zigzags across it. All of it times `scale`.
ChordalSurface openBox(int L, int W, int H, double jitter, double scale) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> share(0, 1);
  std::map<std::array<int, 3>, int> index;  // folded node -> vertex
  ChordalSurface s;
  auto fold = [&](int i, int j) -> std::array<int, 3> {
    if (i < 0) return {0, j, -i};
    if (i > L) return {L, j, i - L};
    if (j < 0) return {i, 0, -j};
    if (j > W) return {i, W, j - W};
    return {i, j, 0};
  };
  auto vertex = [&](int i, int j) {
    const std::array<int, 3> p = fold(i, j);
    const auto [it, added] = index.emplace(p, static_cast<int>(s.vertices.size()));
    if (!added) return it->second;
    const bool atX = p[0] == 0 || p[0] == L, atY = p[1] == 0 || p[1] == W, atZ = p[2] == 0;
    Vec3 x(p[0], p[1], p[2]);
    const double in = jitter * share(random);
    if (atX && (atZ || atY)) x.x() += p[0] == 0 ? in : -in;
    if (atY && (atZ || atX)) x.y() += p[1] == 0 ? in : -in;
    if (atZ && (atX || atY)) x.z() += in;
    s.vertices.push_back(scale * x), s.normals.push_back(Vec3::UnitZ());
    return it->second;
  };
  for (int j = -H; j < W + H; ++j)
    for (int i = -H; i < L + H; ++i) {
      if ((i < 0 || i >= L) && (j < 0 || j >= W)) continue;  // the net's corners
      s.facets.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  return s;
}

// What the grid's quads make: per node the quads round it, and per undirected edge its uses.
struct GridShape {
  std::map<int, int> quadsAt;
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edgeUses;  // edge -> (from, to) per use
  std::set<int> rim;                                                         // nodes of edges used once
};

GridShape shapeOf(const BlockGrid& g) {
  GridShape shape;
  for (const auto& q : g.quads)
    for (int k = 0; k < 4; ++k) {
      ++shape.quadsAt[q[k]];
      shape.edgeUses[std::minmax(q[k], q[(k + 1) % 4])].emplace_back(q[k], q[(k + 1) % 4]);
    }
  for (const auto& [edge, uses] : shape.edgeUses)
    if (uses.size() == 1) shape.rim.insert(edge.first), shape.rim.insert(edge.second);
  return shape;
}

TEST(PatchGrids, AnOpenBoxIsOneGridPerFaceRegularButAtItsBottomCorners) {
  const int L = 12, W = 8, H = 5;
  const std::size_t even = L * W + 2 * (L + W) * H;  // the quads of unit size
  for (const double jitter : {0.0, 0.4})
    for (const double scale : {1.0, 1e-3, 1e3})
      for (const bool graded : {false, true}) {
        SCOPED_TRACE(testing::Message() << "jitter " << jitter << " scale " << scale << " graded " << graded);
        const ChordalSurface box = openBox(L, W, H, jitter, scale);
        const SizeField unit = [&](const Vec3&) { return scale; };
        const PatchGrids grids = patchGrids(box, unit, 40);
        const BlockGrid& g = graded ? grids.graded : grids.even;
        ASSERT_FALSE(g.empty());
        EXPECT_EQ(g.blocks, 5u);
        if (graded) {  // denser rows towards the creases: a row or two more across every face
          EXPECT_GT(g.quads.size(), even);
          EXPECT_LT(g.quads.size(), 1.6 * even);
        } else {
          EXPECT_EQ(g.quads.size(), even);
        }
        const GridShape shape = shapeOf(g);
        // conformal and oriented alike: every edge inside in two quads, run opposite ways
        for (const auto& [edge, uses] : shape.edgeUses) {
          ASSERT_LE(uses.size(), 2u);
          if (uses.size() == 2) EXPECT_EQ(uses[0].first, uses[1].second);
        }
        EXPECT_EQ(static_cast<long>(g.nodes.size()) - static_cast<long>(shape.edgeUses.size()) +
                      static_cast<long>(g.quads.size()),
                  1);  // a disc, as the surface
        int irregular = 0;
        for (const auto& [node, quads] : shape.quadsAt)
          if (!shape.rim.count(node) && quads != 4) {
            EXPECT_EQ(quads, 3) << "at " << g.nodes[node].transpose();
            EXPECT_NEAR(g.nodes[node].z(), 0, 0.5 * scale);  // a bottom corner
            ++irregular;
          }
        EXPECT_EQ(irregular, 4);
        for (const auto& [edge, uses] : shape.edgeUses) {
          const double length = (g.nodes[edge.first] - g.nodes[edge.second]).norm() / scale;
          EXPECT_GT(length, 0.3);
          EXPECT_LT(length, 1.5);
        }
      }
}

TEST(PatchGrids, NoGridWhereAFaceIsNotFourSidedOrThereIsOneFace) {
  const SizeField unit = [](const Vec3&) { return 1.0; };
  const PatchGrids flat = patchGrids(test_flat_surfaces::rectangle(6, 4), unit, 40);
  EXPECT_TRUE(flat.graded.empty() && flat.even.empty());
  ChordalSurface holed = openBox(12, 8, 5, 0, 1);  // a hole of 2 x 2 cells in the floor
  holed.facets.erase(std::remove_if(holed.facets.begin(), holed.facets.end(),
                                    [&](const auto& f) {
                                      const Vec3& p = holed.vertices[f[0]];
                                      return p.z() == 0 && p.x() >= 5 && p.x() < 7 && p.y() >= 3 && p.y() < 5 &&
                                             holed.vertices[f[2]].z() == 0;
                                    }),
                     holed.facets.end());
  EXPECT_EQ(holed.facets.size(), 12u * 8 + 2 * 20 * 5 - 4);
  const PatchGrids grids = patchGrids(holed, unit, 40);
  EXPECT_TRUE(grids.graded.empty() && grids.even.empty());
}

}  // namespace
}  // namespace hexlayer
