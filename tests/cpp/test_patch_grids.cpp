#include "quadmesh/patch_grids.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// The nodes off the rim that are not regular: each must have three quads round it, at the bottom (a box's corner).
int bottomCorners(const BlockGrid& g, const GridShape& shape, double scale) {
  int irregular = 0;
  for (const auto& [node, quads] : shape.quadsAt)
    if (!shape.rim.count(node) && quads != 4) {
      EXPECT_EQ(quads, 3) << "at " << g.nodes[node].transpose();
      EXPECT_NEAR(g.nodes[node].z(), 0, 0.5 * scale);
      ++irregular;
    }
  return irregular;
}

// Every edge between lo and hi quads long.
void expectEdgesBetween(const BlockGrid& g, const GridShape& shape, double scale, double lo, double hi) {
  for (const auto& [edge, uses] : shape.edgeUses) {
    const double length = (g.nodes[edge.first] - g.nodes[edge.second]).norm() / scale;
    EXPECT_GT(length, lo);
    EXPECT_LT(length, hi);
  }
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
        EXPECT_EQ(bottomCorners(g, shape, scale), 4);
        expectEdgesBetween(g, shape, scale, 0.3, 1.5);
      }
}

// The box without the facets `drop` says (their unused vertices removed).
template <typename Drop>
ChordalSurface without(const ChordalSurface& box, Drop drop) {
  ChordalSurface cut = box;
  cut.facets.erase(std::remove_if(cut.facets.begin(), cut.facets.end(), drop), cut.facets.end());
  return test_flat_surfaces::withoutUnusedVertices(cut);
}

// Every edge in at most two quads, run opposite ways, and the grid's Euler characteristic V - E + F.
long conformalEuler(const BlockGrid& g) {
  const GridShape shape = shapeOf(g);
  for (const auto& [edge, uses] : shape.edgeUses) {
    EXPECT_LE(uses.size(), 2u);
    if (uses.size() == 2) EXPECT_EQ(uses[0].first, uses[1].second);
  }
  return static_cast<long>(g.nodes.size()) - static_cast<long>(shape.edgeUses.size()) +
         static_cast<long>(g.quads.size());
}

// The chordal surface of an open box on a floor of unit cells (i, j) in `cells`, H high: the floor at z = 0, a wall
// of H rows on every edge of its outline, all times `scale`.
ChordalSurface openBoxOn(const std::set<std::pair<int, int>>& cells, int H, double scale) {
  std::map<std::array<int, 3>, int> index;
  ChordalSurface s;
  auto vertex = [&](int i, int j, int k) {
    const auto [it, added] = index.emplace(std::array<int, 3>{i, j, k}, static_cast<int>(s.vertices.size()));
    if (added) s.vertices.push_back(scale * Vec3(i, j, k)), s.normals.push_back(Vec3::UnitZ());
    return it->second;
  };
  for (const auto& [i, j] : cells) {
    s.facets.push_back({vertex(i, j, 0), vertex(i + 1, j, 0), vertex(i + 1, j + 1, 0), vertex(i, j + 1, 0)});
    // the cell's edges counter-clockwise, each with the cell across it: a wall where there is none
    const std::array<std::array<int, 6>, 4> edges{{{i, j, i + 1, j, i, j - 1},
                                                   {i + 1, j, i + 1, j + 1, i + 1, j},
                                                   {i + 1, j + 1, i, j + 1, i, j + 1},
                                                   {i, j + 1, i, j, i - 1, j}}};
    for (const auto& [ai, aj, bi, bj, ci, cj] : edges)
      if (!cells.count({ci, cj}))
        for (int k = 0; k < H; ++k)
          s.facets.push_back({vertex(bi, bj, k), vertex(ai, aj, k), vertex(ai, aj, k + 1), vertex(bi, bj, k + 1)});
  }
  return s;
}

// An open box on an L-shaped floor (12 x 8 and 6 x 6 on its side): the floor has six corners, one of them reflex. It
// is cut in two from that corner straight on to the wall across (the wall's bend there split in two, a side of two
// curves); every face then one grid, conformal, unit quads: three quads round each of the five convex bottom
// corners, five round the reflex one (three of the floor's, two of the walls'), every other node inside regular.
TEST(PatchGrids, AnLShapedFloorIsCutInTwoAtItsReflexCorner) {
  std::set<std::pair<int, int>> cells;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 14; ++j)
      if (j < 8 || i < 6) cells.insert({i, j});
  const int H = 5;
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(testing::Message() << "scale " << scale);
    const ChordalSurface box = openBoxOn(cells, H, scale);
    const std::size_t quads = cells.size() + (2 * 12 + 2 * 14) * H;
    EXPECT_EQ(box.facets.size(), quads);
    const SizeField unit = [&](const Vec3&) { return scale; };
    const BlockGrid g = patchGrids(box, unit, 40).even;
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(g.blocks, 6u + 2);
    EXPECT_EQ(g.quads.size(), quads);
    EXPECT_EQ(conformalEuler(g), 1);
    const GridShape shape = shapeOf(g);
    std::map<int, int> valence;  // quads round a node off the rim -> nodes
    for (const auto& [node, n] : shape.quadsAt)
      if (!shape.rim.count(node)) ++valence[n];
    EXPECT_EQ(valence[3], 5);
    EXPECT_EQ(valence[5], 1);
    EXPECT_EQ(valence.size(), 3u);  // and 4
    expectEdgesBetween(g, shape, scale, 0.3, 1.5);
  }
}

