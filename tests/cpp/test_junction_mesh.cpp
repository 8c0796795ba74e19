// The junctions' steps (pipeline/junction_mesh.hpp): a standing wall's foot from its hexes, the plate's nodes that
// are the walls' foot nodes, the joined mesh, the junction hexes. Run on a rib across a plate (also at order 2), one
// inside it at 3 layers, two ribs on an L-shaped plate, on copies scaled by 1e-3 and 1e3; a boss's foot is a ring; the
// columns of a sheet two ribs cross obliquely lean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "chordal/chordal_locator.hpp"
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

// The walls standing on a plate (parts: boxes fused, the 60 x 40 x 2 plate and those standing on it at z = 2), scaled
// by s: each wall's foot (wallFoot) is `layers` rows of quads on the plate's top z = 2, a strip; the plate meshed with
// its quads carrying the footprints (insertFootprints) has a node under every foot node (within 1e-4 of the plate: its
// sweep lines meeting the wall), and joined the hexes are one conformal mesh (every face in one or two hexes, the faces
// in one closing the part) whose junction hexes (the walls' first rows and the plate's under the feet) are good.
void expectJoined(const std::vector<Box>& parts, int layers, int order = 1) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s) + ", " + std::to_string(layers) + " layers");
    const Cut c = cutOf(boxes(parts, s));
    const double k = s * c.cad.unit;  // input lengths in the pipeline's units
    MeshOptions o;
    o.layers = layers, o.order = order;
    HexMesh walls;
    FootprintQuads footprint;
    double area = 0, feet = 0;  // of the footprints, of the boxes standing on the plate
    for (const Box& b : parts) feet += b.z0 == 2 ? b.dx * b.dy * k * k : 0;
    std::vector<int> wallNode;
    for (int w = 1; w < static_cast<int>(c.cut.pieces.size()); ++w) {
      const MeshResult wall = meshSolid(c.cut.pieces[w], o);
      std::vector<FootSurface> feet = footSurfaces(c.cut, w, 0, 1e-6 * k);
      const WallFoot foot = wallFoot(wall.mesh, wall.quadMesh, feet);
      EXPECT_FALSE(foot.ring);
      EXPECT_EQ(foot.footprint.quads.size() % layers, 0u);
      for (const auto& q : foot.footprint.quads) {
        const auto& p = foot.footprint.nodes;
        area += 0.5 * (p[q[2]] - p[q[0]]).cross(p[q[3]] - p[q[1]]).norm();
      }
      for (const Vec3& p : foot.footprint.nodes) EXPECT_NEAR(p.z(), 2 * k, 1e-9 * k);
      const int first = static_cast<int>(footprint.nodes.size()), nodes = static_cast<int>(walls.nodes.size());
      for (auto q : foot.footprint.quads) {
        for (int& n : q) n += first;
        footprint.quads.push_back(q);
      }
      footprint.nodes.insert(footprint.nodes.end(), foot.footprint.nodes.begin(), foot.footprint.nodes.end());
      for (int n : foot.wallNode) wallNode.push_back(n + nodes);
      appendHexMesh(walls, wall.mesh);
    }
    EXPECT_NEAR(area, feet, 1e-6 * feet);
    FootprintInsertion inserted;
    const MeshResult plate = meshSolid(c.cut.pieces[0], o, [&](const CadSolid& piece, QuadStage& stage) {
      const ChordalLocator locator(stage.chordal);
      FootprintQuads onSheet = footprint;
      for (Vec3& p : onSheet.nodes) p = locator.locate(p * piece.unit).point;
      inserted = insertFootprints(stage.quads, onSheet, locator, 2 * piece.unit * k);
      stage.quads = inserted.quads;
    });
    const std::vector<int> shared = footNodesShared(plate.mesh, inserted.node, walls, wallNode, 1e-4 * k);
    // The feet's corners, and at order 2 the mid-edge nodes of their edges.
    std::set<std::pair<int, int>> edges;
    for (const auto& q : footprint.quads)
      for (int e = 0; e < 4; ++e) edges.insert(std::minmax(q[e], q[(e + 1) % 4]));
    const std::size_t footNodes = footprint.nodes.size() + (order == 2 ? edges.size() : 0);
    EXPECT_EQ(static_cast<std::size_t>(std::count_if(shared.begin(), shared.end(), [](int n) { return n >= 0; })),
              footNodes);
    HexMesh joined = walls;
    joinHexMesh(joined, plate.mesh, shared);
    EXPECT_EQ(joined.nodes.size(), walls.nodes.size() + plate.mesh.nodes.size() - footNodes);
    const QualityReport quality = measureQuality(joined);
    EXPECT_EQ(quality.inverted, 0u);
    double volume = 0;
    for (const Box& b : parts) volume += b.volume() * k * k * k;
    EXPECT_NEAR(quality.volume, volume, 1e-6 * volume);
    std::map<std::array<int, 4>, int> faces;
    for (const auto& h : joined.hexes)
      for (const auto& f : kHexFaces) {
        std::array<int, 4> face{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
        std::sort(face.begin(), face.end());
        ++faces[face];
      }
    for (const auto& [face, n] : faces) EXPECT_LE(n, 2);
    const BoundaryCheck boundary = checkBoundary(joined);
    EXPECT_TRUE(boundary.watertight());
    EXPECT_EQ(boundary.eulerCharacteristic, 2);
    const JunctionHexes j = junctionHexes(joined, quality.scaledJacobian, wallNode);
    EXPECT_GE(j.hexes, 2 * footprint.quads.size());
    EXPECT_LT(j.hexes, joined.hexes.size());
    EXPECT_GT(j.minScaledJacobian, 0.3);
    EXPECT_GT(j.meanScaledJacobian, 0.85);
  }
}

}  // namespace

