// Tets (tets/tet_mesh.hpp, paper §4, §5.4): TetGen's Delaunay tets and their filter (flat, outside and coplanar
// tets), and the tets of a thin box's bubbles cut at its mid plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "bubbles/bubble_packing.hpp"
#include "chordal/chordal_surface.hpp"
#include "core/error.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"
#include "test_parts.hpp"
#include "tets/tet_mesh.hpp"

using namespace hexlayer;
using hexlayer::test_parts::box;

namespace {

double tetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

// Volume of the convex hull of points in general position (no 4 coplanar on the hull), by brute
// force: a triangle is a hull face when all other points are on one side of its plane.
double convexHullVolume(const std::vector<Vec3>& p) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : p) centre += x / p.size();
  double volume = 0;
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      for (size_t k = j + 1; k < n; ++k) {
        const Vec3 normal = (p[j] - p[i]).cross(p[k] - p[i]);
        int above = 0, below = 0;
        for (size_t l = 0; l < n; ++l) {
          if (l == i || l == j || l == k) continue;
          const double s = normal.dot(p[l] - p[i]);
          above += s > 0, below += s < 0;
        }
        if (above == 0 || below == 0) volume += std::abs(tetVolume(centre, p[i], p[j], p[k]));
      }
  return volume;
}

SurfaceNode node(const Vec3& p, Side side) {
  SurfaceNode n;
  n.point = p;
  n.side = side;
  return n;
}

}  // namespace

// TetGen tetrahedralizes the convex hull of the nodes: 8 corners of a perturbed box.
TEST(TetMesh, DelaunayTetsFillTheConvexHull) {
  const std::vector<Vec3> corners = {Vec3(0, 0, 0),   Vec3(3.1, 0, 0.05), Vec3(3, 2.2, 0),  Vec3(0.1, 2, -0.03),
                                     Vec3(0, 0.1, 1), Vec3(2.9, 0, 1.1),  Vec3(3, 2, 0.97), Vec3(-0.1, 2.05, 0.95)};
  std::vector<SurfaceNode> nodes;
  for (const Vec3& c : corners) nodes.push_back(node(c, c.z() > 0.5 ? Side::Top : Side::Bottom));
  const TetMesh mesh = delaunayTets(nodes);
  ASSERT_EQ(mesh.nodes.size(), 8u);
  ASSERT_EQ(mesh.side.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(mesh.nodes[i], corners[i]);
    EXPECT_EQ(mesh.side[i], nodes[i].side);
  }
  ASSERT_GE(mesh.tets.size(), 5u) << "a hexahedron needs at least 5 tets";
  double volume = 0;
  std::vector<int> used(8, 0);
  for (const auto& t : mesh.tets) {
    for (int v : t) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, 8);
      used[v] = 1;
    }
    const double v = std::abs(tetVolume(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]));
    EXPECT_GT(v, 1e-6);
    volume += v;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), 8) << "every corner is a tet node";
  const double hull = convexHullVolume(corners);
  EXPECT_GT(hull, 5.0);
  EXPECT_NEAR(volume, hull, 1e-9 * hull) << "the tets tile the hull without gaps or overlaps";
}

TEST(TetMesh, DelaunayTetsNeedFourNodes) {
  const std::vector<SurfaceNode> three = {node(Vec3(0, 0, 0), Side::Bottom), node(Vec3(1, 0, 0), Side::Bottom),
                                          node(Vec3(0, 1, 1), Side::Top)};
  EXPECT_THROW(delaunayTets(three), Error);
}

void addTetNode(TetMesh& m, const Vec3& p, Side s) {
  m.nodes.push_back(p);
  m.side.push_back(s);
}

