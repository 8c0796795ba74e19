// The boxes' bounding volume hierarchy (core/box_tree.hpp): where a ray enters a box (also along an axis, with
// zero direction components), and the items a walk visits, checked against testing every box, on a grid of
// unit boxes at three scales.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/box_tree.hpp"

using namespace hexlayer;

TEST(BoxTree, WhereARayEntersABox) {
  const Box b{Vec3(1, 1, 1), Vec3(2, 3, 4)};
  EXPECT_DOUBLE_EQ(rayEntersBox(Vec3(0, 2, 2), Vec3(1, 0, 0), b, 0, 10), 1) << "along x, zero y and z";
  EXPECT_DOUBLE_EQ(rayEntersBox(Vec3(0, 0, 0), Vec3(1, 1, 1), b, 0, 10), 1);
  EXPECT_EQ(rayEntersBox(Vec3(0, 0, 2), Vec3(1, 0, 0), b, 0, 10), INFINITY) << "beside the box";
  EXPECT_EQ(rayEntersBox(Vec3(0, 2, 2), Vec3(1, 0, 0), b, 0, 0.5), INFINITY) << "ends before it";
  EXPECT_EQ(rayEntersBox(Vec3(0, 2, 2), Vec3(-1, 0, 0), b, 0, 10), INFINITY) << "points away";
  EXPECT_DOUBLE_EQ(rayEntersBox(Vec3(0, 2, 2), Vec3(-1, 0, 0), b, -10, 10), -2) << "a line: behind counts";
  EXPECT_DOUBLE_EQ(rayEntersBox(Vec3(1.5, 2, 2), Vec3(0, 0, 1), b, 0, 10), 0) << "from inside";
  EXPECT_DOUBLE_EQ(squaredDistanceToBox(Vec3(0, 0, 1.5), b), 2);
  EXPECT_DOUBLE_EQ(squaredDistanceToBox(Vec3(1.5, 2, 2), b), 0);
}

TEST(BoxTree, AWalkVisitsTheBoxesARayMeetsAndThoseNearAPoint) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    std::vector<Box> boxes;  // a 7 x 5 x 3 grid of unit cubes with gaps of 1
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 5; ++j)
        for (int k = 0; k < 3; ++k)
          boxes.push_back({Vec3(2 * i, 2 * j, 2 * k) * s, Vec3(2 * i + 1, 2 * j + 1, 2 * k + 1) * s});
    const BoxTree tree(boxes);
    const Vec3 from = Vec3(-1, 0.5, 0.5) * s;
    for (const Vec3& dir : {Vec3(1, 0, 0), Vec3(1, 0.3, 0.1), Vec3(1, 1, 1)}) {
      std::vector<int> visited, expected;
      tree.traverse([&](const Box& b) { return rayEntersBox(from, dir, b, 0, INFINITY) < INFINITY; },
                    [&](int i) {
                      if (rayEntersBox(from, dir, boxes[i], 0, INFINITY) < INFINITY) visited.push_back(i);
                      return false;
                    });
      for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
        if (rayEntersBox(from, dir, boxes[i], 0, INFINITY) < INFINITY) expected.push_back(i);
      std::sort(visited.begin(), visited.end());
      EXPECT_EQ(visited, expected);
      EXPECT_FALSE(expected.empty());
    }
    const Vec3 p = Vec3(7.5, 5.5, 3.5) * s;  // in the gap between 8 cubes, 0.87 from each
    std::vector<int> near;
    tree.traverse([&](const Box& b) { return squaredDistanceToBox(p, b) <= s * s; },
                  [&](int i) {
                    if (squaredDistanceToBox(p, boxes[i]) <= s * s) near.push_back(i);
                    return false;
                  });
    EXPECT_EQ(near.size(), 8u);
  }
}
