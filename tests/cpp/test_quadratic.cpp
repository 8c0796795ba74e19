// Quadratic hexes (sweep/quadratic.hpp): one mid-edge node per edge shared by its hexes, in C3D20
// order, wall nodes handed to the projection and inner-layer nodes between the walls' ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/error.hpp"
#include "quality/quality.hpp"
#include "sweep/quadratic.hpp"

using namespace hexlayer;

namespace {

// nx x ny unit quads swept through m layers along z: node (i, j, k) at (i, j, height(k)) with id
// i + (nx + 1) (j + (ny + 1) k); on the rim if i or j is on the grid's border.
HexMesh block(int nx, int ny, int m, const std::vector<double>& height) {
  HexMesh mesh;
  mesh.layers = m;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= m; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        mesh.nodes.emplace_back(i, j, height[k]);
        mesh.nodeLayer.push_back(k);
        mesh.nodeOnRim.push_back(i == 0 || j == 0 || i == nx || j == ny);
      }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      for (int k = 0; k < m; ++k)
        mesh.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                              id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return mesh;
}

// Mid-edge nodes an nx x ny x m block has: in-plane edges of m + 1 layers plus the sweep edges.
std::size_t edgeCount(int nx, int ny, int m) {
  return static_cast<std::size_t>((m + 1) * (nx * (ny + 1) + ny * (nx + 1)) + m * (nx + 1) * (ny + 1));
}

std::optional<FacePoint> keep(Side, const Vec3& p) { return FacePoint{p, -1}; }

// An affine map of space (shear, stretch, shift): edges stay straight and midpoints stay midpoints.
Vec3 affine(const Vec3& p) {
  Eigen::Matrix3d a;
  a << 2.0, 0.5, 0.1, -0.3, 1.5, 0.2, 0.1, 0.0, 0.7;
  return a * p + Vec3(10, -4, 3);
}

}  // namespace

TEST(Quadratic, MidEdgeNodesAreSharedOncePerEdge) {
  HexMesh mesh = block(2, 2, 2, {0, 1, 2});
  const QuadraticStats s = addMidEdgeNodes(mesh, keep);
  EXPECT_EQ(edgeCount(2, 2, 2), 54u);  // 3 layers x 12 in-plane edges + 9 sweep lines x 2
  EXPECT_EQ(s.midNodes, 54u);
  EXPECT_EQ(mesh.nodes.size(), 27u + 54u);
  ASSERT_EQ(mesh.midEdges.size(), mesh.hexes.size());
  EXPECT_TRUE(mesh.quadratic());
  EXPECT_EQ(mesh.nodeLayer.size(), mesh.nodes.size());
  EXPECT_EQ(mesh.nodeOnRim.size(), mesh.nodes.size());
  std::map<int, int> uses;
  for (const auto& mids : mesh.midEdges) {
    EXPECT_EQ(std::set<int>(mids.begin(), mids.end()).size(), 12u);
    for (int n : mids) ++uses[n];
  }
  EXPECT_EQ(uses.size(), 54u);
  EXPECT_EQ(uses.begin()->first, 27);  // mid-edge nodes come after the corners
  std::map<int, int> edgesUsedBy;      // an edge of a block is used by 1, 2 or 4 hexes
  for (const auto& [node, n] : uses) ++edgesUsedBy[n];
  EXPECT_EQ(edgesUsedBy, (std::map<int, int>{{1, 24}, {2, 24}, {4, 6}}));
  EXPECT_EQ(countCoincidentNodes(mesh, 1e-9), 0u);  // no duplicated node
}

TEST(Quadratic, LargerBlocksFollowTheEdgeCountFormula) {
  for (const auto& [nx, ny, m] : {std::array<int, 3>{1, 1, 1}, {3, 2, 1}, {4, 3, 5}}) {
    HexMesh mesh = block(nx, ny, m, std::vector<double>(m + 1, 0.0));
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) mesh.nodes[i].z() = mesh.nodeLayer[i];
    EXPECT_EQ(addMidEdgeNodes(mesh, keep).midNodes, edgeCount(nx, ny, m)) << nx << " " << ny << " " << m;
  }
}

