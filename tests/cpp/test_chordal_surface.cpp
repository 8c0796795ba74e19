// Chordal surface (paper §5): cutting hand-made tets at the midpoints of their top-bottom edges,
// facet orientation, the normal and radius at the vertices (Eq. 1-3) and the tet classes (Table 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "chordal/chordal_surface.hpp"
#include "core/error.hpp"

using namespace hexlayer;

namespace {

struct Node {
  Vec3 p;
  Side side;
};

TetMesh makeTets(const std::vector<Node>& nodes, const std::vector<std::array<int, 4>>& tets) {
  TetMesh m;
  for (const Node& n : nodes) {
    m.nodes.push_back(n.p);
    m.side.push_back(n.side);
  }
  m.tets = tets;
  return m;
}

// The same tets with every node moved by the rigid motion x -> R x + t.
TetMesh moved(TetMesh m, const Eigen::Matrix3d& R, const Vec3& t) {
  for (Vec3& p : m.nodes) p = R * p + t;
  return m;
}

Eigen::Matrix3d someRotation() {
  return (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-0.4, Vec3::UnitX()))
      .toRotationMatrix();
}

// All 24 orders of the corners of tet {0, 1, 2, 3}.
std::vector<std::array<int, 4>> allOrders() {
  std::array<int, 4> t{0, 1, 2, 3};
  std::vector<std::array<int, 4>> out;
  do out.push_back(t);
  while (std::next_permutation(t.begin(), t.end()));
  return out;
}

int corners(const std::array<int, 4>& f) { return f[3] < 0 ? 3 : 4; }

// Mean of the top nodes minus mean of the bottom nodes of the whole mesh.
Vec3 upward(const TetMesh& m) {
  Vec3 top = Vec3::Zero(), bottom = Vec3::Zero();
  int nt = 0, nb = 0;
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (m.side[i] == Side::Top)
      top += m.nodes[i], ++nt;
    else
      bottom += m.nodes[i], ++nb;
  return top / nt - bottom / nb;
}

// Area of a facet: half the cross product of the diagonals (quad) or of two edges (triangle).
double facetArea(const ChordalSurface& s, const std::array<int, 4>& f) {
  const auto& v = s.vertices;
  if (f[3] < 0) return 0.5 * (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]).norm();
  return 0.5 * (v[f[2]] - v[f[0]]).cross(v[f[3]] - v[f[1]]).norm();
}

// Index of the chordal vertex at point p, -1 if none.
int vertexAt(const ChordalSurface& s, const Vec3& p) {
  for (size_t i = 0; i < s.vertices.size(); ++i)
    if ((s.vertices[i] - p).norm() < 1e-12) return static_cast<int>(i);
  return -1;
}

// Every chordal vertex is the exact midpoint of its (top, bottom) tet edge.
void expectVerticesAreEdgeMidpoints(const ChordalSurface& s, const TetMesh& m) {
  ASSERT_EQ(s.tetEdge.size(), s.vertices.size());
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    const auto [t, b] = s.tetEdge[i];
    EXPECT_EQ(m.side[t], Side::Top) << "vertex " << i;
    EXPECT_EQ(m.side[b], Side::Bottom) << "vertex " << i;
    EXPECT_LT((s.vertices[i] - 0.5 * (m.nodes[t] + m.nodes[b])).norm(), 1e-14) << "vertex " << i;
  }
}

