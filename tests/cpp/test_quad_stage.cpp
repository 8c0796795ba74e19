// §6 as the pipeline runs it (quadmesh/quad_stage.hpp): the chordal surface of a plate, faired, measured and
// quad-meshed at the strongest fairing level; its tries reported as progress, its time budget.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>

#include <cmath>
#include <vector>

#include "bubbles/bubble_packing.hpp"
#include "chordal/chordal_surface.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"
#include "quadmesh/quad_stage.hpp"
#include "tets/tet_mesh.hpp"

using namespace hexlayer;

// A 40 x 30 x 2 plate at size 2, uniform: the strongest fairing (10) meshes it as one structured grid of
// 20 x 15 quads; the chordal surface it lies on has its normals (+-z) and radius (1, half the wall) at every
// vertex; no knife edge, nothing trimmed.
namespace {

// The kept tets of a 40 x 30 x 2 plate.
TetMesh plateTets() {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallSides sides = classifyWallSides(cad);
  TetMesh tets = delaunayTets(packBubbles(cad, sides, BubbleOptions{}));
  keepSpanningTetsInside(tets, cad);
  return tets;
}

}  // namespace

TEST(QuadStage, APlateIsOneGridOnTheMostFairedSurface) {
  const TetMesh tets = plateTets();
  QuadStageOptions o;
  o.size = 2, o.adaptive = false;
  const QuadStage stage = meshFairedChordalSurface(buildChordalSurface(tets), tets, o);
  EXPECT_EQ(stage.fairingIterations, kFairingIterations[0]);
  EXPECT_EQ(stage.knifeFacets, 0u);
  EXPECT_STREQ(layoutName(stage.quads.layout), "grid");
  EXPECT_EQ(stage.quads.quads.size(), 20u * 15u);
  ASSERT_EQ(stage.chordal.radius.size(), stage.chordal.vertices.size());
  for (std::size_t v = 0; v < stage.chordal.vertices.size(); ++v) {
    EXPECT_NEAR(std::abs(stage.chordal.normals[v].z()), 1, 1e-6);
    EXPECT_NEAR(stage.chordal.radius[v], 1, 1e-6);
  }
}

// The stage reports its tries as progress: after the block grids, 1 of 3 x 13 (three fairing levels of the block
// grids and 12 Gmsh splits); the plate's grid is good, so no Gmsh try runs and none is counted. Its budget is
// 300 s + a second per 100 quads.
TEST(QuadStage, ReportsItsTriesAsProgress) {
  const TetMesh tets = plateTets();
  QuadStageOptions o;
  o.size = 2, o.adaptive = false;
  std::vector<Progress> events;
  o.progress = [&](const Progress& p) { events.push_back(p); };
  const QuadStage stage = meshFairedChordalSurface(buildChordalSurface(tets), tets, o);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, Progress::Kind::Advance);
  EXPECT_EQ(events[0].line(), "quad_mesh: 1/39");
  EXPECT_EQ(stage.tries.run + stage.tries.skipped, 0u);
  EXPECT_NEAR(stage.budgetSeconds, quadStageBudget(300), 1) << "the chordal surface's area is about 40 x 30";
  EXPECT_DOUBLE_EQ(quadStageBudget(4000), 340);
}

// Sliver edges (shorter than 1 % of the median facet edge) on a 10 x 10 grid of unit quads, at x1, 1e-3 and 1e3:
// none on the grid; a vertex pair 0.002 apart (a CAD face a few microns wide, bubbles in pairs on both its edges)
// joined by a thin triangle is one; 0.02 apart (2 % of the edge) is none.
TEST(QuadStage, SliverEdgesAreThoseUnderOnePercentOfTheMedianEdge) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    auto grid = [&](double gap) {
      ChordalSurface c;
      const int n = 10;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) c.vertices.push_back(Vec3(i, j, 0) * s);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const int a = i * (n + 1) + j;
          c.facets.push_back({a, a + n + 1, a + n + 2, a + 1});
        }
      if (gap > 0) {  // a vertex beside the grid's corner (10, 10), and a thin triangle to it
        c.vertices.push_back(Vec3(n + gap, n, 0) * s);
        c.facets.push_back({n * (n + 1) + n, static_cast<int>(c.vertices.size()) - 1, n * (n + 1) + n - 1, -1});
      }
      return c;
    };
    EXPECT_EQ(sliverEdges(grid(0)), 0u);
    EXPECT_EQ(sliverEdges(grid(0.002)), 1u);
    EXPECT_EQ(sliverEdges(grid(0.02)), 0u);
  }
}
