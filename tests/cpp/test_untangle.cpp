// Untangling (sweep/untangle.hpp): the sweep directions of converging sweep lines, smoothed where the inside of
// a sharp bend folds the inner layer, and left alone where the sweep is good.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "quality/quality.hpp"
#include "sweep/sweep.hpp"
#include "sweep/untangle.hpp"

using namespace hexlayer;

namespace {

// A sheet bent by 90° about the z axis, seen on its chordal surface: a flat leg along -x at y = R,
// a quarter arc of radius R about the origin, and a flat leg along -y at x = R; `legs` quads of
// length `step` on each leg, `arc` quads around the arc, `rows` quads along z. The sweep directions
// point away from the bend axis (the top wall is outside), so a radius r > R makes the lines
// cross before the inner wall: the inside corner of a bend with a sharp inner edge.
struct BentSheet {
  QuadMesh quads;
  std::vector<Vec3> normal;
};

BentSheet bentSheet(double R, int legs, int arc, int rows, double step) {
  BentSheet s;
  std::vector<std::pair<Vec3, Vec3>> section;  // (point, normal) across the bend
  for (int i = legs; i > 0; --i) section.push_back({Vec3(-i * step, R, 0), Vec3::UnitY()});
  for (int i = 0; i <= arc; ++i) {
    const double a = M_PI / 2 * (1 - double(i) / arc);
    section.push_back({Vec3(R * std::cos(a), R * std::sin(a), 0), Vec3(std::cos(a), std::sin(a), 0)});
  }
  for (int i = 1; i <= legs; ++i) section.push_back({Vec3(R, -i * step, 0), Vec3::UnitX()});
  const int n = static_cast<int>(section.size());
  for (int k = 0; k <= rows; ++k)
    for (const auto& [p, nrm] : section) s.quads.nodes.push_back(p + Vec3(0, 0, k * step)), s.normal.push_back(nrm);
  for (int k = 0; k < rows; ++k)
    for (int i = 0; i + 1 < n; ++i)  // counter-clockwise seen along the normal
      s.quads.quads.push_back({k * n + i, (k + 1) * n + i, (k + 1) * n + i + 1, k * n + i + 1});
  return s;
}

// The sweep of the bent sheet with radius r and two layers, as the sweep stage builds it.
struct BentSweep {
  HexMesh mesh;
  double r;
  void place(const BentSheet& s, const std::vector<Vec3>& dir, int i) {
    const SweepLine line = radiusSweepLine(s.quads.nodes[i], dir[i], r);
    const std::vector<double> offsets = layerOffsets(2);
    for (int k = 0; k < 3; ++k) mesh.nodes[3 * i + k] = layerNode(s.quads.nodes[i], line, offsets[k]);
  }
  double column(int j) const {
    return std::min(hexScaledJacobian(hexCorners(mesh, 2 * j)), hexScaledJacobian(hexCorners(mesh, 2 * j + 1)));
  }
};

BentSweep sweepBent(const BentSheet& s, const std::vector<Vec3>& dir, double r) {
  BentSweep b{HexMesh{}, r};
  b.mesh.layers = 2;
  b.mesh.nodes.resize(3 * s.quads.nodes.size());
  for (const auto& q : s.quads.quads)
    for (int k = 0; k < 2; ++k) {
      std::array<int, 8> hex;
      for (int c = 0; c < 4; ++c) hex[c] = 3 * q[c] + k, hex[c + 4] = 3 * q[c] + k + 1;
      b.mesh.hexes.push_back(hex);
    }
  for (size_t i = 0; i < s.quads.nodes.size(); ++i) b.place(s, dir, static_cast<int>(i));
  return b;
}

double worstHex(const HexMesh& mesh) {
  double w = 1;
  for (size_t h = 0; h < mesh.hexes.size(); ++h) w = std::min(w, hexScaledJacobian(hexCorners(mesh, h)));
  return w;
}

}  // namespace

TEST(Untangle, SmoothedDirectionsUnfoldTheInsideOfASharpBend) {
  const BentSheet sheet = bentSheet(0.5, 5, 3, 3, 1.0);
  std::vector<Vec3> dir = sheet.normal;
  BentSweep sweep = sweepBent(sheet, dir, 0.75);  // half-thickness above the bend radius
  ASSERT_LT(worstHex(sweep.mesh), 0) << "the radial lines must fold the inner layer";
  const UntangleResult r = untangleSweep(
      sheet.quads, dir, 0.2, [&](int i) { sweep.place(sheet, dir, i); }, [&](int j) { return sweep.column(j); });
  EXPECT_LT(r.worstBefore, 0);
  EXPECT_GT(r.worstAfter, 0.2);
  EXPECT_NEAR(worstHex(sweep.mesh), r.worstAfter, 1e-12);
  EXPECT_GT(r.regions, 0);
  for (size_t i = 0; i < dir.size(); ++i) {
    EXPECT_NEAR(dir[i].norm(), 1, 1e-12);
    if (std::abs(sheet.quads.nodes[i].x()) > 4.5 || std::abs(sheet.quads.nodes[i].y()) > 4.5)
      EXPECT_NEAR((dir[i] - sheet.normal[i]).norm(), 0, 1e-12) << "the leg ends stay untouched";
  }
}

TEST(Untangle, LeavesAGoodSweepAlone) {
  const BentSheet sheet = bentSheet(3.0, 3, 6, 2, 1.0);
  std::vector<Vec3> dir = sheet.normal;
  BentSweep sweep = sweepBent(sheet, dir, 0.5);
  const UntangleResult r = untangleSweep(
      sheet.quads, dir, 0.2, [&](int i) { sweep.place(sheet, dir, i); }, [&](int j) { return sweep.column(j); });
  EXPECT_EQ(r.regions, 0);
  EXPECT_GT(r.worstBefore, 0.2);
  for (size_t i = 0; i < dir.size(); ++i) EXPECT_EQ(dir[i], sheet.normal[i]);
}
