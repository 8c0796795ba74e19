// The map of the chordal surface onto the plane (quadmesh/surface_map.hpp): a rectangle with a hole onto the square
// without folds, its corners found, what is not a sphere with holes refused; and the annulus map for rings and
// tubes: conformal, against the analytic map of a flat ring (log-polar coordinates).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <utility>

#include "quadmesh/block_grids.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "quadmesh/surface_map.hpp"
#include "test_flat_surfaces.hpp"

using namespace hexlayer;
using hexlayer::test_flat_surfaces::rectangle;

namespace {

// A flat ring between radii r0 and r1, `rings` rows of `around` quads, the radii spaced geometrically (square
// quads), normal +z, centred at the origin and squashed by `squash` along y (1: round).
ChordalSurface ring(double r0, double r1, int rings, int around, double squash = 1) {
  ChordalSurface s;
  for (int k = 0; k <= rings; ++k)
    for (int j = 0; j < around; ++j) {
      const double r = r0 * std::pow(r1 / r0, static_cast<double>(k) / rings), a = 2 * M_PI * j / around;
      s.vertices.emplace_back(r * std::cos(a), squash * r * std::sin(a), 0);
    }
  s.normals.assign(s.vertices.size(), Vec3::UnitZ());
  auto v = [&](int k, int j) { return k * around + j % around; };
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < around; ++j) s.facets.push_back({v(k, j), v(k + 1, j), v(k + 1, j + 1), v(k, j + 1)});
  return s;
}

double wrap(double a) { return std::remainder(a, 2 * M_PI); }

double signedArea(const SurfaceMap& map, const std::array<int, 3>& t) {
  const Eigen::Vector2d a = map.uv[t[1]] - map.uv[t[0]], b = map.uv[t[2]] - map.uv[t[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

}  // namespace

// A flat ring r 5..10 is conformal to the rectangle [0, 2 pi] x [log 0.5, 0] by (polar angle, log(r / 10)): the
// map's inner radius is 0.5 (modulus log 2, from the Dirichlet energy of the height), every point's height is
// log(r / 10) and its angle its polar angle up to one rotation (the map is free on both rims).
TEST(SurfaceMap, AnnulusMapOfAFlatRingIsItsLogPolarMap) {
  const ChordalSurface s = ring(5, 10, 12, 96);
  const SurfaceMap map = mapToPlane(s, 1.0, MapBoundary::Annulus);
  ASSERT_FALSE(map.empty());
  EXPECT_NEAR(map.innerRadius, 0.5, 0.01);
  // The map keeps its rims counter-clockwise in the plane: round the ring one way or the other (a mirror).
  const double sense = wrap(map.uv[1].x() - map.uv[0].x()) > 0 ? 1 : -1;
  auto polar = [&](const Vec3& p) { return sense * std::atan2(p.y(), p.x()); };
  const double turn = wrap(map.uv[0].x() - polar(s.vertices[0]));
  double worstHeight = 0, worstAngle = 0;
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const Vec3& p = s.vertices[i];
    worstHeight = std::max(worstHeight, std::abs(map.uv[i].y() - std::log(std::hypot(p.x(), p.y()) / 10)));
    worstAngle = std::max(worstAngle, std::abs(wrap(map.uv[i].x() - polar(p) - turn)));
  }
  EXPECT_LT(worstHeight, 0.01);
  EXPECT_LT(worstAngle, 0.01);
}

// An elliptic ring (squashed 2:1, as a tube's oblique cut is): its ring grid has square quads (the map is
// conformal), where angles by arc length along the rims would shear them.
TEST(SurfaceMap, RingGridOfAnEllipticRingHasSquareQuads) {
  const ChordalSurface s = ring(5, 10, 16, 128, 0.5);
  const SurfaceMap map = mapToPlane(s, 0.5, MapBoundary::Annulus);
  ASSERT_FALSE(map.empty()) << "the map";
  const BlockGrid grid = ringGrid(map, [](const Vec3&) { return 0.5; });
  ASSERT_FALSE(grid.empty()) << "the grid";
  double worst = 1, mean = 0;
  for (const auto& q : grid.quads) {
    const double sj = quadScaledJacobian({grid.nodes[q[0]], grid.nodes[q[1]], grid.nodes[q[2]], grid.nodes[q[3]]});
    worst = std::min(worst, std::abs(sj)), mean += std::abs(sj) / grid.quads.size();
  }
  EXPECT_GT(worst, 0.85);
  EXPECT_GT(mean, 0.97);
}

TEST(SurfaceMap, RectangleWithAHoleMapsOntoTheSquareWithoutFolds) {
  const SurfaceMap map = mapToPlane(rectangle(20, 10, {{8, 12, 3, 7}}), 1.0, MapBoundary::Square);
  ASSERT_FALSE(map.empty());
  EXPECT_TRUE(map.sharpCorners);
  EXPECT_EQ(map.holes.size(), 1u);
  EXPECT_EQ(map.points.size(), 21u * 11u - 9u + 1u);  // the hole's centre added
  for (const auto& t : map.triangles) EXPECT_GT(signedArea(map, t), 0);
  std::set<std::pair<double, double>> corners;
  for (int c : map.corners) corners.insert({map.points[map.rim[c]].x(), map.points[map.rim[c]].y()});
  EXPECT_EQ(corners, (std::set<std::pair<double, double>>{{0, 0}, {20, 0}, {0, 10}, {20, 10}}));
  for (const auto& uv : map.uv) EXPECT_LE(uv.cwiseAbs().maxCoeff(), 1 + 1e-12);
}

TEST(SurfaceMap, RefusesWhatIsNotASphereWithHoles) {
  ChordalSurface two = rectangle(4, 4);
  const ChordalSurface other = rectangle(4, 4);
  const int offset = static_cast<int>(two.vertices.size());
  for (const Vec3& p : other.vertices) two.vertices.push_back(p + Vec3(10, 0, 0)), two.normals.push_back(Vec3::UnitZ());
  for (auto f : other.facets) {
    for (int& v : f) v += offset;
    two.facets.push_back(f);
  }
  EXPECT_TRUE(mapToPlane(two, 1.0, MapBoundary::Square).empty());  // not connected
}
