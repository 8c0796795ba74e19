// The footprint grid (quadmesh/footprint_grid.hpp): a flat rectangular sheet's quads carrying a rib's foot grid,
// the foot's rows x columns quads node for node at the foot's lines, the rest of the rectangle covered by quads
// about the size given. Run on a foot across the sheet (rim to rim), one inside it, a tilted frame, and on copies
// scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "core/error.hpp"
#include "quadmesh/footprint_grid.hpp"

using namespace hexlayer;

namespace {

// A 60 x 40 sheet with a foot of columns u0..u1 (n + 1 of them, evenly) and the given rows, in a frame turned
// about z by `angle`, origin (1, 2, 3), all scaled by s.
Footprint sheet(double u0, double u1, int n, const std::vector<double>& rows, double angle, double s) {
  Footprint f;
  f.origin = s * Vec3(1, 2, 3);
  f.u = Vec3(std::cos(angle), std::sin(angle), 0), f.v = Vec3(-std::sin(angle), std::cos(angle), 0);
  f.uMin = 0, f.uMax = 60 * s, f.vMin = 0, f.vMax = 40 * s;
  for (int j = 0; j <= n; ++j) f.columns.push_back(s * (u0 + (u1 - u0) * j / n));
  for (double r : rows) f.rows.push_back(s * r);
  f.size = 2 * s;
  return f;
}

// (u, v) of a point in the frame.
Eigen::Vector2d inFrame(const Footprint& f, const Vec3& p) {
  return {(p - f.origin).dot(f.u), (p - f.origin).dot(f.v)};
}

// The grid covers the rectangle with counter-clockwise quads (their areas add up to its), no edge longer than
// 1.5 x the size outside the foot, every node in the rectangle's plane; the strip's nodes are at the foot's lines
// (or at its nodes, if given) and its quads are quads of the grid.
void expectGrid(const Footprint& f) {
  const FootprintGrid g = footprintGrid(f);
  double area = 0;
  const double s = f.size / 2;
  for (const auto& q : g.quads.quads) {
    Eigen::Vector2d p[4];
    for (int c = 0; c < 4; ++c) p[c] = inFrame(f, g.quads.nodes[q[c]]);
    const double a = 0.5 * ((p[2] - p[0]).x() * (p[3] - p[1]).y() - (p[2] - p[0]).y() * (p[3] - p[1]).x());
    EXPECT_GT(a, 0) << "counter-clockwise";
    area += a;
    for (int c = 0; c < 4; ++c) EXPECT_LE((p[(c + 1) % 4] - p[c]).norm(), 1.5 * f.size + 1e-12 * s);
  }
  EXPECT_NEAR(area / ((f.uMax - f.uMin) * (f.vMax - f.vMin)), 1, 1e-12);
  for (const Vec3& p : g.quads.nodes) EXPECT_NEAR((p - f.origin).dot(f.u.cross(f.v)), 0, 1e-12 * s);
  std::set<std::array<int, 4>> quads;
  for (auto q : g.quads.quads) {
    std::sort(q.begin(), q.end());
    quads.insert(q);
  }
  ASSERT_EQ(g.strip.size(), f.rows.size());
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    ASSERT_EQ(g.strip[i].size(), f.columns.size());
    for (std::size_t j = 0; j < f.columns.size(); ++j) {
      const Eigen::Vector2d p = inFrame(f, g.quads.nodes[g.strip[i][j]]);
      const Eigen::Vector2d at = f.feet.empty() ? Eigen::Vector2d(f.columns[j], f.rows[i]) : f.feet[i][j];
      EXPECT_NEAR(p.x(), at.x(), 1e-12 * s);
      EXPECT_NEAR(p.y(), at.y(), 1e-12 * s);
      if (i == 0 || j == 0) continue;
      std::array<int, 4> q{g.strip[i - 1][j - 1], g.strip[i - 1][j], g.strip[i][j], g.strip[i][j - 1]};
      std::sort(q.begin(), q.end());
      EXPECT_TRUE(quads.count(q)) << "strip quad " << i << ", " << j << " is a quad of the grid";
    }
  }
  EXPECT_EQ(g.quads.layout, QuadLayout::Grid);
}

}  // namespace

// The foot across the sheet from rim to rim (its first and last columns on the rectangle's sides), 2 rows of quads.
TEST(FootprintGrid, FootRimToRim) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const Footprint f = sheet(0, 60, 30, {19, 20, 21}, 0, s);
    expectGrid(f);
    EXPECT_EQ(footprintGrid(f).quads.quads.size(), 30u * 22u);  // 10 rows each side, 2 in the strip
  }
}

// A foot inside the sheet, 3 rows of quads, in a frame turned by 30 degrees.
TEST(FootprintGrid, FootInsideTurned) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    expectGrid(sheet(10, 50, 20, {19, 19.5, 20.5, 21}, M_PI / 6, s));
  }
}

// A foot whose nodes lean off its lines (a rib's sweep columns leaning by a tenth of the column spacing): the strip's
// nodes are put at them, the quads still counter-clockwise.
TEST(FootprintGrid, FootNodesLeaning) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    Footprint f = sheet(10, 50, 20, {19, 20, 21}, M_PI / 6, s);
    for (std::size_t i = 0; i < f.rows.size(); ++i) {
      f.feet.emplace_back();
      for (double u : f.columns) f.feet.back().emplace_back(u + 0.2 * s * (i - 1.0), f.rows[i]);
    }
    expectGrid(f);
  }
}

// A foot reaching past the sheet, or of one column, is refused.
TEST(FootprintGrid, FootOffTheSheetIsRefused) {
  for (double s : {1.0, 1e-3, 1e3}) {
    EXPECT_THROW(footprintGrid(sheet(-1, 50, 20, {19, 21}, 0, s)), Error);
    EXPECT_THROW(footprintGrid(sheet(10, 50, 20, {19}, 0, s)), Error);
  }
}
