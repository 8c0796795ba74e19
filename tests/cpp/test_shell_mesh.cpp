// The mid-surface shell (pipeline/shell_mesh.hpp) of a meshed 40 x 30 x 2 box, in millimetres and in metres: its
// nodes on the mid-plane z = 1, the thickness 2 at every node, its area the box's 1200, its quads turned one way,
// mid-side nodes at the edges' midpoints, and the node sets per face checked against the coordinates (MakeBox
// numbers the faces like FreeCAD: Face1 x = 0, Face2 x = 40, Face3 y = 0, Face4 y = 30, Face5 z = 0, Face6 z = 2).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include <cmath>
#include <set>

#include "pipeline/pipeline.hpp"
#include "pipeline/shell_mesh.hpp"

using namespace hexlayer;

namespace {

// The box [0, 40 s] x [0, 30 s] x [0, 2 s] meshed with a shell of the given order, 2 s quads.
MeshResult boxShell(double s, int order, int layers = 2) {
  MeshOptions o;
  o.layers = layers, o.size = 2 * s, o.order = order, o.shell = true;
  return meshSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40 * s, 30 * s, 2 * s).Solid(), o);
}

// The shell nodes whose coordinate `axis` is `value` (within 1e-9 of the box's size s).
std::vector<int> nodesAt(const ShellMesh& shell, int axis, double value, double s) {
  std::vector<int> ids;
  for (std::size_t i = 0; i < shell.nodes.size(); ++i)
    if (std::abs(shell.nodes[i][axis] - value) < 1e-9 * s) ids.push_back(static_cast<int>(i));
  return ids;
}

class BoxShell : public ::testing::TestWithParam<std::tuple<double, int>> {};

}  // namespace

TEST_P(BoxShell, LiesOnTheMidPlaneWithTheWallThicknessAndTheBoxArea) {
  const auto [s, order] = GetParam();
  const MeshResult r = boxShell(s, order);
  const ShellMesh& shell = r.shell;
  EXPECT_EQ(shell.quads.size(), r.quadMesh.quads.size());
  EXPECT_EQ(shell.quadratic(), order == 2);
  // Order 2: one mid-side node per edge of the quad mesh of a disc, E = V + F - 1 (Euler).
  const std::size_t corners = r.quadMesh.nodes.size();
  EXPECT_EQ(shell.nodes.size(), order == 2 ? 2 * corners + shell.quads.size() - 1 : corners);
  ASSERT_EQ(shell.thickness.size(), shell.nodes.size());
  for (std::size_t i = 0; i < shell.nodes.size(); ++i) {
    // On the chordal surface: within 1e-9 s in millimetres; in metres (scaled to another size by normalizingUnit) the
    // chordal surface is off the mid-plane by up to 6.4e-3 s, the thickness measured along its normal by 1.5e-5 s.
    EXPECT_NEAR(shell.nodes[i].z(), s, 1e-2 * s) << "node " << i;
    EXPECT_NEAR(shell.thickness[i], 2 * s, 1e-4 * s) << "node " << i;
  }
  const ShellRecord record = *r.report.shell;
  EXPECT_NEAR(record.area, 1200 * s * s, 1e-4 * s * s);
  EXPECT_NEAR(record.cadMidSurfaceArea, 1200 * s * s, 1e-9 * s * s);
  EXPECT_NEAR(record.thicknessMedian, 2 * s, 1e-4 * s);
  EXPECT_EQ(record.elements, shell.quads.size());
  // Every quad turned the same way (its normal along the sweep, from the bottom wall to the top wall).
  std::set<int> signs;
  for (const auto& q : shell.quads)
    signs.insert((shell.nodes[q[2]] - shell.nodes[q[0]]).cross(shell.nodes[q[3]] - shell.nodes[q[1]]).z() > 0);
  EXPECT_EQ(signs.size(), 1u);
  for (std::size_t e = 0; e < shell.midSides.size(); ++e)
    for (int k = 0; k < 4; ++k) {
      const Vec3 mid = 0.5 * (shell.nodes[shell.quads[e][k]] + shell.nodes[shell.quads[e][(k + 1) % 4]]);
      EXPECT_LT((shell.nodes[shell.midSides[e][k]] - mid).norm(), 1e-2 * s);
    }
}

TEST_P(BoxShell, FaceSetsHoldTheNodesOnTheEndsOrOnTheWalls) {
  const auto [s, order] = GetParam();
  const ShellMesh shell = boxShell(s, order).shell;
  ASSERT_EQ(shell.faces.size(), 6u);
  const std::array<std::pair<int, double>, 4> rims = {{{0, 0}, {0, 40}, {1, 0}, {1, 30}}};
  for (int f = 0; f < 4; ++f) {
    EXPECT_EQ(shell.faces[f].name, "Face" + std::to_string(f + 1));
    EXPECT_EQ(shell.faces[f].nodes, nodesAt(shell, rims[f].first, rims[f].second * s, s)) << shell.faces[f].name;
    EXPECT_GT(shell.faces[f].nodes.size(), 5u);
  }
  std::vector<int> all(shell.nodes.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  EXPECT_EQ(shell.faces[4].nodes, all) << "every sweep line ends on the bottom wall";
  EXPECT_EQ(shell.faces[5].nodes, all) << "and on the top wall";
  std::set<int> rim;
  for (int f = 0; f < 4; ++f) rim.insert(shell.faces[f].nodes.begin(), shell.faces[f].nodes.end());
  ASSERT_EQ(shell.nodeSets.size(), 1u);
  EXPECT_EQ(shell.nodeSets[0].name, "RIM");
  EXPECT_EQ(shell.nodeSets[0].nodes, std::vector<int>(rim.begin(), rim.end()));
}

INSTANTIATE_TEST_SUITE_P(UnitsAndOrders, BoxShell,
                         ::testing::Combine(::testing::Values(1.0, 1e-3), ::testing::Values(1, 2)));

// An odd number of layers has no node layer on the chordal surface: the shell is the same.
TEST(ShellMesh, ThreeLayersGiveTheSameShellAsTwo) {
  const ShellMesh two = boxShell(1, 2, 2).shell, three = boxShell(1, 2, 3).shell;
  ASSERT_EQ(two.nodes.size(), three.nodes.size());
  for (std::size_t i = 0; i < two.nodes.size(); ++i) {
    EXPECT_LT((two.nodes[i] - three.nodes[i]).norm(), 1e-9);
    EXPECT_NEAR(two.thickness[i], three.thickness[i], 1e-6);
  }
}

// Without MeshOptions::shell nothing is built and the report has no shell.
TEST(ShellMesh, OnlyWhenAskedFor) {
  MeshOptions o;
  o.size = 2;
  const MeshResult r = meshSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid(), o);
  EXPECT_TRUE(r.shell.quads.empty());
  EXPECT_FALSE(r.report.shell.has_value());
}

TEST(ShellMesh, MeasureShellGivesTheMedianOfTheNodes) {
  ShellMesh s;
  s.nodes = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  s.quads = {{0, 1, 2, 3}};
  s.thickness = {1, 4, 2, 3};
  const ShellRecord r = measureShell(s, 2.5);
  EXPECT_EQ(r.order, 1);
  EXPECT_EQ(r.thicknessMin, 1);
  EXPECT_EQ(r.thicknessMedian, 2.5);
  EXPECT_EQ(r.thicknessMax, 4);
  EXPECT_DOUBLE_EQ(r.area, 2);
  EXPECT_DOUBLE_EQ(r.relativeAreaError(), -0.2);
}
