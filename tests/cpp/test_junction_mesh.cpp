// The T junction's steps (pipeline/junction_mesh.hpp): the frame of a rib on a flat rectangular plate, the rib's
// foot grid from its hexes, the plate's footprint, the plate's nodes that are the rib's foot nodes, the junction
// hexes. Run on a rib across a plate (also at order 2) and one inside it, at 2 and 3 layers, on copies scaled by 1e-3
// and 1e3; a boss and a rib on an L-shaped plate are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/append.hpp"
#include "core/error.hpp"
#include "geometry/cad_solid.hpp"
#include "pipeline/junction_mesh.hpp"
#include "pipeline/pipeline.hpp"
#include "quality/quality.hpp"
#include "test_boxes.hpp"

using namespace hexlayer;
using hexlayer::test_boxes::Box;
using hexlayer::test_boxes::boxes;

namespace {

struct Cut {
  CadSolid cad;
  std::vector<Sheet> sheets;
  JunctionCut cut;
};

Cut cutOf(const TopoDS_Solid& solid) {
  Cut c{prepareSolid(solid, normalizingUnit(solid)), {}, {}};
  const WallSides sides = classifyWallSides(c.cad);
  c.sheets = findSheets(c.cad, sides);
  c.cut = cutAtJunctions(c.cad, sides, c.sheets);
  return c;
}

// A 60 x 40 x 2 plate with a 2 thick, 12 high rib along x at y = 19..21 from x0 to x1, scaled by s: the frame is the
// plate's (u along x, v across, w up to the foot at z = 2), its rectangle the plate's; the rib's foot grid has
// layers + 1 rows from y = 19 to 21 and columns from x0 to x1; the plate meshed with the footprint grid has a node
// under every foot node (within 1e-4 of the plate: its grid nodes under the foot nodes, its sweep lines meeting the
// wall), which the junction hexes
// (the rib's first row and the plate's under the foot) hold.
void expectT(double x0, double x1, int layers, int order = 1) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s) + ", " + std::to_string(layers) + " layers");
    const Cut c = cutOf(boxes({{0, 0, 0, 60, 40, 2}, {x0, 19, 2, x1 - x0, 2, 12}}, s));
    const double k = s * c.cad.unit, tolerance = 1e-9 * k;  // input lengths in the pipeline's units
    const TJunctionFrame t = tJunctionFrame(c.cad, c.sheets, c.cut);
    EXPECT_NEAR(t.w.z(), 1, 1e-12);
    EXPECT_NEAR(std::abs(t.plate.u.x()), 1, 1e-12);
    EXPECT_NEAR(t.plate.uMax - t.plate.uMin, 60 * k, tolerance);
    EXPECT_NEAR(t.plate.vMax - t.plate.vMin, 40 * k, tolerance);
    EXPECT_NEAR(t.thickness, 2 * k, tolerance);
    EXPECT_NEAR(t.footW, 2 * k, tolerance);
    EXPECT_NEAR(t.plate.origin.z(), k, tolerance);
    MeshOptions o;
    o.layers = layers, o.order = order;
    const MeshResult rib = meshSolid(c.cut.pieces[1], o);
    const FootGrid foot = footGrid(rib.mesh, rib.quadMesh, t);
    ASSERT_EQ(foot.rows.size(), static_cast<std::size_t>(layers + 1));
    const double v0 = std::min(19 * k * t.plate.v.y(), 21 * k * t.plate.v.y());
    const double u0 = std::min(x0 * k * t.plate.u.x(), x1 * k * t.plate.u.x());
    EXPECT_NEAR(foot.rows.front(), v0, 1e-6 * k);
    EXPECT_NEAR(foot.rows.back(), v0 + 2 * k, 1e-6 * k);
    EXPECT_NEAR(foot.columns.front(), u0, 1e-6 * k);
    EXPECT_NEAR(foot.columns.back(), u0 + (x1 - x0) * k, 1e-6 * k);
    for (std::size_t i = 0; i < foot.rows.size(); ++i)
      for (std::size_t j = 0; j < foot.columns.size(); ++j)
        EXPECT_NEAR((foot.at[i][j] - Eigen::Vector2d(foot.columns[j], foot.rows[i])).norm(), 0, 0.2 * k);
    FootprintGrid grid;
    const MeshResult plate = meshSolid(c.cut.pieces[0], o, [&](const CadSolid& piece, QuadStage& stage) {
      const Footprint f = footprintOf(t, foot, piece.unit);
      EXPECT_NEAR(f.size, (x1 - x0) * k * piece.unit / (foot.columns.size() - 1), 1e-9 * k * piece.unit);
      grid = footprintGrid(f);
      stage.quads = grid.quads;
    });
    const std::vector<int> shared = footNodesShared(plate.mesh, grid.strip, rib.mesh, foot, 1e-4 * k);
    const std::size_t rows = foot.rows.size(), columns = foot.columns.size();
    // The foot's corners, and at order 2 the mid-edge nodes of its edges along and across.
    const std::size_t feet = rows * columns + (order == 2 ? rows * (columns - 1) + (rows - 1) * columns : 0);
    EXPECT_EQ(static_cast<std::size_t>(std::count_if(shared.begin(), shared.end(), [](int n) { return n >= 0; })),
              feet);
    HexMesh joined = rib.mesh;
    joinHexMesh(joined, plate.mesh, shared);
    EXPECT_EQ(joined.nodes.size(), rib.mesh.nodes.size() + plate.mesh.nodes.size() - feet);
    std::vector<int> footNodes;
    for (const auto& row : foot.nodes) footNodes.insert(footNodes.end(), row.begin(), row.end());
    const JunctionHexes j = junctionHexes(joined, measureQuality(joined).scaledJacobian, footNodes);
    // The rib's first row (M columns x layers) and the plate's hexes under the foot, and their neighbours.
    const std::size_t m = foot.columns.size() - 1;
    EXPECT_GE(j.hexes, 2 * m * layers);
    EXPECT_LT(j.hexes, joined.hexes.size());
    EXPECT_GT(j.minScaledJacobian, 0.99);
    EXPECT_GT(j.meanScaledJacobian, 0.99);
  }
}

