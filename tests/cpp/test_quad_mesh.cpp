// The quad mesh of the chordal surface (quadmesh/quad_mesh.hpp): meshChordalSurface on flat chordal surfaces built
// by hand, a rectangle and a rectangle with a hole, checked on the quads themselves (they tile the surface, lie
// on it, are squares of the size asked), and rimEdgeNeighbours on a strip of two quads; the Gmsh tries' time budgets
// (a try out of its budget is a failed try; none starts after the deadline); a sharply folded sheet (Gmsh's own-patch
// try, and the patch grid kept over a single grid whose rows cross the fold).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "test_flat_surfaces.hpp"

using namespace hexlayer;
using hexlayer::test_flat_surfaces::rectangle;

namespace {

double quadArea(const QuadMesh& q, const std::array<int, 4>& quad) {
  const auto& x = q.nodes;
  return 0.5 * (x[quad[2]] - x[quad[0]]).cross(x[quad[3]] - x[quad[1]]).norm();
}

// The quads' total area and their worst scaled Jacobian.
struct Tiling {
  double area = 0, worst = 1;
};
Tiling tiling(const QuadMesh& q) {
  Tiling t;
  for (const auto& quad : q.quads) {
    t.area += quadArea(q, quad);
    t.worst =
        std::min(t.worst, quadScaledJacobian({q.nodes[quad[0]], q.nodes[quad[1]], q.nodes[quad[2]], q.nodes[quad[3]]}));
  }
  return t;
}

// The quads of the flat nx x ny rectangle `surface` (with holes of total area `holeArea`) at size 1: they
// cover its area exactly, every node lies in its plane and box, every quad's scaled Jacobian is at least `lowest`.
void expectTiling(const ChordalSurface& surface, int nx, int ny, double holeArea, double lowest) {
  const ChordalLocator chordal(surface);
  QuadMeshOptions o;
  o.size = 1;
  const QuadMesh q = meshChordalSurface(chordal, o);
  ASSERT_FALSE(q.quads.empty());
  EXPECT_NE(q.layout, QuadLayout::Gmsh) << "a structured grid on a rectangle";
  EXPECT_EQ(q.holes, 0u);
  const auto [area, worst] = tiling(q);
  EXPECT_NEAR(area, nx * ny - holeArea, 1e-9);
  EXPECT_GE(worst, lowest);
  for (const Vec3& p : q.nodes) {
    EXPECT_NEAR(p.z(), 0, 1e-12);
    EXPECT_TRUE(p.x() > -1e-9 && p.x() < nx + 1e-9 && p.y() > -1e-9 && p.y() < ny + 1e-9);
  }
}

}  // namespace

TEST(QuadMesh, RectangleGetsUnitSquares) { expectTiling(rectangle(20, 10), 20, 10, 0, 0.999); }

// Round the hole a pocket of four blocks, whose corners on the diagonals are 45 degree quads (1 / sqrt 2).
TEST(QuadMesh, RectangleWithAHoleKeepsTheHole) {
  expectTiling(rectangle(20, 10, {{8, 12, 4, 6}}), 20, 10, 8, std::sqrt(0.5) - 1e-9);
}

// 4 x 3 cutouts of 7 x 6 cells, 1 apart: the holed grid's pockets round them would meet, the shared grid's lines
// run along the cutouts' sides: unit squares, no Gmsh try.
TEST(QuadMesh, GridOfCutoutsGetsTheSharedGrid) {
  std::vector<std::array<int, 4>> holes;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) holes.push_back({3 + 8 * i, 10 + 8 * i, 3 + 7 * j, 9 + 7 * j});
  const ChordalSurface surface = rectangle(37, 27, holes);
  expectTiling(surface, 37, 27, 12 * 42, 0.999);
  const ChordalLocator chordal(surface);
  QuadMeshOptions o;
  o.size = 1;
  const QuadMesh q = meshChordalSurface(chordal, o);
  EXPECT_EQ(q.layout, QuadLayout::SharedGrid);
  EXPECT_EQ(q.quads.size(), 37u * 27 - 12 * 42);
  EXPECT_EQ(q.structuredPatches, 1u);
  EXPECT_EQ(q.tries.run, 0u);
}

