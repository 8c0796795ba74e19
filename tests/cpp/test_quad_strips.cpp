// Quad strips (quadmesh/quad_strips.hpp): a strip found from an edge across a grid to the rim, stopped by a blocked
// quad; halved, the grid stays all quads and conformal with one more node on each rim end; a ring of quads with an
// odd number round has its inner loop (the one that must be even) made even by a strip to the outer loop, both loops
// by one strip if both must be, none if the strip would cross a blocked quad; a grid on a disc (its corners on the
// circle, flat) is pillowed, the same grid on the square (sharp corners) is not, and on a half disc over a trapezoid
// the ring runs round the quads of its two acute corners. Also on
// copies scaled by 1e-3 and 1e3 (only the nodes' positions scale).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "quadmesh/quad_smoothing.hpp"
#include "quadmesh/quad_strips.hpp"

using namespace hexlayer;

namespace {

// An n x m grid of unit quads in the plane z = 0, scaled by s; node (i, j) is j * (n + 1) + i.
QuadMesh grid(int n, int m, double s) {
  QuadMesh q;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) q.nodes.emplace_back(s * i, s * j, 0);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      q.quads.push_back({j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i});
  return q;
}

// A ring of `around` x `across` quads between radii 1 and 2, scaled by s; node (i, j) is j * around + i.
QuadMesh ring(int around, int across, double s) {
  QuadMesh q;
  for (int j = 0; j <= across; ++j)
    for (int i = 0; i < around; ++i) {
      const double r = 1.0 + static_cast<double>(j) / across, a = 2 * M_PI * i / around;
      q.nodes.emplace_back(s * r * std::cos(a), s * r * std::sin(a), 0);
    }
  for (int j = 0; j < across; ++j)
    for (int i = 0; i < around; ++i)
      q.quads.push_back(
          {j * around + i, j * around + (i + 1) % around, (j + 1) * around + (i + 1) % around, (j + 1) * around + i});
  return q;
}

// Every edge used by one quad (rim) or two turned opposite ways (conformal, one orientation): the rim's edge count.
int rimEdges(const QuadMesh& q) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k) ++uses[{quad[k], quad[(k + 1) % 4]}];
  int rim = 0;
  for (const auto& [edge, count] : uses) {
    EXPECT_EQ(count, 1) << "an edge used twice the same way";
    rim += uses.count({edge.second, edge.first}) == 0;
  }
  return rim;
}

// The worst scaled Jacobian of the quads.
double worstQuad(const QuadMesh& q) {
  double worst = 1;
  for (const auto& quad : q.quads)
    worst =
        std::min(worst, quadScaledJacobian({q.nodes[quad[0]], q.nodes[quad[1]], q.nodes[quad[2]], q.nodes[quad[3]]}));
  return worst;
}

// Per node, the quads it is a corner of.
std::vector<int> quadsAt(const QuadMesh& q) {
  std::vector<int> at(q.nodes.size(), 0);
  for (const auto& quad : q.quads)
    for (int n : quad) ++at[n];
  return at;
}

}  // namespace

TEST(QuadStrips, AGridWithItsCornersOnACircleIsPillowedOneOnASquareIsNot) {
  for (double s : {1.0, 1e-3, 1e3}) {
    const int n = 6;
    QuadMesh square = grid(n, n, s);
    const QuadMesh before = square;
    EXPECT_FALSE(pillowFlatCorners(square)) << "sharp corners: left as they are";
    EXPECT_EQ(square.quads, before.quads);
    EXPECT_EQ(square.nodes.size(), before.nodes.size());
    // The square [-1, 1]^2 onto the unit disc (x sqrt(1 - y^2 / 2), y sqrt(1 - x^2 / 2)): the corners land on the
    // circle, where it does not turn: each corner's quad is flat there (180 degrees).
    QuadMesh disc = grid(n, n, s);
    for (Vec3& p : disc.nodes) {
      const double x = 2 * p.x() / (n * s) - 1, y = 2 * p.y() / (n * s) - 1;
      p = s * Vec3(x * std::sqrt(1 - y * y / 2), y * std::sqrt(1 - x * x / 2), 0);
    }
    const double flattest = worstQuad(disc);
    EXPECT_LT(flattest, 0.3);
    const std::size_t nodes = disc.nodes.size(), quads = disc.quads.size();
    ASSERT_TRUE(pillowFlatCorners(disc));
    EXPECT_EQ(disc.nodes.size(), nodes + 4 * n) << "a copy of every rim node";
    EXPECT_EQ(disc.quads.size(), quads + 4 * n) << "a quad on every rim edge";
    EXPECT_EQ(rimEdges(disc), 4 * n) << "conformal, one orientation, the rim as long";
    const std::vector<int> at = quadsAt(disc);
    for (std::size_t v = nodes; v < disc.nodes.size(); ++v) {
      EXPECT_EQ(at[v], 2) << "every rim node in two quads";
      EXPECT_NEAR(disc.nodes[v].norm(), s, 1e-12 * s) << "the rim nodes stay on the circle";
    }
    for (int corner : {0, n, n * (n + 1), n * (n + 1) + n}) EXPECT_EQ(at[corner], 3) << "a corner now inside";
    EXPECT_GT(worstQuad(disc), flattest + 0.05) << "no quad flatter than a corner's was, before any smoothing";
  }
}

