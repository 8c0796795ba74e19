#include "core/box_tree.hpp"

#include <algorithm>
#include <cmath>

namespace hexlayer {

namespace {
constexpr int kLeafSize = 4;
}  // namespace

double squaredDistanceToBox(const Vec3& p, const Box& box) {
  return (box.lo - p).cwiseMax(p - box.hi).cwiseMax(0.0).squaredNorm();
}

double rayEntersBox(const Vec3& p, const Vec3& dir, const Box& box, double tMin, double tMax) {
  for (int k = 0; k < 3; ++k) {  // slabs; a component along which the ray does not move keeps t as it is
    if (dir[k] == 0) {
      if (p[k] < box.lo[k] || p[k] > box.hi[k]) return INFINITY;
      continue;
    }
    double a = (box.lo[k] - p[k]) / dir[k], b = (box.hi[k] - p[k]) / dir[k];
    if (a > b) std::swap(a, b);
    tMin = std::max(tMin, a), tMax = std::min(tMax, b);
  }
  return tMin <= tMax ? tMin : INFINITY;
}

BoxTree::BoxTree(const std::vector<Box>& boxes) {
  order_.resize(boxes.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
  if (!boxes.empty()) build(boxes, 0, static_cast<int>(boxes.size()));
}

// Builds the subtree of order_[first, first + count), split at the median centre along the longest side of the
// centres' box; returns its node's index.
int BoxTree::build(const std::vector<Box>& boxes, int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Box all, centres;
  for (int i = first; i < first + count; ++i) {
    const Box& b = boxes[order_[i]];
    all.add(b.lo), all.add(b.hi), centres.add(b.centre());
  }
  const Vec3 pad = Vec3::Constant(1e-9 * (all.hi - all.lo).norm() + 1e-300);  // rounding of the box tests
  nodes_[index].box = {all.lo - pad, all.hi + pad};
  if (count <= kLeafSize) {
    nodes_[index].first = first, nodes_[index].count = count;
    return index;
  }
  int axis;
  (centres.hi - centres.lo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int a, int b) { return boxes[a].centre()[axis] < boxes[b].centre()[axis]; });
  build(boxes, first, half);
  const int right = build(boxes, first + half, count - half);
  nodes_[index].right = right;
  return index;
}

}  // namespace hexlayer
