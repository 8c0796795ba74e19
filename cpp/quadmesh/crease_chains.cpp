#include "quadmesh/crease_chains.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>

#include "chordal/chordal_surface.hpp"
#include "quadmesh/quad_smoothing.hpp"

namespace hexlayer {
namespace {

// An edge's length is weighted by 1 + kNearness (d / mean edge)^2, d its middle's distance from the crease: a chain a
// quad off it costs five lengths per length.
constexpr double kNearness = 4;
constexpr double kAlongRim = 50;  // the weight of a rim edge: a chain runs along the rim only where nothing else does
// The weight of an edge turning from the last inside their quad: put on the crease, the three nodes flatten it.
constexpr double kTurn = 50;
constexpr int kSmoothing = 10;     // iterations of the quads' smoothing round the chains
constexpr double kFloor = 0.2;     // a chain whose quads end below this (and below their worst before) is dropped
constexpr double kRimEnd = 0.5;    // of a mean edge: a crease ending this near the quads' rim ends on it
constexpr double kRimCorner = 30;  // degrees: a rim node where the rim turns more is a corner, not slid along it

// The point of the segment from a to b nearest p.
Vec3 nearestOnSegment(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3 ab = b - a;
  return a + (ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0) * ab;
}

// The point of the polyline nearest p.
Vec3 nearestOnPolyline(const std::vector<Vec3>& line, const Vec3& p) {
  Vec3 best = line.front();
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    if (const Vec3 q = nearestOnSegment(line[i], line[i + 1], p); (q - p).squaredNorm() < (best - p).squaredNorm())
      best = q;
  return best;
}

// The quad node nearest p.
int nearestNode(const QuadMesh& quads, const Vec3& p) {
  int best = 0;
  for (int n = 1; n < static_cast<int>(quads.nodes.size()); ++n)
    if ((quads.nodes[n] - p).squaredNorm() < (quads.nodes[best] - p).squaredNorm()) best = n;
  return best;
}

// Per node, its quad edges' other ends, and whether each edge is on the rim (in one quad).
std::vector<std::vector<std::pair<int, bool>>> edgeNeighbours(const QuadMesh& quads) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& q : quads.quads)
    for (int c = 0; c < 4; ++c) ++uses[std::minmax(q[c], q[(c + 1) % 4])];
  std::vector<std::vector<std::pair<int, bool>>> next(quads.nodes.size());
  for (const auto& [edge, count] : uses) {
    next[edge.first].emplace_back(edge.second, count == 1);
    next[edge.second].emplace_back(edge.first, count == 1);
  }
  return next;
}

// Where a crease ends on the rim: the point of the chordal surface's rim nearest its end, and the quads' rim node
// nearest that point, to be slid there (-1 if the point is farther than reach from the crease's end, or the node is a
// corner of the quads' rim).
struct RimEnd {
  Vec3 at = Vec3::Zero();
  int node = -1;
};
// [in] rim: the chordal surface's rim edges (their ends); [in] next: edgeNeighbours'; [in] p: the crease's end;
// [in] reach. Returns the rim end.
RimEnd rimEndNear(const QuadMesh& quads, const std::vector<std::array<Vec3, 2>>& rim,
                  const std::vector<std::vector<std::pair<int, bool>>>& next, const Vec3& p, double reach) {
  RimEnd end;
  double nearest = reach;
  bool found = false;
  for (const auto& [a, b] : rim)
    if (const Vec3 q = nearestOnSegment(a, b, p); (q - p).norm() <= nearest)
      nearest = (q - p).norm(), end.at = q, found = true;
  if (!found) return end;
  for (int n = 0; n < static_cast<int>(next.size()); ++n)
    if (std::any_of(next[n].begin(), next[n].end(), [](const auto& e) { return e.second; }) &&
        (end.node < 0 || (quads.nodes[n] - end.at).squaredNorm() < (quads.nodes[end.node] - end.at).squaredNorm()))
      end.node = n;
  std::vector<int> along;  // the node's neighbours along the rim
  for (const auto& [m, onRim] : next[end.node])
    if (onRim) along.push_back(m);
  const Vec3 v = quads.nodes[end.node];
  if (along.size() != 2 || (v - quads.nodes[along[0]]).normalized().dot((quads.nodes[along[1]] - v).normalized()) <
                               std::cos(kRimCorner * M_PI / 180))
    end.node = -1;
  return end;
}

