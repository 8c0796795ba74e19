// Structured block grids of the chordal surface (quadmesh/block_grids.hpp): the grids are all-quad, square and
// keep the surface's topology and extent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "core/union_find.hpp"
#include "quadmesh/block_grids.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "test_flat_surfaces.hpp"

using namespace hexlayer;
using hexlayer::test_flat_surfaces::rectangle;

namespace {

// A flat disc of radius `rings`: a fan round the centre, then rings of `around` quads.
ChordalSurface disc(int rings, int around) {
  ChordalSurface s;
  s.vertices.emplace_back(0, 0, 0);
  for (int k = 1; k <= rings; ++k)
    for (int j = 0; j < around; ++j)
      s.vertices.emplace_back(k * std::cos(2 * M_PI * j / around), k * std::sin(2 * M_PI * j / around), 0);
  s.normals.assign(s.vertices.size(), Vec3::UnitZ());
  auto v = [&](int k, int j) { return 1 + (k - 1) * around + j % around; };
  for (int j = 0; j < around; ++j) s.facets.push_back({0, v(1, j), v(1, j + 1), -1});
  for (int k = 1; k < rings; ++k)
    for (int j = 0; j < around; ++j) s.facets.push_back({v(k, j), v(k + 1, j), v(k + 1, j + 1), v(k, j + 1)});
  return s;
}

long euler(const BlockGrid& g) {
  std::set<std::uint64_t> edges;
  for (const auto& q : g.quads)
    for (int k = 0; k < 4; ++k) edges.insert(edgeKey(q[k], q[(k + 1) % 4]));
  return static_cast<long>(g.nodes.size()) - static_cast<long>(edges.size()) + static_cast<long>(g.quads.size());
}

struct Quality {
  double worst = 1, mean = 0, area = 0;
};

// Quad scaled Jacobians (each quad counter-clockwise seen from +z: a flipped quad counts negative)
// and the total area.
Quality quality(const BlockGrid& g) {
  Quality q;
  for (const auto& quad : g.quads) {
    const std::array<Vec3, 4> p{g.nodes[quad[0]], g.nodes[quad[1]], g.nodes[quad[2]], g.nodes[quad[3]]};
    const Vec3 n = (p[2] - p[0]).cross(p[3] - p[1]);
    const double sj = (n.z() > 0 ? 1 : -1) * quadScaledJacobian(p);
    q.worst = std::min(q.worst, sj), q.mean += sj / g.quads.size(), q.area += 0.5 * n.norm();
  }
  return q;
}

const SizeField unit = [](const Vec3&) { return 1.0; };

// A square map's rim as given nodes (a face of the patch grid): n0 x n1 cells, the points evenly along the rim's
// sides, moved a little off it (as a crease's averaged path runs).
SquareRim evenRim(const SurfaceMap& map, int n0, int n1) {
  const std::vector<double> length = arcLength(map.rim, map.points);
  SquareRim rim{n0, n1, {}};
  for (int k = 0; k < 4; ++k) {
    const double from = length[map.corners[k]], to = length[k == 3 ? map.rim.size() : map.corners[k + 1]];
    const int n = k % 2 == 0 ? n0 : n1;
    for (int i = 0; i < n; ++i) {
      LoopPoint p = loopPoint(map, map.rim, length, from + (to - from) * i / n);
      p.x += Vec3(0, 0, 1e-3);
      rim.points.push_back(p);
    }
  }
  return rim;
}

// A flat triangle a, b, c (counter-clockwise seen from +z) cut into n^2 triangles.
ChordalSurface triangle(const Vec3& a, const Vec3& b, const Vec3& c, int n) {
  ChordalSurface s;
  auto v = [&](int i, int j) { return i * (n + 1) - i * (i - 1) / 2 + j; };  // i + j <= n
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) s.vertices.push_back(a + (b - a) * i / n + (c - a) * j / n);
  s.normals.assign(s.vertices.size(), Vec3::UnitZ());
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      s.facets.push_back({v(i, j), v(i + 1, j), v(i, j + 1), -1});
      if (i + j + 1 < n) s.facets.push_back({v(i + 1, j), v(i + 1, j + 1), v(i, j + 1), -1});
    }
  return s;
}

}  // namespace