TEST(Quadratic, MidEdgeNodeSitsBetweenTheC3D20CornerPair) {
  HexMesh mesh = block(2, 2, 2, {0, 0.4, 1.2});
  for (Vec3& p : mesh.nodes) p = affine(p);
  addMidEdgeNodes(mesh, keep);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (int e = 0; e < 12; ++e) {
      const Vec3 mid = 0.5 * (mesh.nodes[mesh.hexes[h][kHexEdges[e][0]]] + mesh.nodes[mesh.hexes[h][kHexEdges[e][1]]]);
      EXPECT_LT((mesh.nodes[mesh.midEdges[h][e]] - mid).norm(), 1e-12) << "hex " << h << " edge " << e;
    }
  // C3D20 order spelled out for the first hex: 9-12 bottom, 13-16 top, 17-20 along the sweep.
  const std::array<std::array<int, 2>, 12> c3d20 = {
      {{1, 2}, {2, 3}, {3, 4}, {4, 1}, {5, 6}, {6, 7}, {7, 8}, {8, 5}, {1, 5}, {2, 6}, {3, 7}, {4, 8}}};
  for (int e = 0; e < 12; ++e) EXPECT_EQ(kHexEdges[e], (std::array<int, 2>{c3d20[e][0] - 1, c3d20[e][1] - 1}));
}

TEST(Quadratic, LayerAndRimOfMidEdgeNodes) {
  HexMesh mesh = block(2, 2, 2, {0, 1, 2});
  addMidEdgeNodes(mesh, keep);
  std::map<int, int> perLayer;
  int rim = 0;
  for (std::size_t i = 27; i < mesh.nodes.size(); ++i) {
    ++perLayer[mesh.nodeLayer[i]];
    rim += mesh.nodeOnRim[i];
    const double z = mesh.nodes[i].z();
    EXPECT_EQ(mesh.nodeLayer[i], z == 0.5 || z == 1.5 ? -1 : static_cast<int>(z));
  }
  EXPECT_EQ(perLayer, (std::map<int, int>{{-1, 18}, {0, 12}, {1, 12}, {2, 12}}));
  EXPECT_EQ(rim, 3 * 8 + 2 * 8);  // 8 border edges per layer, 8 border sweep lines with 2 edges each
}

TEST(Quadratic, ProjectionIsAskedForWallEdgesOnlyAndInnerLayersFollow) {
  HexMesh mesh = block(2, 2, 2, {0, 1, 2});
  mesh.nodeFace.assign(mesh.nodes.size(), -1);
  std::vector<std::pair<Side, Vec3>> asked;
  const Vec3 lift(0, 0, 0.1), drop(0, 0, -0.2);  // both within a quarter of the unit edges
  addMidEdgeNodes(mesh, [&](Side side, const Vec3& p) -> std::optional<FacePoint> {
    if (side == Side::Lateral) return std::nullopt;  // rim nodes: see the next test
    asked.emplace_back(side, p);
    return FacePoint{p + (side == Side::Top ? lift : drop), side == Side::Top ? 7 : 3};
  });
  ASSERT_EQ(asked.size(), 24u);  // 12 in-plane edges on each wall
  for (const auto& [side, p] : asked) EXPECT_EQ(p.z(), side == Side::Top ? 2.0 : 0.0);
  for (std::size_t i = 27; i < mesh.nodes.size(); ++i) {
    const int k = mesh.nodeLayer[i];
    const double z = mesh.nodes[i].z();
    if (k == 2) EXPECT_DOUBLE_EQ(z, 2.1);
    if (k == 0) EXPECT_DOUBLE_EQ(z, -0.2);
    EXPECT_EQ(mesh.nodeFace[i], k == 2 ? 7 : k == 0 ? 3 : -1) << "the face of the projection, wall nodes only";
    // Inner edges half way between the walls' mid-edge nodes; a rim edge of the inner layer joins two rim nodes
    // and starts from their midpoint (here it stays there: no lateral face to project onto).
    if (k == 1) EXPECT_DOUBLE_EQ(z, mesh.nodeOnRim[i] ? 1.0 : 0.5 * (2.1 - 0.2));
    if (k == -1) EXPECT_TRUE(z == 0.5 || z == 1.5);  // sweep edges: plain midpoints
  }
}