// The wall at y = 8 two cells lower for x < 6: its top steps down, six corners, one reflex (at (6, 8, 3)): cut from
// there down to the floor, two four-sided faces, the floor's bend there split in two.
TEST(PatchGrids, AWallWhoseTopStepsDownIsCutAtTheStep) {
  const SizeField unit = [](const Vec3&) { return 1.0; };
  const ChordalSurface box = openBox(12, 8, 5, 0, 1);
  const ChordalSurface stepped = without(box, [&](const auto& f) {
    const Vec3 a = box.vertices[f[0]], c = box.vertices[f[2]];
    return a.y() == 8 && c.y() == 8 && std::max(a.z(), c.z()) > 3 && std::max(a.x(), c.x()) <= 6;
  });
  EXPECT_EQ(stepped.facets.size(), 12u * 8 + 2 * 20 * 5 - 12);
  const BlockGrid g = patchGrids(stepped, unit, 40).even;
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.blocks, 5u + 1);
  EXPECT_EQ(g.quads.size(), stepped.facets.size());
  EXPECT_EQ(conformalEuler(g), 1);
}

// A box 20 x 12 x 10 whose end wall x = 0 is 4 high: the front wall's corner above it is rounded, R6 (the square
// x < 6, z > 4 of its cells mapped onto the quarter disc round (6, 0, 4), as a wall's top corner rounded R12 at 2 mm
// quads). Over three quads that round turns 29 degrees, too little for a corner; over six, 57: the front wall is cut
// in the middle of its round, its turn there measured over six quads too, and the box is one grid per face, every
// quad square enough; at three scales.
TEST(PatchGrids, AWallsTopCornerRoundedOverMoreThanThreeQuadsIsCutInItsMiddle) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(testing::Message() << "scale " << scale);
    const SizeField unit = [&](const Vec3&) { return scale; };
    const ChordalSurface box = openBox(20, 12, 10, 0, 1);
    ChordalSurface rounded = without(box, [&](const auto& f) {
      const Vec3 a = box.vertices[f[0]], c = box.vertices[f[2]];
      return a.x() == 0 && c.x() == 0 && std::max(a.z(), c.z()) > 4;
    });
    for (Vec3& p : rounded.vertices) {
      const double dx = 6 - p.x(), dz = p.z() - 4;
      if (p.y() == 0 && dx > 0 && dz > 0) {
        const double r = std::max(dx, dz) / std::hypot(dx, dz);
        p.x() = 6 - r * dx, p.z() = 4 + r * dz;
      }
      p *= scale;
    }
    const BlockGrid g = patchGrids(rounded, unit, 40).even;
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(g.blocks, 5u);
    EXPECT_EQ(conformalEuler(g), 1);
    expectEdgesBetween(g, shapeOf(g), scale, 0.25, 1.8);
  }
}

// No grid on a surface of one face.
TEST(PatchGrids, NoGridOnOneFace) {
  const SizeField unit = [](const Vec3&) { return 1.0; };
  const PatchGrids flat = patchGrids(test_flat_surfaces::rectangle(6, 4), unit, 40);
  EXPECT_TRUE(flat.graded.empty() && flat.even.empty());
}

// Two holes of 2 x 2 cells in the box's floor a cell apart: their pockets (a cell beyond each hole) would meet, so the
// floor is sharedGrid's with its sides' nodes given, the grid's lines on the holes' sides: every quad a unit square
// (as many as the facets), conformal with the walls, a disc with two holes; at three scales.
TEST(PatchGrids, HolesWhosePocketsMeetShareTheFacesGrid) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(testing::Message() << "scale " << scale);
    const SizeField unit = [&](const Vec3&) { return scale; };
    const ChordalSurface box = openBox(12, 8, 5, 0, scale);
    const ChordalSurface holes = without(box, [&](const auto& f) {
      const Vec3 c = (box.vertices[f[0]] + box.vertices[f[1]] + box.vertices[f[2]] + box.vertices[f[3]]) / 4 / scale;
      return c.z() == 0 && c.y() > 3 && c.y() < 5 && ((c.x() > 3 && c.x() < 5) || (c.x() > 6 && c.x() < 8));
    });
    EXPECT_EQ(holes.facets.size(), 12u * 8 + 2 * 20 * 5 - 8);
    const BlockGrid g = patchGrids(holes, unit, 40).even;
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(g.quads.size(), holes.facets.size());
    EXPECT_EQ(conformalEuler(g), -1);  // a disc with two holes
    expectEdgesBetween(g, shapeOf(g), scale, 0.99, 1.01);
  }
}