TEST(JunctionMesh, RibAcrossAPlate) { expectJoined({{0, 0, 0, 60, 40, 2}, {0, 19, 2, 60, 2, 12}}, 2); }

TEST(JunctionMesh, RibInsideAPlateThreeLayers) { expectJoined({{0, 0, 0, 60, 40, 2}, {10, 19, 2, 40, 2, 12}}, 3); }

// 20-node hexes: the plate's mid-edge nodes on the foot are the rib's too.
TEST(JunctionMesh, RibAcrossAPlateOrderTwo) { expectJoined({{0, 0, 0, 60, 40, 2}, {0, 19, 2, 60, 2, 12}}, 2, 2); }

// Two ribs, one thinner than the plate, on an L-shaped plate.
TEST(JunctionMesh, TwoRibsOnAnLPlate) {
  expectJoined({{0, 0, 0, 60, 40, 2}, {0, 40, 0, 20, 20, 2}, {10, 19, 2, 40, 2, 12}, {5, 45, 2, 10, 1, 8}}, 2);
}

// A boss's foot is a ring.
TEST(JunctionMesh, ABossFootIsARing) {
  const TopoDS_Solid boss =
      readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/junctions/plate_boss.step").at(0);
  const Cut c = cutOf(boss);
  ASSERT_EQ(c.cut.pieces.size(), 2u);
  MeshOptions o;
  const MeshResult wall = meshSolid(c.cut.pieces[1], o);
  std::vector<FootSurface> feet = footSurfaces(c.cut, 1, 0, 1e-6);
  const WallFoot foot = wallFoot(wall.mesh, wall.quadMesh, feet);
  EXPECT_TRUE(foot.ring);
  EXPECT_EQ(foot.footprint.nodes.size(), foot.footprint.quads.size() / o.layers * (o.layers + 1));
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

namespace {

// A flat sheet swept from a 9 x 9 grid of 2 mm quads (z = 0), `layers` layers through z = -1..1, scaled by s, as
// sweep.hpp lays it out (quad node q's column: hex nodes q (layers + 1) + k).
struct SweptSheet {
  QuadMesh quads;
  HexMesh hexes;
};

SweptSheet sweptGrid(int layers, double s) {
  SweptSheet g;
  constexpr int n = 9;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      g.quads.nodes.push_back(s * Vec3(2 * i, 2 * j, 0));
      for (int k = 0; k <= layers; ++k) g.hexes.nodes.push_back(s * Vec3(2 * i, 2 * j, -1 + 2.0 * k / layers));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      const std::array<int, 4> q{a, a + 1, a + n + 2, a + n + 1};
      g.quads.quads.push_back(q);
      for (int k = 0; k < layers; ++k) {
        std::array<int, 8> h;
        for (int c = 0; c < 4; ++c) h[c] = q[c] * (layers + 1) + k, h[c + 4] = q[c] * (layers + 1) + k + 1;
        g.hexes.hexes.push_back(h);
      }
    }
  g.hexes.layers = layers;
  return g;
}

}  // namespace