template <class F>
void expectGeometryError(F&& f, const std::string& words) {
  try {
    f();
    FAIL() << "no hexlayer::Error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::UnsupportedGeometry);
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// A 2-2 tet: top edge along x at z = 1, bottom edge along y at z = 0, crossing above (0.5, 0.5).
const std::vector<Node> kTwoTwo = {{Vec3(0, 0.5, 1), Side::Top},
                                   {Vec3(1, 0.5, 1), Side::Top},
                                   {Vec3(0.5, 0, 0), Side::Bottom},
                                   {Vec3(0.5, 1, 0), Side::Bottom}};

// A 3-1 tet (three top nodes at z = 1 over one bottom node) and a 1-3 tet.
const std::vector<Node> kThreeOne = {{Vec3(0, 0, 1), Side::Top},
                                     {Vec3(1, 0, 1), Side::Top},
                                     {Vec3(0, 1, 1), Side::Top},
                                     {Vec3(0.2, 0.3, 0), Side::Bottom}};
const std::vector<Node> kOneThree = {{Vec3(0, 0, 0), Side::Bottom},
                                     {Vec3(1, 0, 0), Side::Bottom},
                                     {Vec3(0, 1, 0), Side::Bottom},
                                     {Vec3(0.2, 0.3, 1), Side::Top}};

}  // namespace

// (a) A 2-2 tet is cut into one quad whose corners are the midpoints of the four top-bottom edges.
TEST(ChordalSurface, TwoTwoTetGivesOneQuadAtEdgeMidpoints) {
  const std::vector<Vec3> expected = {Vec3(0.25, 0.25, 0.5), Vec3(0.75, 0.25, 0.5), Vec3(0.75, 0.75, 0.5),
                                      Vec3(0.25, 0.75, 0.5)};
  for (const auto& order : allOrders()) {
    SCOPED_TRACE(testing::Message() << "tet order " << order[0] << order[1] << order[2] << order[3]);
    const TetMesh m = makeTets(kTwoTwo, {order});
    const ChordalSurface s = buildChordalSurface(m);
    ASSERT_EQ(s.facets.size(), 1u);
    EXPECT_EQ(s.quads, 1u);
    EXPECT_EQ(s.triangles, 0u);
    ASSERT_EQ(s.vertices.size(), 4u);
    expectVerticesAreEdgeMidpoints(s, m);
    const auto& f = s.facets[0];
    ASSERT_GE(f[3], 0) << "a 2-2 tet gives a quad";
    std::set<int> seen;
    for (const Vec3& p : expected) {
      const int v = vertexAt(s, p);
      EXPECT_GE(v, 0) << "no chordal vertex at " << p.transpose();
      seen.insert(v);
    }
    EXPECT_EQ(seen, (std::set<int>{f[0], f[1], f[2], f[3]}));
    // A proper cycle, not a bow tie: consecutive corners come from tet edges sharing one node.
    for (int k = 0; k < 4; ++k) {
      const auto a = s.tetEdge[f[k]], b = s.tetEdge[f[(k + 1) % 4]];
      EXPECT_EQ((a[0] == b[0]) + (a[1] == b[1]), 1) << "corners " << k << " and " << (k + 1) % 4;
    }
    EXPECT_NEAR(facetArea(s, f), 0.25, 1e-14);
    // Oriented towards the top nodes.
    EXPECT_LT((facetNormal(s, f) - Vec3::UnitZ()).norm(), 1e-14);
  }
}

TEST(ChordalSurface, TwoTwoTetFacetFacesTopAfterRigidMotion) {
  const Eigen::Matrix3d R = someRotation();
  for (const auto& order : allOrders()) {
    const TetMesh m = moved(makeTets(kTwoTwo, {order}), R, Vec3(3, -2, 5));
    const ChordalSurface s = buildChordalSurface(m);
    ASSERT_EQ(s.facets.size(), 1u);
    expectVerticesAreEdgeMidpoints(s, m);
    EXPECT_NEAR(facetNormal(s, s.facets[0]).dot(R * Vec3::UnitZ()), 1.0, 1e-12);
    EXPECT_GT(facetNormal(s, s.facets[0]).dot(upward(m)), 0);
  }
}

// (b) A 3-1 and a 1-3 tet give one triangle each, at the midpoints of the edges at the lone node.
TEST(ChordalSurface, ThreeOneAndOneThreeTetsGiveOneTriangleFacingTop) {
  struct Case {
    const std::vector<Node>* nodes;
    std::vector<Vec3> expected;
  };
  const std::vector<Case> cases = {{&kThreeOne, {Vec3(0.1, 0.15, 0.5), Vec3(0.6, 0.15, 0.5), Vec3(0.1, 0.65, 0.5)}},
                                   {&kOneThree, {Vec3(0.1, 0.15, 0.5), Vec3(0.6, 0.15, 0.5), Vec3(0.1, 0.65, 0.5)}}};
  const Eigen::Matrix3d R = someRotation();
  for (const Case& c : cases)
    for (const auto& order : allOrders()) {
      SCOPED_TRACE(testing::Message() << (c.nodes == &kThreeOne ? "3-1" : "1-3") << " order " << order[0] << order[1]
                                      << order[2] << order[3]);
      const TetMesh m = makeTets(*c.nodes, {order});
      const ChordalSurface s = buildChordalSurface(m);
      ASSERT_EQ(s.facets.size(), 1u);
      EXPECT_EQ(s.triangles, 1u);
      EXPECT_EQ(s.quads, 0u);
      EXPECT_EQ(s.facets[0][3], -1);
      ASSERT_EQ(s.vertices.size(), 3u);
      expectVerticesAreEdgeMidpoints(s, m);
      for (const Vec3& p : c.expected) EXPECT_GE(vertexAt(s, p), 0) << "no chordal vertex at " << p.transpose();
      EXPECT_LT((facetNormal(s, s.facets[0]) - Vec3::UnitZ()).norm(), 1e-14);

      const TetMesh r = moved(m, R, Vec3(-1, 4, 2));
      const ChordalSurface sr = buildChordalSurface(r);
      ASSERT_EQ(sr.facets.size(), 1u);
      EXPECT_NEAR(facetNormal(sr, sr.facets[0]).dot(R * Vec3::UnitZ()), 1.0, 1e-12);
    }
}

// (c) A prism (3 top nodes at z = 2 over 3 bottom nodes at z = 0) split into 3 tets.
namespace {
TetMesh prismSlab(const Vec3& topShift) {
  const std::vector<Node> nodes = {{Vec3(0, 0, 0), Side::Bottom},         {Vec3(1, 0, 0), Side::Bottom},
                                   {Vec3(0, 1, 0), Side::Bottom},         {Vec3(0, 0, 2) + topShift, Side::Top},
                                   {Vec3(1, 0, 2) + topShift, Side::Top}, {Vec3(0, 1, 2) + topShift, Side::Top}};
  // a0 a1 a2 b0 (3-1 from the bottom's view: 1 top node), a1 a2 b0 b1 (2-2), a2 b0 b1 b2 (1 bottom).
  return makeTets(nodes, {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}});
}
}  // namespace

