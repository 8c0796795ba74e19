// Gauss-Seidel sweeps on two threads with the result of one: a sweep over a mesh's nodes, each update reading only
// the nodes of the elements around its node, decides each move only through the order of neighbours (a node moves
// with its neighbours before it in their new places, those after it in their old). Cut in two by a plane, the
// nodes of each half with no neighbour in the other move independently of the other half's: the two halves are swept
// side by side, then the seam (the nodes with a neighbour across), each part in index order. Only the pairs across
// the seam are visited in another order than index order; the result is the same on any number of threads.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "core/box_tree.hpp"
#include "core/groups.hpp"
#include "core/threads.hpp"
#include "core/types.hpp"

namespace hexlayer {

// The order of the sweeps: the halves' inner nodes, then the seam. One half in index order where the mesh is small or
// the cut would not leave the halves most of the nodes.
struct SweepHalves {
  std::array<std::vector<int>, 2> halves;
  std::vector<int> seam;
  std::vector<long> position;  // per node, its place in a sweep (the halves, then the seam)
};

constexpr std::size_t kHalvedNodes = 2000;  // nodes from which a sweep is cut in two
constexpr double kMostSeam = 0.1;           // the largest share of the nodes on the seam

// [in] points: per node; [in] busy(node): whether it is expected to move (the cut, across the longest side of their
// box, goes through the middle one of them: each half has as much to do), asked only of a mesh large enough to be cut;
// [in] around: the elements around each node; [in] nodesOf(element): its nodes. Returns the order.
template <class Index, class Busy, class NodesOf>
SweepHalves sweepHalves(const std::vector<Vec3>& points, Busy busy, const Groups<Index>& around, NodesOf nodesOf) {
  const int n = static_cast<int>(points.size());
  SweepHalves o;
  o.position.resize(n);
  auto inIndexOrder = [&] {
    o.halves[0].clear(), o.halves[1].clear(), o.seam.clear();
    for (int node = 0; node < n; ++node) o.halves[0].push_back(node), o.position[node] = node;
    return o;
  };
  if (static_cast<std::size_t>(n) < kHalvedNodes) return inIndexOrder();
  Box box;
  std::vector<int> moving;
  for (int node = 0; node < n; ++node)
    if (busy(node)) box.add(points[node]), moving.push_back(node);
  if (moving.size() < 2) return inIndexOrder();
  int axis = 0;
  (box.hi - box.lo).maxCoeff(&axis);
  auto before = [&](int a, int b) { return std::make_pair(points[a][axis], a) < std::make_pair(points[b][axis], b); };
  const auto middle = moving.begin() + static_cast<long>(moving.size() / 2);
  std::nth_element(moving.begin(), middle, moving.end(), before);
  auto half = [&](int node) { return before(node, *middle) ? 0 : 1; };
  for (int node = 0; node < n; ++node) {
    bool seam = false;
    for (Index k = around.start[node]; k < around.start[node + 1] && !seam; ++k)
      for (int c : nodesOf(around.items[k])) seam |= half(c) != half(node);
    (seam ? o.seam : o.halves[half(node)]).push_back(node);
  }
  if (static_cast<double>(o.seam.size()) > kMostSeam * n) return inIndexOrder();
  long place = 0;
  for (const std::vector<int>* part : {&o.halves[0], &o.halves[1], &o.seam})
    for (int node : *part) o.position[node] = place++;
  return o;
}

// One sweep in the order: visit(node, part) for the nodes of each half (part 0 and 1, side by side), then of the seam
// (part 2). visit must read and write only the node's own data and that of the nodes of its elements.
template <class Visit>
void sweepInHalves(const SweepHalves& order, Visit visit) {
  ParallelErrors errors;
#pragma omp parallel for schedule(static, 1) if (!order.halves[1].empty())
  for (int h = 0; h < 2; ++h)
    errors.run([&] {
      for (int node : order.halves[h]) visit(node, h);
    });
  errors.rethrow();
  for (int node : order.seam) visit(node, 2);
}

// Which nodes can still move in a sweep: a node's update depends only on the nodes of the elements around it, so if
// none of them (itself included) moved since its last visit, the visit would decide as before and is skipped. The
// result is the same as visiting every node. Times are places in the sweeps' order (sweep * nodes + position): a visit
// at 2 t, a move at 2 t + 1. Safe in sweepInHalves: a half's node reads the times of its half and of the seam only.
class MoveClock {
 public:
  explicit MoveClock(std::size_t nodes) : movedAt_(nodes, -1), visitedAt_(nodes, -2) {}
  // [in] around: the elements around each node; [in] nodesOf(element): its nodes; [in] node.
  template <class Index, class NodesOf>
  bool unchanged(const Groups<Index>& around, NodesOf nodesOf, int node) const {
    for (Index k = around.start[node]; k < around.start[node + 1]; ++k)
      for (int c : nodesOf(around.items[k]))
        if (movedAt_[c] > visitedAt_[node]) return false;
    return true;
  }
  void visit(int node, long t) { visitedAt_[node] = 2 * t; }
  void moved(int node, long t) { movedAt_[node] = 2 * t + 1; }

 private:
  std::vector<long> movedAt_, visitedAt_;
};

}  // namespace hexlayer