// An oblique crossing: the middle column's ends are two walls' foot nodes 1 mm apart along x (0.5 mm off the column
// each way). That column runs straight between them, its inner nodes evenly; the columns round it lean by 3/4, 2/4,
// 1/4 of its offsets ring by ring; the fourth ring and the rim stay; no hex folds. On copies scaled by 1e-3 and 1e3.
TEST(JunctionMesh, AnObliqueCrossingLeansTheColumnsRoundIt) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    constexpr int m = 3, centre = 4 * 10 + 4;  // quad node (4, 4)
    SweptSheet g = sweptGrid(m, s);
    const HexMesh before = g.hexes;
    HexMesh walls;
    walls.nodes = {s * Vec3(7.5, 8, -1), s * Vec3(8.5, 8, 1)};
    std::vector<int> shared(g.hexes.nodes.size(), -1);
    shared[centre * (m + 1)] = 0, shared[centre * (m + 1) + m] = 1;
    leanCrossedColumns(g.hexes, g.quads, shared, walls);
    for (int k = 0; k <= m; ++k)
      EXPECT_NEAR(
          (g.hexes.nodes[centre * (m + 1) + k] - s * Vec3(7.5 + static_cast<double>(k) / m, 8, -1 + 2.0 * k / m))
              .norm(),
          0, 1e-12 * s);
    for (int i = 0; i <= 9; ++i) {
      const int q = 4 * 10 + i, ring = std::abs(i - 4);
      const double lean = ring <= 3 && i > 0 && i < 9 ? 1.0 - ring / 4.0 : 0;
      const Vec3 low = g.hexes.nodes[q * (m + 1)], high = g.hexes.nodes[q * (m + 1) + m];
      EXPECT_NEAR((low - before.nodes[q * (m + 1)]).x(), -0.5 * s * lean, 1e-12 * s) << "column " << i;
      EXPECT_NEAR((high - before.nodes[q * (m + 1) + m]).x(), 0.5 * s * lean, 1e-12 * s) << "column " << i;
    }
    for (std::size_t h = 0; h < g.hexes.hexes.size(); ++h) EXPECT_GT(hexScaledJacobian(hexCorners(g.hexes, h)), 0.5);
  }
}

// A column ending on a foot node whose middle node sits near that end (swept from a bend's chordal surface cutting
// its inside corner) gets it midway between the foot node and its other end; a column already even, and one on no
// foot, stay. Two layers: each column three nodes, bottom to top. Scaled by 1e-3 and 1e3.
TEST(JunctionMesh, AColumnOnAFootWithItsMiddleNearOneEndIsEvened) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    HexMesh sheet;
    sheet.layers = 2;
    sheet.nodes = {Vec3(0, 0, 0), Vec3(0, 0.4, 0.3), Vec3(0, 2, 2),   // uneven: its middle 0.4 from the bottom
                   Vec3(5, 0, 0), Vec3(5, 1, 1),     Vec3(5, 2, 2),   // even
                   Vec3(9, 0, 0), Vec3(9, 0.2, 0.1), Vec3(9, 2, 2)};  // uneven, on no foot
    for (Vec3& p : sheet.nodes) p *= s;
    HexMesh walls;
    walls.nodes = {Vec3(0, 0.1, 0) * s, Vec3(5, 0, 0) * s};  // the foot nodes under columns 0 and 1's bottoms
    std::vector<int> shared(sheet.nodes.size(), -1);
    shared[0] = 0, shared[3] = 1;
    const HexMesh before = sheet;
    evenFootColumns(sheet, 3, shared, walls);
    EXPECT_NEAR((sheet.nodes[1] - Vec3(0, 1.05, 1) * s).norm(), 0, 1e-12 * s);  // between (0, 0.1, 0) and (0, 2, 2)
    EXPECT_EQ(sheet.nodes[4], before.nodes[4]);
    EXPECT_EQ(sheet.nodes[7], before.nodes[7]);
  }
}
