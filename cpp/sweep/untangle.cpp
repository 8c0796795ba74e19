#include "sweep/untangle.hpp"

#include <algorithm>

namespace hexlayer {
namespace {

constexpr int kRounds = 8;            // the ring grows by one quad per round
constexpr int kSmoothingSweeps = 10;  // Jacobi sweeps of the direction smoothing per round

using Adjacency = std::vector<std::vector<int>>;

// For every node, the quads it is a corner of.
Adjacency nodeQuads(const QuadMesh& q) {
  Adjacency out(q.nodes.size());
  for (size_t j = 0; j < q.quads.size(); ++j)
    for (int v : q.quads[j]) out[v].push_back(static_cast<int>(j));
  return out;
}

// For every node, the other nodes of its quads.
Adjacency quadNeighbours(const QuadMesh& q, const Adjacency& quadsOf) {
  Adjacency out(q.nodes.size());
  for (size_t i = 0; i < q.nodes.size(); ++i) {
    for (int j : quadsOf[i])
      for (int v : q.quads[j])
        if (v != static_cast<int>(i)) out[i].push_back(v);
    std::sort(out[i].begin(), out[i].end());
    out[i].erase(std::unique(out[i].begin(), out[i].end()), out[i].end());
  }
  return out;
}

// The nodes of the bad columns and `rings` rings of quads around them.
std::vector<char> badRegion(const QuadMesh& q, const std::vector<double>& column, double target, int rings,
                            const Adjacency& neighbours) {
  std::vector<char> in(q.nodes.size(), 0);
  for (size_t j = 0; j < q.quads.size(); ++j)
    if (column[j] < target)
      for (int v : q.quads[j]) in[v] = 1;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> grown = in;
    for (size_t i = 0; i < in.size(); ++i)
      if (in[i])
        for (int v : neighbours[i]) grown[v] = 1;
    in.swap(grown);
  }
  return in;
}

// Connected parts of the marked nodes (connected through shared quads), in increasing node order.
std::vector<std::vector<int>> components(const std::vector<char>& in, const Adjacency& neighbours) {
  std::vector<std::vector<int>> parts;
  std::vector<char> seen(in.size(), 0);
  for (size_t s = 0; s < in.size(); ++s) {
    if (!in[s] || seen[s]) continue;
    std::vector<int> part{static_cast<int>(s)};
    seen[s] = 1;
    for (size_t k = 0; k < part.size(); ++k)
      for (int v : neighbours[part[k]])
        if (in[v] && !seen[v]) seen[v] = 1, part.push_back(v);
    std::sort(part.begin(), part.end());
    parts.push_back(std::move(part));
  }
  return parts;
}

// Laplacian smoothing of unit directions on `nodes`; the directions around them stay fixed.
void smoothDirections(const std::vector<int>& nodes, const Adjacency& neighbours, std::vector<Vec3>& dir) {
  std::vector<Vec3> next(nodes.size());
  for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep) {
    for (size_t k = 0; k < nodes.size(); ++k) {
      Vec3 sum = Vec3::Zero();
      for (int v : neighbours[nodes[k]]) sum += dir[v];
      next[k] = sum.norm() > 0 ? sum.normalized() : dir[nodes[k]];
    }
    for (size_t k = 0; k < nodes.size(); ++k) dir[nodes[k]] = next[k];
  }
}

std::vector<int> quadsTouching(const std::vector<int>& nodes, const Adjacency& quadsOf) {
  std::vector<int> quads;
  for (int i : nodes) quads.insert(quads.end(), quadsOf[i].begin(), quadsOf[i].end());
  std::sort(quads.begin(), quads.end());
  quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
  return quads;
}

// How far the columns fall short of the target, summed: a round is kept when it lowers this.
double shortfall(const std::vector<double>& quality, double target) {
  double s = 0;
  for (double c : quality) s += std::max(0.0, target - c);
  return s;
}

}  // namespace

UntangleResult untangleSweep(const QuadMesh& q, std::vector<Vec3>& dir, double target,
                             const std::function<void(int)>& place, const std::function<double(int)>& columnQuality) {
  const Adjacency quadsOf = nodeQuads(q);
  const Adjacency neighbours = quadNeighbours(q, quadsOf);
  std::vector<double> column(q.quads.size());
  for (size_t j = 0; j < q.quads.size(); ++j) column[j] = columnQuality(static_cast<int>(j));
  UntangleResult result;
  result.worstBefore = column.empty() ? 1 : *std::min_element(column.begin(), column.end());
  for (int round = 0; round < kRounds; ++round) {
    const std::vector<std::vector<int>> parts =
        components(badRegion(q, column, target, round + 1, neighbours), neighbours);
    if (parts.empty()) break;
    result.regions += static_cast<int>(parts.size());
    for (const std::vector<int>& nodes : parts) {
      const std::vector<int> quads = quadsTouching(nodes, quadsOf);
      std::vector<double> before;
      for (int j : quads) before.push_back(column[j]);
      std::vector<Vec3> saved;
      for (int i : nodes) saved.push_back(dir[i]);
      smoothDirections(nodes, neighbours, dir);
      for (int i : nodes) place(i);
      std::vector<double> after;
      for (int j : quads) after.push_back(columnQuality(j));
      if (shortfall(after, target) < shortfall(before, target)) {
        for (size_t k = 0; k < quads.size(); ++k) column[quads[k]] = after[k];
        ++result.improved;
        continue;
      }
      for (size_t k = 0; k < nodes.size(); ++k) dir[nodes[k]] = saved[k], place(nodes[k]);
    }
  }
  result.worstAfter = column.empty() ? 1 : *std::min_element(column.begin(), column.end());
  return result;
}

}  // namespace hexlayer