TEST(ChordalSurface, PrismSlabGivesPlanarSharedSurfaceAtMidHeight) {
  const TetMesh m = prismSlab(Vec3::Zero());
  ChordalSurface s = buildChordalSurface(m);
  ASSERT_EQ(s.facets.size(), 3u);
  EXPECT_EQ(s.triangles, 2u);
  EXPECT_EQ(s.quads, 1u);
  // Distinct top-bottom edges of the three tets: a0b0 a1b0 a2b0 a1b1 a2b1 a2b2.
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.tets)
    for (int i : t)
      for (int j : t)
        if (m.side[i] == Side::Top && m.side[j] == Side::Bottom) edges.insert({i, j});
  ASSERT_EQ(edges.size(), 6u);
  EXPECT_EQ(s.vertices.size(), edges.size()) << "every chordal vertex is shared by the tets around its edge";
  expectVerticesAreEdgeMidpoints(s, m);
  for (const Vec3& v : s.vertices) EXPECT_NEAR(v.z(), 1.0, 1e-15);

  double area = 0;
  std::map<std::pair<int, int>, int> edgeUse;
  for (const auto& f : s.facets) {
    EXPECT_LT((facetNormal(s, f) - Vec3::UnitZ()).norm(), 1e-14);
    area += facetArea(s, f);
    for (int k = 0; k < corners(f); ++k)
      ++edgeUse[{std::min(f[k], f[(k + 1) % corners(f)]), std::max(f[k], f[(k + 1) % corners(f)])}];
  }
  EXPECT_NEAR(area, 0.5, 1e-14) << "the facets tile the prism's cross-section without overlap";
  int interior = 0, boundary = 0;
  for (const auto& [e, uses] : edgeUse) {
    EXPECT_LE(uses, 2);
    (uses == 2 ? interior : boundary)++;
  }
  EXPECT_EQ(interior, 2) << "triangle-quad and quad-triangle share one edge each";
  EXPECT_EQ(boundary, 6);

  computeNormalsAndRadius(s, m);
  ASSERT_EQ(s.normals.size(), s.vertices.size());
  ASSERT_EQ(s.radius.size(), s.vertices.size());
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    EXPECT_LT((s.normals[v] - Vec3::UnitZ()).norm(), 1e-14) << "vertex " << v;
    EXPECT_NEAR(s.radius[v], 1.0, 1e-14) << "vertex " << v;
  }
}