TEST(Quadratic, RimNodesAreProjectedOntoTheLateralFacesLast) {
  HexMesh mesh = block(2, 2, 2, {0, 1, 2});
  mesh.nodeFace.assign(mesh.nodes.size(), -1);
  std::size_t lateral = 0;
  const QuadraticStats s = addMidEdgeNodes(mesh, [&](Side side, const Vec3& p) -> std::optional<FacePoint> {
    if (side != Side::Lateral)
      return FacePoint{p + Vec3(0, 0, side == Side::Top ? 0.1 : -0.1), side == Side::Top ? 7 : 3};
    ++lateral;
    if (p.x() == 0) return FacePoint{p + Vec3(-0.3, 0, 0), 2};  // more than a quarter of the unit edges: refused
    return FacePoint{p + Vec3(0.01, 0, 0), 1};
  });
  EXPECT_EQ(lateral, 3u * 8 + 2u * 8) << "8 border edges per node layer, 8 border sweep lines with 2 edges";
  EXPECT_EQ(s.rimNodes, lateral);
  EXPECT_EQ(s.rimProjected, lateral - (3 * 2 + 2 * 3)) << "the x = 0 side: 2 edges per layer and 3 sweep lines of 2";
  for (std::size_t i = 27; i < mesh.nodes.size(); ++i) {
    if (!mesh.nodeOnRim[i]) continue;
    const int k = mesh.nodeLayer[i];
    const bool refused = mesh.nodes[i].x() <= 0;  // at x = 0 (or -0.3 if it had been projected)
    EXPECT_EQ(mesh.nodeFace[i], refused ? (k == 2 ? 7 : k == 0 ? 3 : -1) : 1) << i;
    if (k == 2) EXPECT_DOUBLE_EQ(mesh.nodes[i].z(), 2.1) << "on the wall, then moved along it";
  }
}

TEST(Quadratic, InnerMidEdgeNodeTakesTheMeanFractionOfItsEnds) {
  HexMesh mesh = block(1, 1, 2, {0, 0.5, 1});
  mesh.nodes[4 + 1].z() = 0.3;  // node (1, 0) of the middle layer: fraction 0.3 on its sweep line
  addMidEdgeNodes(mesh, keep);
  const Vec3 m = mesh.nodes[mesh.midEdges[1][0]];  // upper hex, edge 0-1 lies in the middle layer
  EXPECT_EQ(mesh.nodeLayer[mesh.midEdges[1][0]], 1);
  EXPECT_DOUBLE_EQ(m.z(), 0.5 * (0.5 + 0.3));
  EXPECT_DOUBLE_EQ(m.x(), 0.5);
}

TEST(Quadratic, FarOrFailedProjectionKeepsTheMidpoint) {
  HexMesh mesh = block(1, 1, 1, {0, 1});
  const QuadraticStats s = addMidEdgeNodes(mesh, [](Side side, const Vec3& p) -> std::optional<FacePoint> {
    if (side != Side::Top) return std::nullopt;
    return FacePoint{p + Vec3(0, 0, p.x() == 0.5 ? 0.2 : 0.3),
                     5};  // edges along x move 0.2 (kept), along y 0.3 (> 1/4)
  });
  EXPECT_EQ(s.wallNodes, 8u);
  EXPECT_EQ(s.projected, 2u);
  EXPECT_NEAR(s.maxProjectionMove, 0.2, 1e-12);
  const std::array<double, 12> z = {0, 0, 0, 0, 1.2, 1, 1.2, 1, 0.5, 0.5, 0.5, 0.5};  // per edge, C3D20 order
  for (int e = 0; e < 12; ++e) EXPECT_NEAR(mesh.nodes[mesh.midEdges[0][e]].z(), z[e], 1e-12) << e;
}

TEST(Quadratic, RefusesAQuadraticMeshOrOneWithoutLayers) {
  HexMesh mesh = block(1, 1, 1, {0, 1});
  addMidEdgeNodes(mesh, keep);
  EXPECT_THROW(addMidEdgeNodes(mesh, keep), Error);
  HexMesh bare = block(1, 1, 1, {0, 1});
  bare.nodeLayer.clear();
  EXPECT_THROW(addMidEdgeNodes(bare, keep), Error);
}