// 10 x 3 cutouts 2 x 2, 4 apart, at the size 1.5: the holed grid's pockets fit (they do not meet), but their rings
// round cutouts a quad and a third wide are poor (a mean under 0.95), so the shared grid is ranked too and wins: its
// lines run along the cutouts' sides, rectangles tiling the plate, no Gmsh try.
TEST(QuadMesh, SmallCutoutsWhosePocketsArePoorGetTheSharedGrid) {
  std::vector<std::array<int, 4>> holes;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 10; ++i) holes.push_back({2 + 6 * i, 4 + 6 * i, 3 + 8 * j, 5 + 8 * j});
  const ChordalSurface surface = rectangle(60, 24, holes);
  const ChordalLocator chordal(surface);
  QuadMeshOptions o;
  o.size = 1.5;
  const QuadMesh q = meshChordalSurface(chordal, o);
  EXPECT_EQ(q.layout, QuadLayout::SharedGrid);
  EXPECT_EQ(q.tries.run, 0u);
  const auto [area, worst] = tiling(q);
  EXPECT_NEAR(area, 60 * 24 - 30 * 4, 1e-9);
  EXPECT_GE(worst, 0.999);
}

// Two quads side by side: every node is on the rim; the middle nodes' rim neighbours are along the long sides.
TEST(QuadMesh, RimEdgeNeighboursOfAStrip) {
  QuadMesh q;
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 2; ++i) q.nodes.emplace_back(i, j, 0);
  q.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  std::vector<std::vector<int>> next = rimEdgeNeighbours(q);
  for (auto& n : next) std::sort(n.begin(), n.end());
  EXPECT_EQ(next[0], (std::vector<int>{1, 3}));
  EXPECT_EQ(next[1], (std::vector<int>{0, 2})) << "the shared edge 1-4 is not on the rim";
  EXPECT_EQ(next[4], (std::vector<int>{3, 5}));
  EXPECT_EQ(next[2], (std::vector<int>{1, 5}));
}

// The rectangle with a hole, its pocket's 45-degree corners (0.71) counted as poor quads (below 0.99): the grid
// is not good, so the Gmsh tries run. Each gets a millisecond: every one runs out of it and is a failed try (not
// a wait), and the grid is kept.
TEST(QuadMesh, TryOutOfItsBudgetIsAFailedTry) {
  const ChordalSurface surface = rectangle(20, 10, {{8, 12, 4, 6}});
  const ChordalLocator chordal(surface);
  QuadMeshOptions o;
  o.size = 1, o.timeoutSeconds = 1e-3, o.acceptableQuad = 0.99;
  std::vector<std::size_t> done;
  o.tried = [&](std::size_t d, std::size_t total) {
    EXPECT_EQ(total, 1 + o.patchSplits.size());
    done.push_back(d);
  };
  const QuadMesh q = meshChordalSurface(chordal, o);
  EXPECT_NE(q.layout, QuadLayout::Gmsh);
  // HexLayer's own patches are a fallback for when no try gave quads: with the grid's they are not tried.
  const auto own = std::count_if(o.patchSplits.begin(), o.patchSplits.end(), [](auto& s) { return s.ownPatches; });
  EXPECT_EQ(own, 2);
  EXPECT_EQ(q.tries.run, o.patchSplits.size() - own);
  EXPECT_EQ(q.tries.failed, q.tries.run);
  EXPECT_EQ(q.tries.timedOut, q.tries.run);
  EXPECT_EQ(q.tries.skipped, 0u);
  ASSERT_EQ(done.size(), 1 + o.patchSplits.size()) << "the block grids, then each Gmsh try";
  for (std::size_t k = 0; k < done.size(); ++k) EXPECT_EQ(done[k], k + 1);
}

// Past the deadline (the quad stage's budget spent) no Gmsh try starts: all are counted as not started, and the
// block grid (not good, as above) is kept.
TEST(QuadMesh, NoTryStartsAfterTheDeadline) {
  const ChordalSurface surface = rectangle(20, 10, {{8, 12, 4, 6}});
  const ChordalLocator chordal(surface);
  QuadMeshOptions o;
  o.size = 1, o.acceptableQuad = 0.99, o.deadline = std::chrono::steady_clock::now();
  const QuadMesh q = meshChordalSurface(chordal, o);
  EXPECT_NE(q.layout, QuadLayout::Gmsh);
  EXPECT_EQ(q.tries.run, 0u);
  EXPECT_EQ(q.tries.skipped, o.patchSplits.size());
}

// The default budget of a try grows with the quads: 60 s, and a second per 200 quads.
TEST(QuadMesh, TryBudgetGrowsWithTheQuads) {
  EXPECT_DOUBLE_EQ(gmshTryBudget(0), 60);
  EXPECT_DOUBLE_EQ(gmshTryBudget(20000), 160);
}