// A grid on a half disc over a trapezoid: two corners on the half circle (flat), two acute ones below (60 degrees).
// Pillowed, the ring runs round the acute corners' quads (each corner still in one quad, at 60 degrees), along the
// rim elsewhere.
TEST(QuadStrips, PillowingKeepsTheQuadsOfAcuteCorners) {
  for (double s : {1.0, 1e-3, 1e3}) {
    const int n = 6;
    QuadMesh d = grid(n, n, s);
    for (Vec3& p : d.nodes) {
      const double x = 2 * p.x() / (n * s) - 1, y = 2 * p.y() / (n * s) - 1;
      const double widening = 1 / std::tan(M_PI / 3);  // the sides below lean out: 60-degree corners
      p = s * (y > 0 ? Vec3(x * std::sqrt(1 - y * y / 2), y * std::sqrt(1 - x * x / 2), 0)
                     : Vec3(x * (1 - widening * y), y, 0));
    }
    const std::size_t nodes = d.nodes.size(), quads = d.quads.size();
    const std::array<int, 2> acute{0, n};  // the corners below
    const QuadMesh before = d;
    auto cornerQuad = [](const QuadMesh& q, int corner) {  // the corners of the (last) quad at `corner`, in order
      std::array<Vec3, 4> p;
      for (const auto& quad : q.quads)
        if (std::find(quad.begin(), quad.end(), corner) != quad.end())
          for (int k = 0; k < 4; ++k) p[k] = q.nodes[quad[k]];
      return p;
    };
    ASSERT_TRUE(pillowFlatCorners(d));
    EXPECT_EQ(d.nodes.size(), nodes + 4 * n);
    EXPECT_EQ(d.quads.size(), quads + 4 * n);
    EXPECT_EQ(rimEdges(d), 4 * n) << "conformal, one orientation, the rim as long";
    const std::vector<int> at = quadsAt(d);
    for (int corner : acute) {
      EXPECT_EQ(at[corner], 1) << "an acute corner keeps its one quad";
      const std::array<Vec3, 4> was = cornerQuad(before, corner), is = cornerQuad(d, corner);
      for (int k = 0; k < 4; ++k) EXPECT_LT((is[k] - was[k]).norm(), 1e-12 * s) << "its quad where it was";
    }
    for (int corner : {n * (n + 1), n * (n + 1) + n}) EXPECT_EQ(at[corner], 3) << "a flat corner now inside";
    EXPECT_GT(worstQuad(d), 0.3);
  }
}

TEST(QuadStrips, AStripCrossesAGridToTheRimAndHalvedKeepsItConformal) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    QuadMesh q = grid(3, 3, s);
    const QuadStrip strip =
        stripToRim(q.quads, quadsOfEdges(q.quads), {}, 1, 2);  // the bottom rim's middle edge, up to the top rim
    ASSERT_EQ(strip.size(), 3u);
    EXPECT_EQ(strip[0].first, 1);
    EXPECT_EQ(strip[2].first, 7);
    std::vector<char> blocked(q.quads.size(), 0);
    blocked[4] = 1;  // the middle quad
    EXPECT_TRUE(stripToRim(q.quads, quadsOfEdges(q.quads), blocked, 1, 2).empty());
    q.nodes.push_back(0.5 * (q.nodes[1] + q.nodes[2]));
    halveStrip(q.quads, q.nodes, strip, static_cast<int>(q.nodes.size()) - 1);
    EXPECT_EQ(q.quads.size(), 12u);
    EXPECT_EQ(q.nodes.size(), 16u + 4u);
    EXPECT_EQ(rimEdges(q), 14);
    for (const auto& quad : q.quads) {  // each half keeps the grid's orientation and a quarter of the area
      const Vec3 n = (q.nodes[quad[2]] - q.nodes[quad[0]]).cross(q.nodes[quad[3]] - q.nodes[quad[1]]);
      EXPECT_GT(n.z(), 0);
    }
  }
}

TEST(QuadStrips, AnOddLoopThatMustBeEvenIsMadeEven) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    QuadMesh q = ring(7, 2, s);  // inner and outer loops of 7 edges
    const auto inner = [s](const Vec3& p) { return p.norm() < 1.5 * s; };
    EXPECT_EQ(evenRimLoops(q, inner, {}), 0u);
    EXPECT_EQ(q.quads.size(), 16u);  // one strip of two quads halved
    EXPECT_EQ(rimEdges(q), 16);      // 8 inner, 8 outer
    std::vector<char> all(q.quads.size(), 1);
    QuadMesh blocked = ring(7, 2, s);
    EXPECT_EQ(evenRimLoops(blocked, inner, all), 1u);  // no strip may run: it stays odd
    EXPECT_EQ(blocked.quads.size(), 14u);
    QuadMesh both = ring(7, 2, s);  // both loops must be even: one strip from one to the other evens both
    EXPECT_EQ(evenRimLoops(both, [](const Vec3&) { return true; }, {}), 0u);
    EXPECT_EQ(both.quads.size(), 16u);
    EXPECT_EQ(rimEdges(both), 16);
    QuadMesh square = grid(3, 3, s);  // one loop of 12 edges: even already, nothing to do
    EXPECT_EQ(evenRimLoops(square, [](const Vec3&) { return true; }, {}), 0u);
    EXPECT_EQ(square.quads.size(), 9u);
  }
}