void expectRefused(const TopoDS_Solid& solid, const std::string& why) {
  const Cut c = cutOf(solid);
  try {
    tJunctionFrame(c.cad, c.sheets, c.cut);
    FAIL() << "not refused: " << why;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::UnsupportedGeometry);
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(JunctionMesh, RibAcrossAPlate) { expectT(0, 60, 2); }

TEST(JunctionMesh, RibInsideAPlateThreeLayers) { expectT(10, 50, 3); }

// 20-node hexes: the plate's mid-edge nodes on the foot are the rib's too.
TEST(JunctionMesh, RibAcrossAPlateOrderTwo) { expectT(0, 60, 2, 2); }

// A boss (its walls cylinders) and a rib on an L-shaped plate are not this T.
TEST(JunctionMesh, OtherJunctionsAreRefused) {
  const TopoDS_Solid boss =
      readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/junctions/plate_boss.step").at(0);
  expectRefused(boss, "not planar");
  for (double s : {1.0, 1e-3, 1e3})
    expectRefused(boxes({{0, 0, 0, 60, 40, 2}, {0, 40, 0, 20, 20, 2}, {10, 19, 2, 40, 2, 12}}, s), "not a rectangle");
}

// The junction hexes: those with a corner among the foot's nodes, their scaled Jacobian's min and mean.
TEST(JunctionMesh, JunctionHexesHoldAFootNode) {
  HexMesh mesh;
  mesh.nodes.assign(16, Vec3::Zero());
  mesh.hexes = {{0, 1, 2, 3, 4, 5, 6, 7}, {8, 9, 10, 11, 12, 13, 14, 15}, {4, 5, 6, 7, 8, 9, 10, 11}};
  const JunctionHexes j = junctionHexes(mesh, {0.5, 0.9, 1.0}, {12});
  EXPECT_EQ(j.hexes, 1u);
  EXPECT_DOUBLE_EQ(j.minScaledJacobian, 0.9);
  const JunctionHexes both = junctionHexes(mesh, {0.5, 0.9, 1.0}, {4, 9});
  EXPECT_EQ(both.hexes, 3u);
  EXPECT_DOUBLE_EQ(both.minScaledJacobian, 0.5);
  EXPECT_DOUBLE_EQ(both.meanScaledJacobian, 0.8);
}