// Eq. 3 takes the component of l = v_t - v along the normal, not |l|: on a sheared slab the
// top-bottom edges lean, but the radius is still half the thickness.
TEST(ChordalSurface, RadiusIsNormalComponentOnShearedSlab) {
  const TetMesh m = prismSlab(Vec3(0.6, 0.3, 0));
  ChordalSurface s = buildChordalSurface(m);
  ASSERT_EQ(s.vertices.size(), 6u);
  computeNormalsAndRadius(s, m);
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    EXPECT_NEAR(s.vertices[v].z(), 1.0, 1e-15);
    EXPECT_LT((s.normals[v] - Vec3::UnitZ()).norm(), 1e-14) << "vertex " << v;
    EXPECT_NEAR(s.radius[v], 1.0, 1e-14) << "vertex " << v;
    EXPECT_GT((m.nodes[s.tetEdge[v][0]] - s.vertices[v]).norm(), 1.02) << "the edge leans: |l| > r";
  }
}

// Eq. 2: the vertex normal is the normalized mean of the normals of the facets around it.
TEST(ChordalSurface, VertexNormalAveragesFacetNormals) {
  // Two 3-1 tets on a roof: chordal triangles tilted by +-45 degrees about the y axis, sharing an edge.
  const std::vector<Node> nodes = {{Vec3(0, 0, 0), Side::Top},
                                   {Vec3(0, 2, 0), Side::Top},
                                   {Vec3(-2, 0, -2), Side::Top},
                                   {Vec3(2, 0, -2), Side::Top},
                                   {Vec3(0, 1, -2), Side::Bottom}};
  // Tet A: top 0 1 2 over bottom 4; tet B: top 0 1 3 over bottom 4.
  const TetMesh m = makeTets(nodes, {{0, 1, 2, 4}, {0, 1, 3, 4}});
  ChordalSurface s = buildChordalSurface(m);
  ASSERT_EQ(s.facets.size(), 2u);
  ASSERT_EQ(s.vertices.size(), 4u);
  computeNormalsAndRadius(s, m);
  const Vec3 nA = facetNormal(s, s.facets[0]), nB = facetNormal(s, s.facets[1]);
  EXPECT_GT(nA.z(), 0);
  EXPECT_GT(nB.z(), 0);
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    const int top = s.tetEdge[v][0];
    Vec3 expected;
    if (top == 0 || top == 1)
      expected = (nA + nB).normalized();  // on the shared edge
    else
      expected = top == 2 ? nA : nB;
    EXPECT_LT((s.normals[v] - expected).norm(), 1e-12) << "vertex " << v;
    EXPECT_NEAR(s.radius[v], s.normals[v].dot(m.nodes[top] - s.vertices[v]), 1e-12);
  }
  // The shared edge's vertices look straight up.
  EXPECT_LT((s.normals[vertexAt(s, Vec3(0, 0.5, -1))] - Vec3::UnitZ()).norm(), 1e-12);
}

// (d) Three tets around the same two chordal vertices: a fin, the chordal edge is in three facets.
TEST(ChordalSurface, EdgeInThreeFacetsIsNonManifold) {
  const std::vector<Node> nodes = {{Vec3(0, 0, 1), Side::Top},       // T0
                                   {Vec3(0, -1, 0), Side::Bottom},   // B0
                                   {Vec3(0, 1, 0), Side::Bottom},    // B1
                                   {Vec3(1, 0, 1), Side::Top},       // 2-2 with T0 B0 B1
                                   {Vec3(-1, 0, 1), Side::Top},      // 2-2 on the other side
                                   {Vec3(0, 0, -1), Side::Bottom}};  // 1-3: the fin below
  // Control: two of them make a manifold strip sharing the edge (T0B0, T0B1).
  const ChordalSurface ok = buildChordalSurface(makeTets(nodes, {{0, 1, 2, 3}, {0, 1, 2, 4}}));
  EXPECT_EQ(ok.facets.size(), 2u);
  EXPECT_EQ(ok.vertices.size(), 6u);
  expectGeometryError(
      [&] {
        buildChordalSurface(makeTets(nodes, {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}}));
      },
      "non-manifold");
}

TEST(ChordalSurface, OnlyFlatTetsGiveNoSurface) {
  const std::vector<Node> nodes = {
      {Vec3(0, 0, 1), Side::Top}, {Vec3(1, 0, 1), Side::Top}, {Vec3(0, 1, 1), Side::Top}, {Vec3(0, 0, 1.5), Side::Top}};
  expectGeometryError([&] { buildChordalSurface(makeTets(nodes, {{0, 1, 2, 3}})); }, "empty chordal surface");
}

