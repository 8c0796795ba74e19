// The point grid (core/point_grid.hpp): the queries the bubble packing relies on, against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>
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

// The order forEachNear documents (cell by cell, x then y then z, each cell in the order of insertion), over points
// spread on many cells either side of the origin (the cell table grown many times over) and near a plane off the
// axes; every point found once.
TEST(PointGrid, PointsComeCellByCellInInsertionOrderAcrossManyCells) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> along(-300, 300), across(-2, 2);
  const double cell = 1.5;
  PointGrid grid(cell);
  std::vector<Vec3> points;
  for (int i = 0; i < 30000; ++i) {
    const double x = along(random), y = along(random);
    points.push_back(Vec3(x, y, 0.3 * x - 0.2 * y + across(random)));
    grid.insert(i, points.back());
  }
  auto cellOf = [&](const Vec3& p) {
    return std::array<long, 3>{static_cast<long>(std::floor(p.x() / cell)), static_cast<long>(std::floor(p.y() / cell)),
                               static_cast<long>(std::floor(p.z() / cell))};
  };
  for (int q = 0; q < 40; ++q) {
    const Vec3 p = points[q * 701];
    const double radius = 4.0;
    std::vector<int> found;
    grid.forEachNear(p, radius, [&](int id, const Vec3& at) {
      EXPECT_EQ(at, points[id]);
      found.push_back(id);
    });
    std::vector<std::pair<std::array<long, 3>, int>> expected;
    for (int i = 0; i < static_cast<int>(points.size()); ++i)
      if ((points[i] - p).squaredNorm() <= radius * radius) expected.push_back({cellOf(points[i]), i});
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(found.size(), expected.size());
    for (std::size_t k = 0; k < found.size(); ++k) EXPECT_EQ(found[k], expected[k].second);
  }
}