TEST(BlockGrids, GridWithAPocketRoundTheHole) {
  const SurfaceMap map = mapToPlane(rectangle(20, 10, {{8, 12, 3, 7}}), 1.0, MapBoundary::Square);
  const BlockGrid g = holedGrid(map, unit);
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.blocks, 5u);
  EXPECT_EQ(euler(g), 0);  // an annulus, like the surface
  const Quality q = quality(g);
  EXPECT_GT(q.worst, 0.6);
  EXPECT_GT(q.mean, 0.95);
  EXPECT_NEAR(q.area, 200 - 16, 1e-9);
  EXPECT_NEAR(static_cast<double>(g.quads.size()), 184, 30);  // unit quads
}

// The rim's nodes given (a face of the patch grid): 10 x 5 cells, the given points evenly along the rim's sides,
// moved a little off it (as a crease's averaged path runs): they are the grid's first nodes, in order; the grid has
// its pocket and the same area; a hole in a corner cell of the rim (a bend relief) gets a pocket on the rim; a wrong
// number of points is refused.
TEST(BlockGrids, GridWithAPocketOnTheRimNodesItIsGiven) {
  for (const auto& [hole, n0, n1] :
       {std::tuple{std::array<int, 4>{8, 12, 3, 7}, 10, 5}, std::tuple{std::array<int, 4>{18, 19, 8, 9}, 10, 5}}) {
    const SurfaceMap map = mapToPlane(rectangle(20, 10, {hole}), 1.0, MapBoundary::Square);
    ASSERT_FALSE(map.empty());
    const SquareRim rim = evenRim(map, n0, n1);
    const BlockGrid g = holedGrid(map, unit, rim);
    ASSERT_FALSE(g.empty());
    for (std::size_t t = 0; t < rim.points.size(); ++t) EXPECT_EQ(g.nodes[t], rim.points[t].x);
    EXPECT_EQ(g.blocks, 5u);
    EXPECT_EQ(euler(g), 0);
    const Quality q = quality(g);
    EXPECT_GT(q.worst, 0.2);
    EXPECT_NEAR(q.area, 200 - (hole[1] - hole[0]) * (hole[3] - hole[2]), 0.05);
    SquareRim fewer = rim;
    fewer.points.pop_back();
    EXPECT_TRUE(holedGrid(map, unit, fewer).empty());
  }
  // without the rim's nodes given, the hole in the corner cell (quads of 2) has no pocket
  const SizeField two = [](const Vec3&) { return 2.0; };
  EXPECT_TRUE(holedGrid(mapToPlane(rectangle(20, 10, {{18, 19, 8, 9}}), 1.0, MapBoundary::Square), two).empty());
}

TEST(BlockGrids, OGridOfADisc) {
  const SurfaceMap map = mapToPlane(disc(10, 64), 1.0, MapBoundary::Circle);
  EXPECT_FALSE(map.sharpCorners);
  const BlockGrid g = oGrid(map, unit);
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.blocks, 5u);
  EXPECT_EQ(euler(g), 1);
  const Quality q = quality(g);
  EXPECT_GT(q.worst, 0.6);
  EXPECT_GT(q.mean, 0.9);
  const double polygon = 0.5 * 64 * 100 * std::sin(2 * M_PI / 64);  // the disc's area
  EXPECT_NEAR(q.area, polygon, 0.02 * polygon);
  for (const Vec3& p : g.nodes) EXPECT_LE(p.norm(), 10 + 1e-9);
  EXPECT_TRUE(
      oGrid(mapToPlane(rectangle(20, 10, {{8, 12, 3, 7}}), 1.0, MapBoundary::Circle), unit).empty());  // has a hole
}

