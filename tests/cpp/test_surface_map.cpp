// The map of the chordal surface onto the plane (quadmesh/surface_map.hpp): a rectangle with a hole onto the square
// without folds, its corners found, what is not a sphere with holes refused; and the annulus map for rings and
// tubes: conformal, against the analytic map of a flat ring (log-polar coordinates).
#include <gtest/gtest.h>

#include <algorithm>
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

// A patch mapped onto the square at the corners it is given (a face of the patch grid): the rectangle's rim walked
// clockwise from (20, 10) with its corners there, its hole either way round: the corners on the square's, no
// triangle folded (all turned one way), the hole walked counter-clockwise in the plane; corners not ascending from
// 0 are refused.
TEST(SurfaceMap, APatchMapsOntoTheSquareAtTheCornersItIsGiven) {
  const ChordalSurface r = rectangle(20, 10, {{8, 12, 3, 7}});
  auto at = [&](int x, int y) {
    for (std::size_t v = 0; v < r.vertices.size(); ++v)
      if (r.vertices[v] == Vec3(x, y, 0)) return static_cast<int>(v);
    return -1;
  };
  std::vector<int> rim, hole;
  for (int y = 10; y > 0; --y) rim.push_back(at(20, y));
  for (int x = 20; x > 0; --x) rim.push_back(at(x, 0));
  for (int y = 0; y < 10; ++y) rim.push_back(at(0, y));
  for (int x = 0; x < 20; ++x) rim.push_back(at(x, 10));
  for (int x = 8; x < 12; ++x) hole.push_back(at(x, 3));
  for (int y = 3; y < 7; ++y) hole.push_back(at(12, y));
  for (int x = 12; x > 8; --x) hole.push_back(at(x, 7));
  for (int y = 7; y > 3; --y) hole.push_back(at(8, y));
  for (const bool reversed : {false, true}) {
    std::vector<int> h = hole;
    if (reversed) std::reverse(h.begin(), h.end());
    const SurfaceMap map = mapOntoSquare(r.vertices, chordalTriangles(r), rim, {0, 10, 30, 40}, {h});
    ASSERT_FALSE(map.empty());
    const std::array<Eigen::Vector2d, 4> square{{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}};
    for (int k = 0; k < 4; ++k) EXPECT_LT((map.uv[rim[map.corners[k]]] - square[k]).norm(), 1e-12);
    const std::vector<std::array<int, 3>> own = chordalTriangles(r);  // the map's first triangles (then the fan's)
    const double first = signedArea(map, map.triangles.front());
    for (std::size_t t = 0; t < own.size(); ++t) EXPECT_GT(signedArea(map, map.triangles[t]) * first, 0);
    ASSERT_EQ(map.holes.size(), 1u);
    double twice = 0;
    for (std::size_t i = 0; i < map.holes[0].size(); ++i) {
      const Eigen::Vector2d& a = map.uv[map.holes[0][i]];
      const Eigen::Vector2d& b = map.uv[map.holes[0][(i + 1) % map.holes[0].size()]];
      twice += a.x() * b.y() - b.x() * a.y();
    }
    EXPECT_GT(twice, 0);
  }
  EXPECT_TRUE(mapOntoSquare(r.vertices, chordalTriangles(r), rim, {0, 30, 10, 40}, {hole}).empty());
  EXPECT_TRUE(mapOntoSquare(r.vertices, chordalTriangles(r), rim, {1, 10, 30, 40}, {hole}).empty());
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

namespace {

// A strip of quads (split on a diagonal) across a bend: `flat` long on the floor (z = 0), a quarter cylinder of
// radius r, `flat` up the wall (x = -r), `width` along y; every length times `scale`. Points along the strip's
// length first, then across.
struct BentStrip {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  double length = 0;  // along the unbent strip
};

BentStrip bentStrip(double flat, double r, double width, double scale) {
  BentStrip s;
  const int along = 24, across = 4;
  s.length = 2 * flat + M_PI / 2 * r;
  for (int i = 0; i <= along; ++i) {
    const double t = s.length * i / along;  // arc length from the floor's far end
    Vec3 p;
    if (t <= flat)
      p = Vec3(flat - t, 0, 0);
    else if (t <= flat + M_PI / 2 * r) {
      const double a = (t - flat) / r;  // turned about the bend's axis (x = 0, z = r)
      p = Vec3(-r * std::sin(a), 0, r - r * std::cos(a));
    } else {
      p = Vec3(-r, 0, r + t - flat - M_PI / 2 * r);
    }
    for (int j = 0; j <= across; ++j) s.points.push_back(scale * (p + Vec3(0, width * j / across, 0)));
  }
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const int a = i * (across + 1) + j, b = a + across + 1;
      // Every other quad's triangles turned the other way: the map orients them alike itself.
      if ((i + j) % 2) {
        s.triangles.push_back({a, b, b + 1}), s.triangles.push_back({a, b + 1, a + 1});
      } else {
        s.triangles.push_back({a, a + 1, b + 1}), s.triangles.push_back({a, b + 1, b});
      }
    }
  return s;
}

}  // namespace

