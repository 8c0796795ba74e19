// The point grid (core/point_grid.hpp): the queries the bubble packing relies on, against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/point_grid.hpp"

using namespace hexlayer;

TEST(PointGrid, QueriesFindExactlyThePointsWithinTheRadiusInCellOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> along(-5, 5), across(0, 0.5);
  PointGrid grid(1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 400; ++i)
    points.push_back(Vec3(along(random), along(random), across(random))), grid.insert(i, points.back());
  for (int q = 0; q < 50; ++q) {
    const Vec3 p(along(random), along(random), along(random));
    std::vector<int> found, expected;
    grid.forEachNear(p, 1.7, [&](int id, const Vec3&) { found.push_back(id); });
    for (int i = 0; i < 400; ++i)
      if ((points[i] - p).squaredNorm() <= 1.7 * 1.7) expected.push_back(i);
    std::vector<int> sorted = found;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, expected);
    EXPECT_EQ(grid.anyNear(p, 1.7, [](int, const Vec3&) { return true; }), !expected.empty());
    int first = -1;
    grid.anyNear(p, 1.7, [&](int id, const Vec3&) { return first = id, true; });
    EXPECT_EQ(first, found.empty() ? -1 : found.front()) << "stops at the first point forEachNear visits";
  }
}