// §5.4: flat tets (all four nodes on one side) are dropped, so are tets outside; coplanar ones are kept.
TEST(TetMesh, KeepSpanningTetsInsideDropsFlatAndOutsideTetsAndKeepsCoplanarOnes) {
  const CadSolid cad = box(10, 10, 2);
  TetMesh m;
  auto add = [&](const Vec3& p, Side s) { addTetNode(m, p, s); };
  add({1, 1, 2}, Side::Top);       // 0
  add({4, 1, 2}, Side::Top);       // 1
  add({1, 4, 2}, Side::Top);       // 2
  add({2, 2, 0}, Side::Bottom);    // 3
  add({3, 3, 0}, Side::Bottom);    // 4
  add({2, 2, 1.5}, Side::Top);     // 5: with 0 1 2 a flat top tet
  add({5, 2, 0}, Side::Bottom);    // 6
  add({2, 5, 0.5}, Side::Bottom);  // 7: with 3 4 6 a flat bottom tet
  add({12, 1, 2}, Side::Top);      // 8..11: a spanning tet beside the box
  add({15, 1, 2}, Side::Top);      // 9
  add({12, 4, 2}, Side::Top);      // 10
  add({13, 2, 0}, Side::Bottom);   // 11
  add({1, 1, 0}, Side::Bottom);    // 12: with 0 1 13 four nodes in the plane y = 1
  add({4, 1, 0}, Side::Bottom);    // 13
  add({2, 0.3, 2}, Side::Top);     // 14, 15: behind that plane (y < 1)
  add({3, 0.3, 0}, Side::Bottom);  // 15
  const std::array<int, 4> spanning31{0, 1, 2, 3}, flatTop{0, 1, 2, 5}, outside{8, 9, 10, 11}, coplanar{0, 1, 12, 13},
      flatBottom{3, 4, 6, 7}, spanning22{0, 1, 3, 4};
  // The coplanar tet between tets on its two sides: in front (y > 1) on its faces 0 1 12 and 1 13 12, behind
  // (y < 1) on its faces 0 1 13 and 0 13 12, as at a sharp bend.
  const std::array<int, 4> front1{0, 1, 12, 2}, front2{1, 13, 12, 4}, back1{0, 1, 13, 15}, back2{0, 13, 12, 14};
  m.tets = {spanning31, flatTop, outside, coplanar, flatBottom, spanning22, front1, front2, back1, back2};

  const TetFilterCounts counts = keepSpanningTetsInside(m, cad);
  EXPECT_EQ(counts.delaunay, 10u);
  EXPECT_EQ(counts.flat, 2u);
  EXPECT_EQ(counts.outside, 1u);
  EXPECT_EQ(counts.coplanar, 1u);
  ASSERT_EQ(m.tets.size(), 7u) << "the coplanar tet inside is kept: it joins the tets on its two sides";
  EXPECT_EQ(m.tets[0], spanning31);
  EXPECT_EQ(m.tets[1], coplanar);
  EXPECT_EQ(m.tets[2], spanning22);
  EXPECT_EQ(m.nodes.size(), 16u) << "nodes are kept";
}

// The same coplanar tet with tets on one side only (in front): it stands on the hull of the tets, in the
// plane where they end, as at a round rim (the hull plane runs inside the solid, far from its boundary).
TEST(TetMesh, CoplanarTetOnTheHullIsDropped) {
  const CadSolid cad = box(10, 10, 2);
  TetMesh m;
  auto add = [&](const Vec3& p, Side s) { addTetNode(m, p, s); };
  add({1, 5, 2}, Side::Top);     // 0
  add({4, 5, 2}, Side::Top);     // 1
  add({1, 5, 0}, Side::Bottom);  // 2
  add({4, 5, 0}, Side::Bottom);  // 3
  add({1, 8, 2}, Side::Top);     // 4
  add({3, 8, 0}, Side::Bottom);  // 5
  const std::array<int, 4> coplanar{0, 1, 2, 3}, front1{0, 1, 2, 4}, front2{1, 3, 2, 5};
  m.tets = {coplanar, front1, front2};

  const TetFilterCounts counts = keepSpanningTetsInside(m, cad);
  EXPECT_EQ(counts.outside, 1u);
  EXPECT_EQ(counts.coplanar, 0u);
  ASSERT_EQ(m.tets.size(), 2u);
  EXPECT_EQ(m.tets[0], front1);
  EXPECT_EQ(m.tets[1], front2);
}

// Two top and two bottom bubbles on the rim edges of a rounded corner, a little off the rim face (as
// sheet_metal_54's at (-3.4, 28, 3.4)): a sliver of the hull, dropped; a tet inside is not.
TEST(TetMesh, RimSliverSlightlyOffTheRimFaceIsDropped) {
  const CadSolid cad = box(10, 10, 2);
  TetMesh m;
  auto add = [&](const Vec3& p, Side s) { addTetNode(m, p, s); };
  add({1, 2.6e-4, 2}, Side::Top);  // 0, 1: on the rim edge y = 0, z = 2, just inside
  add({4, 2.2e-4, 2}, Side::Top);
  add({1.5, 1.5e-4, 0}, Side::Bottom);  // 2, 3: on the rim edge y = 0, z = 0
  add({3.5, 2.0e-4, 0}, Side::Bottom);
  add({2.5, 2, 0}, Side::Bottom);  // 4: inside
  const std::array<int, 4> sliver{0, 1, 2, 3}, inside{0, 1, 2, 4};
  ASSERT_FALSE(isCoplanarTet({m.nodes[0], m.nodes[1], m.nodes[2], m.nodes[4]}));
  ASSERT_TRUE(isCoplanarTet({m.nodes[0], m.nodes[1], m.nodes[2], m.nodes[3]}));
  m.tets = {sliver, inside};

  const TetFilterCounts counts = keepSpanningTetsInside(m, cad);
  EXPECT_EQ(counts.outside, 1u);
  EXPECT_EQ(counts.coplanar, 0u);
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], inside);
}