// (e) Table 1 keys: exterior triangles / exterior edges per tet.
TEST(ChordalSurface, ClassifyTetsCountsExteriorTrianglesAndEdges) {
  const std::vector<Node> nodes = {{Vec3(0, 0, 0), Side::Bottom},
                                   {Vec3(1, 0, 0), Side::Bottom},
                                   {Vec3(0, 1, 0), Side::Bottom},
                                   {Vec3(0, 0, 1), Side::Top},
                                   {Vec3(0.3, 0.3, -1), Side::Bottom}};
  EXPECT_EQ(classifyTets(makeTets(nodes, {{0, 1, 2, 3}})), (std::map<std::string, std::size_t>{{"4/6", 1}}));
  // Sharing face (0, 1, 2): each tet has 3 exterior triangles, and all 6 of its edges are still
  // edges of an exterior triangle.
  EXPECT_EQ(classifyTets(makeTets(nodes, {{0, 1, 2, 3}, {2, 1, 0, 4}})),
            (std::map<std::string, std::size_t>{{"3/6", 2}}));
}

// (f) Eq. 1: n = e2 x e1 / |e2 x e1|.
TEST(ChordalSurface, FacetNormalOfTriangleAndNonPlanarQuad) {
  ChordalSurface s;
  s.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 0, 3)};
  // e1 = v1 - v2 = (-2, 0, 0), e2 = v3 - v2 = (-2, 0, 3): e2 x e1 = (0, -6, 0).
  EXPECT_LT((facetNormal(s, {0, 1, 2, -1}) - Vec3(0, -1, 0)).norm(), 1e-15);
  EXPECT_LT((facetNormal(s, {0, 2, 1, -1}) - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((facetNormal(s, {1, 2, 0, -1}) - Vec3(0, -1, 0)).norm(), 1e-15) << "any start corner";

  // Twisted quad: corner 2 lifted. Diagonals e1 = v4 - v2 = (-1, 1, 0), e2 = v3 - v1 = (1, 1, 1):
  // e2 x e1 = (-1, -1, 2).
  s.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1), Vec3(0, 1, 0)};
  const Vec3 expected = Vec3(-1, -1, 2) / std::sqrt(6.0);
  EXPECT_LT((facetNormal(s, {0, 1, 2, 3}) - expected).norm(), 1e-15);
  EXPECT_LT((facetNormal(s, {0, 3, 2, 1}) + expected).norm(), 1e-15) << "reversed corners flip the normal";
  EXPECT_NEAR(facetNormal(s, {1, 2, 3, 0}).norm(), 1.0, 1e-15);

  // A degenerate facet has no direction.
  s.vertices = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)};
  EXPECT_EQ(facetNormal(s, {0, 1, 2, -1}), Vec3::Zero());
}

// Two top and two bottom nodes on parallel lines (the edges of a bend) make a coplanar 2-2 tet
// whose quad has all four corners on one line. Here every top row has a bottom row in its vertical
// plane, shifted along it, so the Delaunay tets hold many such tets; their facets are collapsed
// and the surface is the mid-height cross-section of the nodes' hull, a disk without slits.
TEST(ChordalSurface, CoplanarTetsOfParallelRowsLeaveNoSlit) {
  std::vector<SurfaceNode> nodes;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 3; ++y) {
      SurfaceNode top, bottom;
      top.point = Vec3(x, y, 2), top.side = Side::Top;
      bottom.point = Vec3(x + 0.3, y, 0), bottom.side = Side::Bottom;
      nodes.push_back(top), nodes.push_back(bottom);
    }
  const TetMesh tets = delaunayTets(nodes);
  const ChordalSurface s = buildChordalSurface(tets);
  EXPECT_NEAR(chordalArea(s), 3.0 * 2.0, 0.05 * 6)
      << "[0.15, 3.15] x [0, 2] at z = 1; a collapse moves vertices along the rows";
  const auto uses = facetEdgeUses(s);
  const long euler =
      static_cast<long>(s.vertices.size()) - static_cast<long>(uses.size()) + static_cast<long>(s.facets.size());
  EXPECT_EQ(euler, 1) << "a disk: no slit along the node rows";
  for (const auto& [edge, n] : uses) EXPECT_LE(n, 2);
  for (const auto& f : s.facets) EXPECT_GT(facetNormal(s, f).norm(), 0.5) << "no degenerate facet is left";
  for (const Vec3& v : s.vertices) EXPECT_NEAR(v.z(), 1.0, 1e-12);
}

