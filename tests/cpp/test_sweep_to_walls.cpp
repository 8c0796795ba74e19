// Beyond the paper's sweep: the sweep line ending on the CAD walls (π_t, π_b of §3), the
// untangling of converging sweep lines, and the fairing of the chordal surface.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include <cmath>
#include <random>

#include "chordal/chordal_fairing.hpp"
#include "geometry/wall_rays.hpp"
#include "quality/quality.hpp"
#include "sweep/sweep.hpp"
#include "sweep/sweep_to_walls.hpp"
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

TEST(SweepLine, LayerNodesFollowAnAsymmetricLine) {
  const Vec3 q(1, 2, 3);
  const SweepLine line{Vec3(1, 2, 2), Vec3(1, 2, 6)};  // 1 below, 3 above the chordal surface
  const std::vector<double> offsets = layerOffsets(4);
  const double expected[] = {2, 2.5, 3, 4.5, 6};
  for (int k = 0; k <= 4; ++k) EXPECT_NEAR(layerNode(q, line, offsets[k]).z(), expected[k], 1e-12) << k;
  const SweepLine even = radiusSweepLine(q, Vec3::UnitZ(), 1.5);
  EXPECT_NEAR((layerNode(q, even, -1) - Vec3(1, 2, 1.5)).norm(), 0, 1e-12);  // §7.2: q - r n̄
  EXPECT_NEAR((layerNode(q, even, 1) - Vec3(1, 2, 4.5)).norm(), 0, 1e-12);
}

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

TEST(ChordalFairing, RemovesNoiseKeepsTheRimAndDoesNotShrinkACylinder) {
  // A noisy cylinder patch of radius 10 (angle 0..90°, z 0..10), grid 31 x 11, as quads.
  ChordalSurface s;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.2, 0.2);
  const int na = 31, nz = 11;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < na; ++i) {
      const double a = M_PI / 2 * i / (na - 1), rim = (i == 0 || i == na - 1 || k == 0 || k == nz - 1);
      const double rr = 10 + (rim ? 0 : noise(random));
      s.vertices.emplace_back(rr * std::cos(a), rr * std::sin(a), k * 1.0);
    }
  for (int k = 0; k + 1 < nz; ++k)
    for (int i = 0; i + 1 < na; ++i)
      s.facets.push_back({k * na + i, k * na + i + 1, (k + 1) * na + i + 1, (k + 1) * na + i});
  const std::vector<Vec3> before = s.vertices;
  auto radialError = [&](const std::vector<Vec3>& v) {  // root mean square distance to the cylinder
    double sum = 0;
    for (const Vec3& p : v) sum += std::pow(std::hypot(p.x(), p.y()) - 10, 2);
    return std::sqrt(sum / v.size());
  };
  fairChordalSurface(s, 10);
  EXPECT_GT(radialError(before), 0.09);
  EXPECT_LT(radialError(s.vertices), 0.45 * radialError(before)) << "most of the noise is gone";
  double meanRadius = 0;
  for (const Vec3& p : s.vertices) meanRadius += std::hypot(p.x(), p.y()) / s.vertices.size();
  EXPECT_NEAR(meanRadius, 10, 0.01) << "Taubin's smoothing does not shrink the surface";
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < na; ++i)
      if (i == 0 || i == na - 1 || k == 0 || k == nz - 1) EXPECT_EQ(s.vertices[k * na + i], before[k * na + i]);
}

// castSweepLine (sweep_to_walls.hpp) on a 40 x 30 x 2 box from its mid-plane: with a radius of 1 the line ends
// on the walls (Face6 at z = 2, Face5 at z = 0); with a radius of 0.2 the walls (1 away) lie beyond 4 radii, so
// the line keeps the radius function's ends (q -+ 0.2 n, no face); tilted out through the rim near x = 40, the
// top end is on the rim face (Face2, x = 40) where the line leaves.
TEST(SweepToWalls, SweepLineEndsOnTheWallsWithinReach) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallSides sides = classifyWallSides(cad);
  WallRays rays(cad, sides);
  const Vec3 q(20, 15, 1);
  const SweepLine wide = castSweepLine(rays, q, Vec3::UnitZ(), 1);
  EXPECT_NEAR((wide.top - Vec3(20, 15, 2)).norm(), 0, 1e-9);
  EXPECT_NEAR((wide.bottom - Vec3(20, 15, 0)).norm(), 0, 1e-9);
  EXPECT_EQ(wide.topFace, 5);
  EXPECT_EQ(wide.bottomFace, 4);
  const SweepLine narrow = castSweepLine(rays, q, Vec3::UnitZ(), 0.2);
  EXPECT_NEAR((narrow.top - Vec3(20, 15, 1.2)).norm(), 0, 1e-12);
  EXPECT_NEAR((narrow.bottom - Vec3(20, 15, 0.8)).norm(), 0, 1e-12);
  EXPECT_EQ(narrow.topFace, -1);
  EXPECT_EQ(narrow.bottomFace, -1);
  const SweepLine out = castSweepLine(rays, Vec3(39.8, 15, 1), Vec3(1, 0, 1).normalized(), 1);
  EXPECT_NEAR((out.top - Vec3(40, 15, 1.2)).norm(), 0, 1e-9);
  EXPECT_EQ(out.topFace, 1) << "Face2, x = 40";
}
