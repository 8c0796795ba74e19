// The hash grid over boxes (core/box_grid.hpp): the nearest item to a point, as brute force finds it, on random
// segments of very different lengths (fixed seed), with the exact distance and with a bounding-box shortcut, also at
// points on and next to the segments and on the cells' faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/box_grid.hpp"

using namespace hexlayer;

namespace {

struct Segment {
  Vec3 a, b;
};

double squaredDistance(const Segment& s, const Vec3& p) {
  const Vec3 d = s.b - s.a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (s.a + t * d - p).squaredNorm();
}

// The nearest segment to p by brute force, the lowest id on a tie.
int nearestByBruteForce(const std::vector<Segment>& segments, const Vec3& p) {
  int best = -1;
  double bestD2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(segments.size()); ++i)
    if (const double d2 = squaredDistance(segments[i], p); d2 < bestD2) best = i, bestD2 = d2;
  return best;
}

// 300 segments in [0, 10]^3: most about 0.2 long, one in ten up to 6 long (an item in many cells).
std::vector<Segment> randomSegments(std::mt19937& random) {
  std::uniform_real_distribution<double> inside(0, 10), unit(-1, 1);
  std::vector<Segment> segments;
  for (int i = 0; i < 300; ++i) {
    const Vec3 a(inside(random), inside(random), inside(random));
    const double length = i % 10 == 0 ? 6 : 0.2;
    segments.push_back({a, a + length * Vec3(unit(random), unit(random), unit(random)).normalized()});
  }
  return segments;
}

// The segments in a grid of 0.5 cells, each by its bounding box.
BoxGrid gridOf(const std::vector<Segment>& segments) {
  BoxGrid grid(0.5);
  for (int i = 0; i < static_cast<int>(segments.size()); ++i)
    grid.insert(i, segments[i].a.cwiseMin(segments[i].b), segments[i].a.cwiseMax(segments[i].b));
  return grid;
}

}  // namespace

TEST(BoxGrid, NearestIsTheBruteForceNearestOnRandomSegments) {
  std::mt19937 random(17);
  const std::vector<Segment> segments = randomSegments(random);
  const BoxGrid grid = gridOf(segments);
  std::uniform_real_distribution<double> around(-5, 15);  // inside the grid's box and beyond it
  for (int q = 0; q < 500; ++q) {
    const Vec3 p(around(random), around(random), around(random));
    const int expected = nearestByBruteForce(segments, p);
    EXPECT_EQ(grid.nearest(p, [&](int id, double) { return squaredDistance(segments[id], p); }), expected)
        << "at " << p.transpose();
    // As the header allows: an item whose box is farther than the best so far returns anything above it.
    auto shortcut = [&](int id, double bestD2) {
      const Vec3 lo = segments[id].a.cwiseMin(segments[id].b), hi = segments[id].a.cwiseMax(segments[id].b);
      if ((p - p.cwiseMax(lo).cwiseMin(hi)).squaredNorm() > bestD2) return bestD2 * 2 + 1;
      return squaredDistance(segments[id], p);
    };
    EXPECT_EQ(grid.nearest(p, shortcut), expected) << "at " << p.transpose();
  }
}

// Points on the items and just off them (the quad smoothing's and the sweep's queries), and points on the cells'
// faces (no clearance in their cell): the search stops as soon as the nearest found is nearer than p's clearance in
// its cell plus the rings scanned, and still finds brute force's nearest.
TEST(BoxGrid, NearestOnAndNextToTheItemsAndOnCellFacesIsTheBruteForceNearest) {
  std::mt19937 random(23);
  const std::vector<Segment> segments = randomSegments(random);
  const BoxGrid grid = gridOf(segments);
  std::uniform_real_distribution<double> share(0, 1), unit(-1, 1);
  std::uniform_int_distribution<int> which(0, static_cast<int>(segments.size()) - 1), cell(0, 20);
  for (int q = 0; q < 1500; ++q) {
    const Segment& s = segments[which(random)];
    Vec3 p = s.a + share(random) * (s.b - s.a);
    if (q % 3 == 1) p += 1e-9 * Vec3(unit(random), unit(random), unit(random));
    if (q % 3 == 2) p.x() = 0.5 * cell(random);  // on a face between two cells
    const int expected = nearestByBruteForce(segments, p);
    EXPECT_EQ(grid.nearest(p, [&](int id, double) { return squaredDistance(segments[id], p); }), expected)
        << "at " << p.transpose();
  }
}

TEST(BoxGrid, PointsThatAreNotFiniteFindNothingAndFarPointsTheNearest) {
  BoxGrid grid(1.0);
  grid.insert(0, Vec3(0, 0, 0), Vec3(1, 1, 1));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(grid.nearest(Vec3(nan, 0, 0), [](int, double) { return 0.0; }), -1);
  EXPECT_EQ(grid.nearest(Vec3(1e300, -1e300, 0), [](int, double) { return 1.0; }), 0) << "far away: still found";
}

// An empty grid finds nothing (its box is [INT_MAX, INT_MIN]: the rings it scanned ran up to INT_MAX, and a
// ChordalLocator of a surface without facets hung in locate, before the empty grid was answered at once).
TEST(BoxGrid, EmptyGridFindsNothing) {
  BoxGrid empty(1.0);
  EXPECT_EQ(empty.nearest(Vec3(1, 2, 3), [](int, double) { return 0.0; }), -1);
}

// Two items as near: the lower id, whatever the order they were inserted or their cells visited.
TEST(BoxGrid, TiesGoToTheLowestId) {
  BoxGrid grid(1.0);
  grid.insert(7, Vec3(2, 0, 0), Vec3(2, 0, 0));
  grid.insert(3, Vec3(-2, 0, 0), Vec3(-2, 0, 0));
  grid.insert(5, Vec3(0, 2, 0), Vec3(0, 2, 0));
  EXPECT_EQ(grid.nearest(Vec3(0, 0, 0), [](int, double) { return 4.0; }), 3);
}
