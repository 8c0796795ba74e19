// A bounding volume hierarchy over boxes (one per item: a triangle, a CAD face): the items near a point or
// along a ray, without testing every item.
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

struct Box {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);  // empty
  void add(const Vec3& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
  Vec3 centre() const { return 0.5 * (lo + hi); }
};

// Squared distance from p to the box (0 inside).
double squaredDistanceToBox(const Vec3& p, const Box& box);

// Where the line p + t dir enters the box within t in [tMin, tMax] (dir need not be unit; zero components are
// allowed); +infinity if it does not meet the box there.
double rayEntersBox(const Vec3& p, const Vec3& dir, const Box& box, double tMin, double tMax);

class BoxTree {
 public:
  // [in] boxes: item i's box.
  explicit BoxTree(const std::vector<Box>& boxes);

  // Depth-first walk: enter(box) says whether to look inside a node's box, visit(item) whether to stop.
  template <class Enter, class Visit>
  void traverse(Enter&& enter, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::array<int, 128> stack;  // a median split keeps the depth near log2(items)
    int size = 0;
    stack[size++] = 0;
    while (size > 0) {
      const int index = stack[--size];
      const Node& node = nodes_[index];
      if (!enter(node.box)) continue;
      if (node.count == 0) {
        stack[size++] = node.right, stack[size++] = index + 1;
        continue;
      }
      for (int i = node.first; i < node.first + node.count; ++i)
        if (visit(order_[i])) return;
    }
  }

 private:
  struct Node {
    Box box;        // of the node's items
    int first = 0;  // leaf: its items are order_[first, first + count)
    int count = 0;  // 0 for an inner node
    int right = 0;  // inner node: index of the second child (the first follows the node)
  };
  int build(const std::vector<Box>& boxes, int first, int count);

  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace hexlayer
