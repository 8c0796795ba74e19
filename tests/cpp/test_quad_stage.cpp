// §6 as the pipeline runs it (quadmesh/quad_stage.hpp): the chordal surface of a plate, faired, measured and
// quad-meshed at the strongest fairing level.
#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>

#include <cmath>

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
TEST(QuadStage, APlateIsOneGridOnTheMostFairedSurface) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallSides sides = classifyWallSides(cad);
  TetMesh tets = delaunayTets(packBubbles(cad, sides, BubbleOptions{}));
  keepSpanningTetsInside(tets, cad);
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