// A hole of 2 x 2 cells in the box's floor: the floor is one grid with a pocket of four blocks round the hole (its
// map onto the square, holedGrid with its sides' nodes), the walls one grid each, all conformal; a disc with a hole.
TEST(PatchGrids, AHoleInAFaceGetsAPocketOfFourBlocks) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(testing::Message() << "scale " << scale);
    const ChordalSurface box = openBox(12, 8, 5, 0, scale);
    const ChordalSurface holed = without(box, [&](const auto& f) {
      const Vec3 a = box.vertices[f[0]] / scale, c = box.vertices[f[2]] / scale;
      return a.z() == 0 && c.z() == 0 && std::min(a.x(), c.x()) >= 5 && std::max(a.x(), c.x()) <= 7 &&
             std::min(a.y(), c.y()) >= 3 && std::max(a.y(), c.y()) <= 5;
    });
    EXPECT_EQ(holed.facets.size(), 12u * 8 + 2 * 20 * 5 - 4);
    const SizeField unit = [&](const Vec3&) { return scale; };
    const BlockGrid g = patchGrids(holed, unit, 40).even;
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(g.blocks, 4u + 1 + 4);  // four walls; the floor and its pocket
    EXPECT_EQ(conformalEuler(g), 0);  // a disc with a hole
    std::size_t onHole = 0;           // nodes on the hole's square
    for (const Vec3& x : g.nodes) {
      const Vec3 p = x / scale;
      onHole += std::abs(p.z()) < 1e-9 && p.x() > 4.99 && p.x() < 7.01 && p.y() > 2.99 && p.y() < 5.01 &&
                (std::abs(p.x() - 5) < 1e-9 || std::abs(p.x() - 7) < 1e-9 || std::abs(p.y() - 3) < 1e-9 ||
                 std::abs(p.y() - 5) < 1e-9);
    }
    EXPECT_GE(onHole, 8u);
    expectEdgesBetween(g, shapeOf(g), scale, 0.2, 1.6);
  }
}

// Quads of 5 on a box 30 x 20 x 10: a hole of one cell in the floor (its loop 4 long, shorter than a quad's edge: a
// pinhole, as a bend relief) is closed by the floor's grid, as the quad mesh's topology has it (a disc, no pocket);
// a hole of 2 x 2 cells (its loop 8 long) keeps its pocket (a disc with a hole).
TEST(PatchGrids, APinholeInAFaceIsClosedAndAHoleIsNot) {
  const SizeField five = [](const Vec3&) { return 5.0; };
  for (const int cells : {1, 2}) {
    SCOPED_TRACE(testing::Message() << "hole of " << cells << " x " << cells << " cells");
    const ChordalSurface box = openBox(30, 20, 10, 0, 1);
    const ChordalSurface holed = without(box, [&](const auto& f) {
      const Vec3 c = (box.vertices[f[0]] + box.vertices[f[1]] + box.vertices[f[2]] + box.vertices[f[3]]) / 4;
      return c.z() == 0 && c.x() > 14 && c.x() < 14 + cells && c.y() > 9 && c.y() < 9 + cells;
    });
    EXPECT_EQ(holed.facets.size(), 30u * 20 + 2 * 50 * 10 - cells * cells);
    const BlockGrid g = patchGrids(holed, five, 40).even;
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(conformalEuler(g), cells == 1 ? 1 : 0);
    EXPECT_EQ(g.blocks, cells == 1 ? 4u + 1 : 4u + 1 + 4);
  }
}

// The wall at y = 0 stands on the floor's edge for x < 6 only: the floor's side along it is the bend and then the
// rim, going on flat (a side of two curves). Still one grid per face, unit quads, conformal; the bend's nodes and
// the rim's make one row along the floor's side, three bottom corners with three quads round them.
TEST(PatchGrids, AWallStandingOnPartOfAnEdgeEndsOnTheSideOfTheFloor) {
  const int L = 12, W = 8, H = 5;
  for (const double jitter : {0.0, 0.3})
    for (const double scale : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE(testing::Message() << "jitter " << jitter << " scale " << scale);
      const ChordalSurface box = openBox(L, W, H, jitter, scale);
      const ChordalSurface part = without(box, [&](const auto& f) {  // by the cell's centre
        const Vec3 c = (box.vertices[f[0]] + box.vertices[f[1]] + box.vertices[f[2]] + box.vertices[f[3]]) / 4 / scale;
        return c.y() < 0.45 && c.z() > 0.3 && c.x() > 6;
      });
      const std::size_t cells = L * W + 2 * (L + W) * H - (L - 6) * H;
      EXPECT_EQ(part.facets.size(), cells);
      const SizeField unit = [&](const Vec3&) { return scale; };
      const BlockGrid g = patchGrids(part, unit, 40).even;
      ASSERT_FALSE(g.empty());
      EXPECT_EQ(g.blocks, 5u);
      EXPECT_EQ(g.quads.size(), cells);
      EXPECT_EQ(conformalEuler(g), 1);
      const GridShape shape = shapeOf(g);
      EXPECT_EQ(bottomCorners(g, shape, scale), 3);
      expectEdgesBetween(g, shape, scale, 0.3, 1.5);
    }
}

}  // namespace
}  // namespace hexlayer