namespace {

// The 24 x 12 rectangle folded up by 90 degrees along the oblique line x = 8 + y / 2 (a sharp bend crossing the
// facets, as a sheet's chordal surface has), then scaled.
ChordalSurface foldedRectangle(double scale) {
  ChordalSurface s = rectangle(24, 12);
  const Vec3 origin(8, 0, 0), along = Vec3(0.5, 1, 0).normalized();
  const Eigen::AngleAxisd fold(M_PI / 2, along);
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    if (s.vertices[v].x() > 8 + 0.5 * s.vertices[v].y())
      s.vertices[v] = origin + fold * (s.vertices[v] - origin), s.normals[v] = fold * s.normals[v];
    s.vertices[v] *= scale;
  }
  return s;
}

// The folded sheet at the scales 1, 1e-3 and 1e3 given to `check` with its locator and options asking for quads of
// the scale's unit size.
void onFoldedSheets(const std::function<void(double, const ChordalLocator&, const QuadMeshOptions&)>& check) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const ChordalSurface surface = foldedRectangle(scale);
    const ChordalLocator chordal(surface);
    QuadMeshOptions o;
    o.size = scale;
    check(scale, chordal, o);
  }
}

}  // namespace

// A Gmsh try of HexLayer's own patches (chordal_patches.hpp) on a sheet folded sharply along a line across its
// facets: quads on the surface, none inverted, their area the surface's, the same quads on every run (Gmsh is
// given the patches' curves and points, not its createTopology, whose order changed from run to run).
TEST(QuadMesh, OwnPatchesOfASharplyFoldedSheet) {
  onFoldedSheets([](double scale, const ChordalLocator& chordal, const QuadMeshOptions& o) {
    const PatchSplit own{60, 60, false, 3, true};
    QuadMesh first;
    for (int run = 0; run < 2; ++run) {
      const QuadMesh q = gmshQuads(chordal, o, own);
      ASSERT_FALSE(q.quads.empty()) << q.failure;
      EXPECT_EQ(q.holes, 0u);
      const auto [area, worst] = tiling(q);
      EXPECT_NEAR(area, 24 * 12 * scale * scale, 0.03 * 24 * 12 * scale * scale) << "scale " << scale;
      EXPECT_GT(worst, 0.2) << "scale " << scale;
      // Gmsh smooths its nodes in 3D: they stray a little off the fold (the stage then puts them on the surface).
      for (const Vec3& x : q.nodes) EXPECT_LT((chordal.locate(x).point - x).norm(), 0.25 * scale);
      if (run == 0)
        first = q;
      else
        EXPECT_EQ(q.nodes, first.nodes) << "scale " << scale;
    }
  });
}

// The same fold meshed by the stage: the single grid's rows (along the rectangle's sides) cross the oblique fold, so
// the patch grid of its two faces is kept in its place (quad_mesh.cpp's kCutsCrease): no Gmsh try, every quad on one
// side of the fold, its nodes on the surface, the area the surface's.
TEST(QuadMesh, ASharpFoldAcrossTheGridGetsOneGridPerFace) {
  onFoldedSheets([](double scale, const ChordalLocator& chordal, const QuadMeshOptions& o) {
    const QuadMesh q = meshChordalSurface(chordal, o);
    EXPECT_EQ(q.layout, QuadLayout::PatchGrid) << "scale " << scale;
    EXPECT_EQ(q.tries.run, 0u);
    double area = 0;
    const Vec3 origin = Vec3(8, 0, 0) * scale, across = Vec3(1, -0.5, 0).normalized();  // across the fold, unfolded
    for (const auto& quad : q.quads) {
      area += quadArea(q, quad);
      int flat = 0, up = 0;  // nodes on the flat part and on the folded one (off the fold line)
      for (int v : quad) {
        const Vec3& x = q.nodes[v];
        if (x.z() > 1e-6 * scale)
          ++up;
        else if ((x - origin).dot(across) < -1e-6 * scale)
          ++flat;
      }
      EXPECT_TRUE(flat == 0 || up == 0) << "a quad across the fold, scale " << scale;
    }
    EXPECT_NEAR(area, 24 * 12 * scale * scale, 0.03 * 24 * 12 * scale * scale) << "scale " << scale;
    for (const Vec3& x : q.nodes) EXPECT_LT((chordal.locate(x).point - x).norm(), 1e-9 * scale);
  });
}