// LSCM (unfoldConformally): a strip across a bend is developable, so it unfolds exactly up to its facets: every
// edge keeps its length (within the chord-to-arc difference of the facets), the strip is as long as unbent and as
// wide, every triangle counter-clockwise in the plane; on copies scaled by 1e-3 and 1e3. A strip in two pieces is
// refused (empty map).
TEST(SurfaceMap, ConformalMapUnfoldsAStripAcrossABend) {
  for (double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(scale);
    const BentStrip strip = bentStrip(10, 4, 3, scale);
    const SurfaceMap map = unfoldConformally(strip.points, strip.triangles);
    ASSERT_FALSE(map.empty());
    double worst = 0;
    for (const auto& t : map.triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const double in3d = (map.points[a] - map.points[b]).norm(), in2d = (map.uv[a] - map.uv[b]).norm();
        worst = std::max(worst, std::abs(in2d / in3d - 1));
      }
    EXPECT_LT(worst, 1e-2);
    for (const auto& t : map.triangles) {
      const Eigen::Vector2d u = map.uv[t[1]] - map.uv[t[0]], v = map.uv[t[2]] - map.uv[t[0]];
      EXPECT_GT(u.x() * v.y() - u.y() * v.x(), 0);
    }
    const int last = static_cast<int>(strip.points.size()) - 5;  // the far end's first point
    const double chordLength = (map.uv[last] - map.uv[0]).norm();
    EXPECT_NEAR(chordLength / scale, strip.length, 1e-2 * strip.length);
    EXPECT_NEAR((map.uv[4] - map.uv[0]).norm() / scale, 3, 1e-2 * 3);
  }
  BentStrip two = bentStrip(10, 4, 3, 1);
  two.triangles.erase(two.triangles.begin() + 40, two.triangles.begin() + 48);  // a row of quads taken out
  EXPECT_TRUE(unfoldConformally(two.points, two.triangles).empty());
}

// A ring of triangles onto a flat annulus (unfoldRing): a flat ring r 5..10 comes back as itself up to a similarity
// (every point at |uv| proportional to its radius, the annulus's centre at the origin), a tube of radius 3 and height
// 4 as the annulus of radii ratio exp(-2 pi 4 / its girth) (conformal: the log-polar rectangle taken through exp);
// every triangle counter-clockwise, the area the triangles'; on copies scaled by 1e-3 and 1e3. A disc (a rectangle)
// is not a ring (empty).
TEST(SurfaceMap, RingUnfoldsOntoAFlatAnnulus) {
  constexpr int kAround = 96, kRings = 12;
  for (double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(scale);
    for (const bool tube : {false, true}) {
      const ChordalSurface flat = ring(5, 10, kRings, kAround);
      std::vector<Vec3> points;  // the flat ring, or its rows stood up as a tube of radius 3 and height 4
      for (std::size_t i = 0; i < flat.vertices.size(); ++i) {
        const Vec3& p = flat.vertices[i];
        const double k = static_cast<double>(i / kAround) / kRings;
        points.push_back(scale * (tube ? Vec3(3 * p.x() / p.norm(), 3 * p.y() / p.norm(), 4 * k) : p));
      }
      auto v = [&](int k, int j) { return k * kAround + j % kAround; };  // ring()'s vertex of row k, column j
      const SurfaceMap map = unfoldRing(points, chordalTriangles(flat));
      ASSERT_FALSE(map.empty());
      double area3 = 0, area2 = 0;
      for (const auto& t : map.triangles) {
        area3 += 0.5 * (map.points[t[1]] - map.points[t[0]]).cross(map.points[t[2]] - map.points[t[0]]).norm();
        area2 += signedArea(map, t);
        EXPECT_GT(signedArea(map, t), 0);
      }
      EXPECT_NEAR(area2 / area3, 1, 1e-9);
      auto radius = [&](int i) { return map.uv[i].norm(); };
      if (!tube) {
        for (std::size_t i = 0; i < points.size(); ++i)
          EXPECT_NEAR(radius(static_cast<int>(i)) / radius(0) * points[0].norm() / points[i].norm(), 1, 0.01);
      } else {
        const double girth = kAround * 2 * 3 * std::sin(M_PI / kAround);  // the polygon's, as the triangles run
        const double ratio = radius(v(kRings, 0)) / radius(v(0, 0));      // either rim may be the inner one
        EXPECT_NEAR(std::min(ratio, 1 / ratio), std::exp(-2 * M_PI * 4 / girth), 0.01);
        for (int j = 0; j < kAround; ++j) EXPECT_NEAR(radius(v(0, j)) / radius(v(0, 0)), 1, 0.01);
      }
    }
  }
  const ChordalSurface plain = rectangle(10, 6);
  EXPECT_TRUE(unfoldRing(plain.vertices, chordalTriangles(plain)).empty());
}