// A triangle gets three blocks, one per corner (each corner one quad's), where the square grid puts a straight angle
// at the middle of its longest side; equilateral, right isosceles and obtuse, at 1e-3, 1 and 1e3.
TEST(BlockGrids, TriangleGridOfATriangle) {
  const auto flat = [](const Vec3& p) { return Vec3(p.x(), p.y(), 0); };
  const std::vector<std::array<Vec3, 3>> triangles{{Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(10, 10 * std::sqrt(3.0), 0)},
                                                   {Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(0, 20, 0)},
                                                   {Vec3(0, 0, 0), Vec3(30, 0, 0), Vec3(8, 9, 0)}};
  // its smallest corner caps a quad's scaled Jacobian at its sine: sin 60° = 0.87, sin 45° = 0.71, sin 22.2° = 0.378
  const std::vector<double> worst{0.8, 0.6, 0.37};
  for (double scale : {1e-3, 1.0, 1e3})
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto& [a, b, c] = triangles[t];
      const SurfaceMap map = mapToPlane(triangle(a * scale, b * scale, c * scale, 24), scale, MapBoundary::Square);
      ASSERT_GE(map.sideMiddle, 0) << t;
      const SizeField size = [&](const Vec3&) { return 2 * scale; };
      const BlockGrid g = triangleGrid(map, size, flat);
      ASSERT_FALSE(g.empty()) << t;
      EXPECT_EQ(g.blocks, 3u);
      EXPECT_EQ(euler(g), 1);
      const Quality q = quality(g);
      const double area = 0.5 * (b - a).cross(c - a).norm() * scale * scale;
      EXPECT_NEAR(q.area, area, 1e-3 * area) << t;
      EXPECT_GT(q.worst, worst[t]) << t << " scale " << scale;
      EXPECT_GT(q.worst, quality(holedGrid(map, size)).worst + 0.1) << t;
      for (const Vec3& corner : {a, b, c}) {  // a node, in one quad
        int quads = 0;
        for (const auto& quad : g.quads)
          for (int n : quad) quads += (g.nodes[n] - corner * scale).norm() < 1e-9 * scale;
        EXPECT_EQ(quads, 1) << t;
      }
    }
  EXPECT_LT(mapToPlane(rectangle(20, 10), 1.0, MapBoundary::Square).sideMiddle, 0);  // four corners
  EXPECT_TRUE(triangleGrid(mapToPlane(rectangle(20, 10), 1.0, MapBoundary::Square), unit, flat).empty());
}

TEST(BlockGrids, PocketsThatMeetAreRefused) {
  // two holes one cell apart: their pockets (one cell beyond each hole) overlap
  const ChordalSurface s = rectangle(20, 10, {{6, 9, 3, 7}, {10, 13, 3, 7}});
  const SurfaceMap map = mapToPlane(s, 1.0, MapBoundary::Square);
  ASSERT_EQ(map.holes.size(), 2u);
  EXPECT_TRUE(holedGrid(map, unit).empty());
}

namespace {

// The surface scaled by `factor` about the origin.
ChordalSurface scaled(ChordalSurface s, double factor) {
  for (Vec3& p : s.vertices) p *= factor;
  return s;
}

// The area of a flat surface's facets (quads split on a diagonal).
double area(const ChordalSurface& s) {
  double a = 0;
  for (const auto& f : s.facets) {
    const Vec3 &p = s.vertices[f[0]], &q = s.vertices[f[1]], &r = s.vertices[f[2]];
    a += 0.5 * (q - p).cross(r - p).norm();
    if (f[3] >= 0) a += 0.5 * (r - p).cross(s.vertices[f[3]] - p).norm();
  }
  return a;
}

// Holes of w x h cells in `columns` x `rows`, `gapX` and `gapY` cells apart, the first at (x0, y0).
std::vector<std::array<int, 4>> holeRows(int columns, int rows, int w, int h, int gapX, int gapY, int x0, int y0) {
  std::vector<std::array<int, 4>> holes;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int x = x0 + i * (w + gapX), y = y0 + j * (h + gapY);
      holes.push_back({x, x + w, y, y + h});
    }
  return holes;
}

// What the shared grid of a surface gave.
struct Shared {
  std::size_t quads = 0, nodes = 0, blocks = 0;
  Quality quality;
};