// Coplanar: height over the shortest edge, so a thin tet is flat but one with a tiny edge is not.
TEST(TetMesh, CoplanarTetIsFlatForItsShortestEdge) {
  const Vec3 a(0, 0, 0), b(1.5, 0, 0), c(0, 1.5, 0), d(1.5, 1.5, 0);
  EXPECT_TRUE(isCoplanarTet({a, b, c, d})) << "four nodes in one plane";
  EXPECT_TRUE(isCoplanarTet({a, b, c, Vec3(1.5, 1.5, 1e-5)})) << "1e-5 off over 1.5 mm edges";
  EXPECT_FALSE(isCoplanarTet({a, b, c, Vec3(1.5, 1.5, 1e-3)})) << "1e-3 off: a thin tet, not a plane";
  EXPECT_FALSE(isCoplanarTet({a, b, c, Vec3(0.5, 0.5, 1)})) << "a tet of fair shape";
  // The U-channel's 0.002 mm tunnel: flat only because one edge is 0.002 mm long.
  EXPECT_FALSE(
      isCoplanarTet({Vec3(1.5, 0.002, 1.5), Vec3(1.502, 0.002, 0), Vec3(1.502, 0.002, 1.5), Vec3(1.502, 0, 0)}));
}

// The thin box end to end up to the chordal surface: Delaunay tets of the bubble nodes, filtered,
// fill the plate exactly, and their chordal surface is the mid plane z = 1 with radius 1.
TEST(TetMesh, ThinBoxTetsFillThePlateAndCutAtMidPlane) {
  const CadSolid cad = box(40, 30, 2);
  const WallSides w = classifyWallSides(cad);
  TetMesh tets = delaunayTets(packBubbles(cad, w, BubbleOptions{}));
  double hull = 0;  // the hull of the nodes is the box: only flat slivers on its rim faces are outside
  for (const auto& t : tets.tets)
    hull += std::abs(tetVolume(tets.nodes[t[0]], tets.nodes[t[1]], tets.nodes[t[2]], tets.nodes[t[3]]));
  const TetFilterCounts counts = keepSpanningTetsInside(tets, cad);
  EXPECT_EQ(counts.delaunay, tets.tets.size() + counts.flat + counts.outside);
  double volume = 0;
  for (const auto& t : tets.tets) {
    int top = 0;
    for (int v : t) top += tets.side[v] == Side::Top;
    EXPECT_GT(top, 0);
    EXPECT_LT(top, 4);
    volume += std::abs(tetVolume(tets.nodes[t[0]], tets.nodes[t[1]], tets.nodes[t[2]], tets.nodes[t[3]]));
  }
  EXPECT_NEAR(volume, 2400.0, 1e-6 * 2400);
  EXPECT_NEAR(hull, 2400.0, 1e-6 * 2400) << "what was dropped had no volume (flat tets and rim slivers)";

  ChordalSurface s = buildChordalSurface(tets);
  computeNormalsAndRadius(s, tets);
  double area = 0;
  for (const auto& f : s.facets) {
    const auto& v = s.vertices;
    area += f[3] < 0 ? 0.5 * (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]).norm()
                     : 0.5 * (v[f[2]] - v[f[0]]).cross(v[f[3]] - v[f[1]]).norm();
    EXPECT_GT(facetNormal(s, f).z(), 1 - 1e-9);
  }
  EXPECT_NEAR(area, 1200.0, 1e-6 * 1200);
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    EXPECT_NEAR(s.vertices[v].z(), 1.0, 1e-9);
    EXPECT_LT((s.normals[v] - Vec3::UnitZ()).norm(), 1e-9);
    EXPECT_NEAR(s.radius[v], 1.0, 1e-9);
  }
}