namespace {

// A flat surface of the given facets (z = 0) on the vertices, tetEdge left empty.
ChordalSurface flatSurface(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 4>>& facets) {
  ChordalSurface s;
  s.vertices = vertices;
  s.tetEdge.assign(vertices.size(), {0, 0});
  s.facets = facets;
  for (const auto& f : facets) ++(f[3] < 0 ? s.triangles : s.quads);
  return s;
}

}  // namespace

// Two squares of two triangles each touching at the vertex (1, 1) only, and an ear: one triangle touching the
// first square at its vertex (0, 1). The rim passes (1, 1) and (0, 1) twice; the smaller fan goes at each: the
// ear, then the second square (2 facets against 2: the first in facet order stays). One square is left, its
// unused vertices dropped and the rest renumbered in order.
TEST(ChordalSurface, PinchedRimKeepsTheLargestFanAtEachVertex) {
  ChordalSurface s = flatSurface(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {-1, 2, 0}, {-1, 1.5, 0}},
      {{0, 1, 2, -1}, {0, 2, 3, -1}, {2, 4, 5, -1}, {2, 5, 6, -1}, {3, 7, 8, -1}});
  EXPECT_EQ(dropPinchedFacets(s), 3u);
  ASSERT_EQ(s.facets.size(), 2u);
  EXPECT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.facets[0], (std::array<int, 4>{0, 1, 2, -1}));
  EXPECT_EQ(s.facets[1], (std::array<int, 4>{0, 2, 3, -1}));
  EXPECT_EQ(s.triangles, 2u);
  EXPECT_EQ(dropPinchedFacets(s), 0u) << "nothing pinched is left";
}

// A 3 x 3 grid of unit squares without its middle one: the rim loops are the outer square (12 long, loop 0: it
// holds vertex 0) and the hole (4 long), each rim vertex on one of them; filled, the hole's vertices are inside.
TEST(ChordalSurface, RimLoopsAreTheOuterRimAndTheHole) {
  std::vector<Vec3> grid;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) grid.emplace_back(i, j, 0);
  std::vector<std::array<int, 4>> squares;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (i != 1 || j != 1) squares.push_back({4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4});
  const RimLoops loops = rimLoops(flatSurface(grid, squares));
  ASSERT_EQ(loops.length.size(), 2u);
  EXPECT_DOUBLE_EQ(loops.length[0], 12.0);
  EXPECT_DOUBLE_EQ(loops.length[1], 4.0);
  for (int v = 0; v < 16; ++v) {
    const bool hole = v == 5 || v == 6 || v == 9 || v == 10;
    EXPECT_EQ(loops.loopOf[v], hole ? 1 : 0) << v;
  }
  squares.push_back({5, 6, 10, 9});
  const RimLoops filled = rimLoops(flatSurface(grid, squares));
  EXPECT_EQ(filled.length.size(), 1u);
  for (int v : {5, 6, 9, 10}) EXPECT_EQ(filled.loopOf[v], -1) << "inside once the hole is filled";
}

// Two unit squares side by side are split from their corner 0; a fold the tets left (a triangle standing on the first
// square's diagonal 0-2, up out of the plane) makes that square split from its corner 1, so that no edge is in more
// than two triangles (Gmsh's parametrization refuses an edge in four).
TEST(ChordalSurface, AQuadIsSplitOnADiagonalTheSurfaceHasNot) {
  ChordalSurface s = flatSurface({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}, {0.5, 0.5, 1}},
                                 {{0, 1, 2, 3}, {1, 4, 5, 2}});
  using Triangles = std::vector<std::array<int, 3>>;
  EXPECT_EQ(chordalTriangles(s), (Triangles{{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}}));
  s.facets.push_back({0, 2, 6, -1});
  const Triangles split = chordalTriangles(s);
  EXPECT_EQ(split, (Triangles{{0, 1, 3}, {1, 2, 3}, {1, 4, 5}, {1, 5, 2}, {0, 2, 6}}));
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : split)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [edge, n] : uses) EXPECT_LE(n, 2) << edge.first << "-" << edge.second;
}