// The shared grid of a flat surface with `holes` holes, at scale 1, 1e-3 and 1e3 (the quad size `quad` scaled with it):
// laid out, every quad valid, the surface's topology, its area within `areaTolerance` (relative), the same counts and
// shape at every scale. Returns scale 1's.
Shared expectSharedGrid(const ChordalSurface& surface, int holes, double areaTolerance, double quad = 1) {
  Shared first;
  for (const double factor : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE(factor);
    const ChordalSurface s = scaled(surface, factor);
    const SizeField size = [&](const Vec3&) { return quad * factor; };
    const SurfaceMap map = mapToPlane(s, quad * factor, MapBoundary::Square);
    EXPECT_EQ(map.holes.size(), static_cast<std::size_t>(holes));
    const BlockGrid g = sharedGrid(map, size);
    EXPECT_FALSE(g.empty());
    if (g.empty()) return first;
    EXPECT_EQ(euler(g), 1 - holes);
    Quality q = quality(g);
    EXPECT_GT(q.worst, 0);
    EXPECT_NEAR(q.area, area(s), areaTolerance * area(s));
    q.area /= factor * factor;
    const Shared now{g.quads.size(), g.nodes.size(), g.blocks, q};
    if (factor == 1.0) {
      first = now;
      continue;
    }
    EXPECT_EQ(now.quads, first.quads);
    EXPECT_EQ(now.nodes, first.nodes);
    EXPECT_EQ(now.blocks, first.blocks);
    EXPECT_NEAR(now.quality.worst, first.quality.worst, 1e-6);
    EXPECT_NEAR(now.quality.mean, first.quality.mean, 1e-6);
  }
  return first;
}

}  // namespace

TEST(BlockGrids, SharedGridRoundAGridOfCutouts) {
  // 4 x 3 cutouts of 7 x 6 cells, 1 apart: the pockets would meet; the grid's lines run along the cutouts' sides
  const ChordalSurface s = rectangle(37, 27, holeRows(4, 3, 7, 6, 1, 1, 3, 3));
  EXPECT_TRUE(holedGrid(mapToPlane(s, 1, MapBoundary::Square), unit).empty());
  const Shared g = expectSharedGrid(s, 12, 1e-9);
  EXPECT_EQ(g.blocks, 1u);                 // one structured block: every inside node regular
  EXPECT_EQ(g.quads, 37u * 27 - 12 * 42);  // unit squares
  EXPECT_EQ(g.nodes, s.vertices.size());   // on the surface's own vertices
  EXPECT_GT(g.quality.worst, 0.999);
}

// The rim's nodes given (a face of the patch grid whose holes' pockets would meet): 4 x 3 cutouts of 7 x 6 cells, 1
// apart, in a plate of 37 x 27. With 37 x 27 cells on the rim the lines run on the cutouts' sides (unit squares); with
// 45 x 31 the rim's lines are moved onto them, the rest spread between (all quads square enough); the grid's first
// nodes are the rim's points in order, its area the plate's less the cutouts'. Fewer cells than the cutouts' sides
// need lines (8 along the plate: 9 of them inside) give no grid.
TEST(BlockGrids, SharedGridOnTheRimNodesItIsGiven) {
  const SurfaceMap map = mapToPlane(rectangle(37, 27, holeRows(4, 3, 7, 6, 1, 1, 3, 3)), 1.0, MapBoundary::Square);
  ASSERT_FALSE(map.empty());
  for (const auto& [n0, n1, worst] : {std::tuple{37, 27, 0.999}, std::tuple{45, 31, 0.6}}) {
    const SquareRim rim = evenRim(map, n0, n1);
    EXPECT_TRUE(holedGrid(map, unit, rim).empty()) << "the pockets meet";
    const BlockGrid g = sharedGrid(map, unit, rim);
    ASSERT_FALSE(g.empty()) << n0 << " x " << n1;
    for (std::size_t t = 0; t < rim.points.size(); ++t) EXPECT_EQ(g.nodes[t], rim.points[t].x);
    EXPECT_EQ(euler(g), 1 - 12);
    const Quality q = quality(g);
    EXPECT_GT(q.worst, worst) << n0 << " x " << n1;
    EXPECT_NEAR(q.area, 37 * 27 - 12 * 42, 0.1);
    if (n0 == 37) EXPECT_EQ(g.quads.size(), 37u * 27 - 12 * 42);
  }
  EXPECT_TRUE(sharedGrid(map, unit, evenRim(map, 8, 27)).empty());
}

namespace {

// A keyboard plate's cutouts: 3 x 2 of 6 x 6 cells, 1 apart across and 4 along, each with a notch of 2 x 1 in the
// middle of its top and bottom sides, in a plate of 25 x 22.
std::vector<std::array<int, 4>> notchedCutouts() {
  std::vector<std::array<int, 4>> holes = holeRows(3, 2, 6, 6, 1, 4, 2, 3);
  for (std::size_t h = 0, n = holes.size(); h < n; ++h) {
    const auto [x0, x1, y0, y1] = holes[h];
    holes.push_back({x0 + 2, x0 + 4, y1, y1 + 1}), holes.push_back({x0 + 2, x0 + 4, y0 - 1, y0});
  }
  return holes;
}

}  // namespace

