// core/sweep_halves.hpp: a Gauss-Seidel sweep on two threads. On a grid past kHalvedNodes the nodes fall into two
// halves with no neighbours across and a thin seam; a sweep that moves each node to the mean of its neighbours gives
// the same nodes on one thread and on two, and the same as one thread visiting the halves and the seam one after the
// other.
#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <array>
#include <vector>

#include "core/groups.hpp"
#include "core/sweep_halves.hpp"

using namespace hexlayer;

namespace {

// An n x n grid of unit squares: its nodes (node (i, j) at i + (n + 1) j) and its cells.
struct Grid {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 4>> cells;
  Groups<int> around;  // the cells at each node
};

Grid grid(int n) {
  Grid g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.nodes.emplace_back(i, j, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      g.cells.push_back({i + (n + 1) * j, i + 1 + (n + 1) * j, i + 1 + (n + 1) * (j + 1), i + (n + 1) * (j + 1)});
  g.around = groupByKey<int>(g.nodes.size(), [&](auto emit) {
    for (std::size_t c = 0; c < g.cells.size(); ++c)
      for (int v : g.cells[c]) emit(v, static_cast<int>(c));
  });
  return g;
}

// Three sweeps moving every inner node (busy) to the mean of the nodes of its cells. [in] threads: 0: none (the parts
// one after the other by hand).
std::vector<Vec3> smoothed(Grid g, const std::vector<char>& busy, const SweepHalves& order, int threads) {
  auto visit = [&](int v, int) {
    if (!busy[v]) return;
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (int k = g.around.start[v]; k < g.around.start[v + 1]; ++k)
      for (int c : g.cells[g.around.items[k]]) sum += g.nodes[c], ++count;
    g.nodes[v] = sum / count;
  };
  for (int sweep = 0; sweep < 3; ++sweep) {
    if (threads == 0) {
      for (const std::vector<int>* part : {&order.halves[0], &order.halves[1], &order.seam})
        for (int v : *part) visit(v, 0);
      continue;
    }
#ifdef _OPENMP
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
#endif
    sweepInHalves(order, visit);
#ifdef _OPENMP
    omp_set_num_threads(before);
#endif
  }
  return g.nodes;
}

}  // namespace

TEST(SweepHalves, SmallMeshesKeepIndexOrder) {
  const Grid g = grid(10);
  const std::vector<char> busy(g.nodes.size(), 1);
  const SweepHalves order = sweepHalves(
      g.nodes, [&](int v) { return busy[v] != 0; }, g.around, [&](int c) { return g.cells[c]; });
  ASSERT_EQ(order.halves[0].size(), g.nodes.size());
  EXPECT_TRUE(order.halves[1].empty() && order.seam.empty());
  for (std::size_t v = 0; v < g.nodes.size(); ++v) EXPECT_EQ(order.position[v], static_cast<long>(v));
}

TEST(SweepHalves, LargeGridIsCutInTwoHalvesAndAThinSeamAndSweptTheSameOnAnyThreads) {
  Grid g = grid(60);                                                               // 3721 nodes
  for (Vec3& p : g.nodes) p.y() += 0.3 * std::sin(p.x()) * std::sin(0.7 * p.y());  // something to smooth
  std::vector<char> busy(g.nodes.size(), 0);
  for (std::size_t v = 0; v < g.nodes.size(); ++v)
    busy[v] = g.nodes[v].x() > 0 && g.nodes[v].x() < 60 && v > 60 && v < g.nodes.size() - 61;
  const SweepHalves order = sweepHalves(
      g.nodes, [&](int v) { return busy[v] != 0; }, g.around, [&](int c) { return g.cells[c]; });
  EXPECT_GT(order.halves[0].size(), 1500u);
  EXPECT_GT(order.halves[1].size(), 1500u);
  EXPECT_LE(order.seam.size(), g.nodes.size() / 20);  // a band a few nodes wide across the grid
  std::vector<int> half(g.nodes.size(), 2);
  for (int h = 0; h < 2; ++h)
    for (int v : order.halves[h]) half[v] = h;
  for (const auto& cell : g.cells)  // no cell has a node of each half
    for (int a : cell)
      for (int b : cell) EXPECT_FALSE(half[a] + half[b] == 1) << a << " " << b;
  const std::vector<Vec3> byHand = smoothed(g, busy, order, 0);
  EXPECT_EQ(smoothed(g, busy, order, 1), byHand);
  EXPECT_EQ(smoothed(g, busy, order, 2), byHand);
  EXPECT_NE(byHand, g.nodes);
}