// The chordal surface's rim edges. [in] chordal. Returns their ends.
std::vector<std::array<Vec3, 2>> chordalRim(const ChordalSurface& chordal) {
  std::vector<std::array<Vec3, 2>> rim;
  for (const auto& [edge, uses] : facetEdgeUses(chordal))
    if (uses == 1) rim.push_back({chordal.vertices[edge.first], chordal.vertices[edge.second]});
  return rim;
}

// Whether nodes a, b and c are corners of one quad. [in] quadsAt: per node, its quads.
bool oneQuad(const QuadMesh& quads, const std::vector<std::vector<int>>& quadsAt, int a, int b, int c) {
  return std::any_of(quadsAt[b].begin(), quadsAt[b].end(), [&](int q) {
    const auto& corners = quads.quads[q];
    return std::count(corners.begin(), corners.end(), a) && std::count(corners.begin(), corners.end(), c);
  });
}

// The chain of quad nodes from `from` to `to` whose edges lie nearest the polyline (Dijkstra over the edges walked, so
// that the chain turns inside a quad only where it must: put on the crease, the three nodes of such a turn flatten it).
// [in] next: edgeNeighbours'; [in] quadsAt: per node, its quads; [in] size: the mean quad edge. Returns the nodes in
// order (empty if `to` cannot be reached).
std::vector<int> chainAlong(const QuadMesh& quads, const std::vector<std::vector<std::pair<int, bool>>>& next,
                            const std::vector<std::vector<int>>& quadsAt, const std::vector<Vec3>& line, double size,
                            int from, int to) {
  // the states: an edge walked into its node, (node, index into next[node] of the node it came from); `from` alone
  std::map<std::pair<int, int>, double> cost;
  std::map<std::pair<int, int>, std::pair<int, int>> previous;
  using Entry = std::pair<double, std::pair<int, int>>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  const std::pair<int, int> start{from, -1};
  cost[start] = 0, open.emplace(0.0, start);
  std::pair<int, int> reached{-1, -1};
  while (!open.empty()) {
    const auto [c, state] = open.top();
    open.pop();
    if (c > cost[state]) continue;
    const int n = state.first, came = state.second < 0 ? -1 : next[n][state.second].first;
    if (n == to) {
      reached = state;
      break;
    }
    for (const auto& [m, rim] : next[n]) {
      if (m == came) continue;
      const Vec3 middle = 0.5 * (quads.nodes[n] + quads.nodes[m]);
      const double d = (nearestOnPolyline(line, middle) - middle).norm() / size;
      const bool turn = came >= 0 && oneQuad(quads, quadsAt, came, n, m);
      const double w = (quads.nodes[m] - quads.nodes[n]).norm() * (1 + kNearness * d * d) * (rim ? kAlongRim : 1) *
                       (turn ? kTurn : 1);
      const auto back = std::find_if(next[m].begin(), next[m].end(), [&](const auto& e) { return e.first == n; });
      const std::pair<int, int> into{m, static_cast<int>(back - next[m].begin())};
      const auto known = cost.find(into);
      if (known == cost.end() || c + w < known->second)
        cost[into] = c + w, previous[into] = state, open.emplace(c + w, into);
    }
  }
  std::vector<int> chain;
  if (reached.first < 0) return chain;
  for (std::pair<int, int> s = reached;; s = previous[s]) {
    chain.push_back(s.first);
    if (s.second < 0) break;
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// The worst scaled Jacobian of the quads round the flagged nodes. [in] quadsAt: per node, its quads.
double worstAround(const QuadMesh& quads, const std::vector<std::vector<int>>& quadsAt, const std::vector<char>& at) {
  double worst = 1;
  for (std::size_t n = 0; n < quads.nodes.size(); ++n)
    if (at[n])
      for (int q : quadsAt[n]) {
        std::array<Vec3, 4> corners;
        for (int c = 0; c < 4; ++c) corners[c] = quads.nodes[quads.quads[q][c]];
        worst = std::min(worst, quadScaledJacobian(corners));
      }
  return worst;
}

}  // namespace

CreaseChainStats followCreases(QuadMesh& quads, const ChordalLocator& chordal,
                               const std::vector<std::vector<Vec3>>& creases) {
  CreaseChainStats stats;
  if (creases.empty() || quads.quads.empty()) return stats;
  const double size = meanEdge(quads);
  const auto next = edgeNeighbours(quads);
  std::vector<std::vector<int>> quadsAt(quads.nodes.size());
  for (std::size_t q = 0; q < quads.quads.size(); ++q)
    for (int n : quads.quads[q]) quadsAt[n].push_back(static_cast<int>(q));
  const std::vector<std::array<Vec3, 2>> rim = chordalRim(chordal.surface());
  std::vector<char> fixed(quads.nodes.size(), 0);  // the chains' nodes put on their creases
  for (const std::vector<Vec3>& crease : creases) {
    if (crease.size() < 2) continue;
    std::vector<Vec3> line;  // the crease on the chordal surface
    for (const Vec3& p : crease) line.push_back(chordal.locate(p).point);
    // its ends: where it meets the rim, the rim node slid there (the sweep's rim capture puts its column on the CAD
    // edge's end), else the nodes nearest its ends
    const std::array<RimEnd, 2> rimEnds{rimEndNear(quads, rim, next, line.front(), kRimEnd * size),
                                        rimEndNear(quads, rim, next, line.back(), kRimEnd * size)};
    const std::vector<int> chain = chainAlong(quads, next, quadsAt, line, size,
                                              rimEnds[0].node >= 0 ? rimEnds[0].node : nearestNode(quads, line.front()),
                                              rimEnds[1].node >= 0 ? rimEnds[1].node : nearestNode(quads, line.back()));
    std::vector<char> on(quads.nodes.size(), 0);
    std::vector<Vec3> to(quads.nodes.size());
    for (int n : chain)  // another rim node (on a rim edge) stays
      if (!fixed[n] && std::none_of(next[n].begin(), next[n].end(), [](const auto& e) { return e.second; }))
        on[n] = 1, to[n] = chordal.locate(nearestOnPolyline(line, quads.nodes[n])).point;
    for (const RimEnd& end : rimEnds)
      if (end.node >= 0 && !fixed[end.node] && !chain.empty() &&
          (end.node == chain.front() || end.node == chain.back()))
        on[end.node] = 1, to[end.node] = end.at;
    if (std::count(on.begin(), on.end(), 1) == 0) continue;
    const std::vector<Vec3> before = quads.nodes;
    const double worstBefore = worstAround(quads, quadsAt, on);
    double farthest = 0;
    for (std::size_t n = 0; n < on.size(); ++n)
      if (on[n]) {
        farthest = std::max(farthest, (to[n] - quads.nodes[n]).norm() / size);
        quads.nodes[n] = to[n], fixed[n] = 1;
      }
    std::vector<char> stays = fixed;  // the chains and their ends on the rim
    for (int n : chain) stays[n] = 1;
    smoothQuadMesh(quads, chordal, kSmoothing, true, stays);  // round the chains
    if (const double worst = worstAround(quads, quadsAt, on); worst < std::min(worstBefore, kFloor)) {
      quads.nodes = before, ++stats.dropped;  // the quads round it too poor
      for (std::size_t n = 0; n < on.size(); ++n)
        if (on[n]) fixed[n] = 0;
      continue;
    }
    ++stats.chains, stats.nodesMoved += std::count(on.begin(), on.end(), 1);
    stats.farthest = std::max(stats.farthest, farthest);
  }
  stats.worstQuad = worstAround(quads, quadsAt, fixed);
  return stats;
}

}  // namespace hexlayer