TEST(BlockGrids, SharedGridFollowsNotchedCutouts) {
  const ChordalSurface s = rectangle(25, 22, notchedCutouts());
  EXPECT_TRUE(holedGrid(mapToPlane(s, 1, MapBoundary::Square), unit).empty());
  const Shared g = expectSharedGrid(s, 6, 1e-9);
  EXPECT_EQ(g.blocks, 1u);
  EXPECT_EQ(g.quads, 25u * 22 - 6 * (36 + 4));  // the notches' corners on grid nodes
  EXPECT_EQ(g.nodes, s.vertices.size());
  EXPECT_GT(g.quality.worst, 0.999);
}

// The chordal rim can cut a notch's corner (the keyboard plate's): each notch's far left corner moved 0.3 into the
// notch. The cutouts are still laid out on the grid's lines, the corners' nodes on the moved points.
TEST(BlockGrids, SharedGridFollowsNotchesWhoseCornersTheRimCuts) {
  ChordalSurface s = rectangle(25, 22, notchedCutouts());
  const std::vector<std::array<int, 4>> holes = notchedCutouts();
  for (std::size_t h = 6; h < holes.size(); ++h) {
    const bool top = h % 2 == 0;  // a notch above its cutout
    const Vec3 corner(holes[h][0], top ? holes[h][3] : holes[h][2], 0);
    for (Vec3& p : s.vertices)
      if ((p - corner).norm() < 1e-9) p += Vec3(0.3, top ? -0.3 : 0.3, 0);
  }
  const Shared g = expectSharedGrid(s, 6, 1e-3);
  EXPECT_EQ(g.blocks, 1u);
  EXPECT_EQ(g.quads, 25u * 22 - 6 * (36 + 4));
  EXPECT_GT(g.quality.worst, 0.5);
  EXPECT_LT(g.quality.worst, 0.99);  // the quads at the cut corners
  EXPECT_GT(g.quality.mean, 0.98);
}

TEST(BlockGrids, SharedGridPocketsRoundOctagonsCloseTogether) {
  // 3 x 2 octagons (6 x 5 cells, chamfered) 1 cell apart: no line follows them; pockets half way to the next
  const ChordalSurface s = rectangle(30, 20, holeRows(3, 2, 6, 5, 1, 1, 3, 3), true);
  EXPECT_TRUE(holedGrid(mapToPlane(s, 1, MapBoundary::Square), unit).empty());
  const Shared g = expectSharedGrid(s, 6, 0.01);
  EXPECT_EQ(g.blocks, 1u + 4 * 6);
  EXPECT_GT(g.quality.worst, 0.55);  // unsmoothed; their spokes from the octagons' centres (0.24 by arc length)
  EXPECT_GT(g.quality.mean, 0.9);
}

TEST(BlockGrids, SharedGridWithHolesNearTheRim) {
  // quads of 2: an octagon and a cutout half a quad from the rim, where holedGrid's pockets would leave the square
  const ChordalSurface o = rectangle(24, 16, {{3, 11, 1, 8}}, true), c = rectangle(24, 16, {{14, 20, 11, 15}});
  const SizeField two = [](const Vec3&) { return 2.0; };
  EXPECT_TRUE(holedGrid(mapToPlane(o, 2, MapBoundary::Square), two).empty());
  EXPECT_TRUE(holedGrid(mapToPlane(c, 2, MapBoundary::Square), two).empty());
  const Shared octagon = expectSharedGrid(o, 1, 0.01, 2);
  EXPECT_EQ(octagon.blocks, 5u);  // its pocket's box on the rim
  EXPECT_GT(octagon.quality.worst, 0.55);
  EXPECT_GT(octagon.quality.mean, 0.9);
  const Shared cutout = expectSharedGrid(c, 1, 1e-9, 2);
  EXPECT_EQ(cutout.blocks, 1u);
  EXPECT_GT(cutout.quality.worst, 0.999);
}
