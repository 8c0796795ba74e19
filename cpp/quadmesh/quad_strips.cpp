#include "quadmesh/quad_strips.hpp"

#include "quadmesh/surface_map.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace hexlayer {
namespace {

using Key = std::pair<int, int>;  // an undirected edge, lower node first

Key keyOf(int a, int b) { return a < b ? Key{a, b} : Key{b, a}; }

// The rim loops: each a list of nodes, its edges between consecutive ones (the last to the first).
std::vector<std::vector<int>> rimLoops(const QuadMesh& q) {
  const std::vector<std::vector<int>> around = rimEdgeNeighbours(q);
  std::vector<char> seen(around.size(), 0);
  std::vector<std::vector<int>> loops;
  for (int start = 0; start < static_cast<int>(around.size()); ++start) {
    if (seen[start] || around[start].size() != 2) continue;
    std::vector<int> loop{start};
    seen[start] = 1;
    for (int prev = start, at = around[start][0]; at != start;) {
      if (seen[at] || around[at].size() != 2) {  // a rim pinched at a node: not a simple loop
        loop.clear();
        break;
      }
      seen[at] = 1, loop.push_back(at);
      const int next = around[at][0] == prev ? around[at][1] : around[at][0];
      prev = at, at = next;
    }
    if (!loop.empty()) loops.push_back(std::move(loop));
  }
  return loops;
}

// The longest rim loop (by its edges' length): the outer rim. [in] q. Returns it (empty if q has none).
std::vector<int> longestRimLoop(const QuadMesh& q) {
  const std::vector<std::vector<int>> loops = rimLoops(q);
  auto length = [&](const std::vector<int>& loop) { return arcLength(loop, q.nodes).back(); };
  auto longest =
      std::max_element(loops.begin(), loops.end(), [&](const auto& a, const auto& b) { return length(a) < length(b); });
  return longest == loops.end() ? std::vector<int>{} : *longest;
}

// Whether a node of the loop in one quad (three other corners) has its rim edges at more than kFlatCorner.
// [in] q, loop; [in] corners: per node, the other corners of its quads.
bool hasFlatCorner(const QuadMesh& q, const std::vector<int>& loop, const std::vector<std::vector<int>>& corners) {
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int c = loop[i];
    if (corners[c].size() != 3) continue;
    const Vec3 ca = q.nodes[loop[(i + 1) % loop.size()]] - q.nodes[c];
    const Vec3 cb = q.nodes[loop[(i + loop.size() - 1) % loop.size()]] - q.nodes[c];
    if (angleBetween(ca, cb) > kFlatCorner) return true;
  }
  return false;
}

// [in] q; [in,out] loop: a rim loop of q (two nodes at least), turned so that its quads lie on its left (each runs
// its rim edge the loop's way).
void orientLikeItsQuads(const QuadMesh& q, std::vector<int>& loop) {
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k)
      if (keyOf(quad[k], quad[(k + 1) % 4]) == keyOf(loop[0], loop[1])) {
        if (quad[k] != loop[0]) std::reverse(loop.begin(), loop.end());
        return;
      }
}

}  // namespace

QuadsOfEdges quadsOfEdges(const std::vector<std::array<int, 4>>& quads) {
  QuadsOfEdges on;
  for (int q = 0; q < static_cast<int>(quads.size()); ++q)
    for (int k = 0; k < 4; ++k) on[keyOf(quads[q][k], quads[q][(k + 1) % 4])].push_back(q);
  return on;
}

QuadStrip stripToRim(const std::vector<std::array<int, 4>>& quads, const QuadsOfEdges& on,
                     const std::vector<char>& blocked, int a, int b) {
  auto isBlocked = [&](int q) { return !blocked.empty() && blocked[q]; };
  QuadStrip strip;
  std::set<int> seen;
  Key edge = keyOf(a, b);
  int from = -1;  // the quad the strip comes from
  for (;;) {
    int next = -1;  // the quad across the edge: at the start, the one not blocked
    for (int q : on.at(edge))
      if (q != from && (from >= 0 || !isBlocked(q))) next = q;
    if (next < 0) return strip;  // the last quad's far edge is on the rim
    if (isBlocked(next) || !seen.insert(next).second) return {};
    if (from >= 0 && on.at(edge).size() != 2) return {};  // a non-manifold edge
    const std::array<int, 4>& c = quads[next];
    int k = 0;
    while (keyOf(c[k], c[(k + 1) % 4]) != edge) ++k;
    strip.emplace_back(next, k);
    from = next, edge = keyOf(c[(k + 2) % 4], c[(k + 3) % 4]);
  }
}

void halveStrip(std::vector<std::array<int, 4>>& quads, std::vector<Vec3>& nodes, const QuadStrip& strip, int first) {
  int in = first;
  for (const auto& [q, k] : strip) {
    const std::array<int, 4> c{quads[q][k], quads[q][(k + 1) % 4], quads[q][(k + 2) % 4], quads[q][(k + 3) % 4]};
    const int out = static_cast<int>(nodes.size());
    nodes.push_back(0.5 * (nodes[c[2]] + nodes[c[3]]));
    quads[q] = {c[0], in, out, c[3]};
    quads.push_back({in, c[1], c[2], out});
    in = out;
  }
}

std::size_t evenRimLoops(QuadMesh& q, const std::function<bool(const Vec3&)>& mustBeEven, std::vector<char> blocked) {
  blocked.resize(q.quads.size(), 0);
  for (;;) {
    const std::vector<std::vector<int>> loops = rimLoops(q);
    std::vector<int> loopOf(q.nodes.size(), -1);  // the loop that must be even a node is on
    std::size_t odd = 0;
    for (std::size_t l = 0; l < loops.size(); ++l)
      if (std::all_of(loops[l].begin(), loops[l].end(), [&](int n) { return mustBeEven(q.nodes[n]); })) {
        for (int n : loops[l]) loopOf[n] = static_cast<int>(l);
        odd += loops[l].size() % 2;
      }
    if (odd == 0) return 0;
    // the shortest strip from an odd loop that must be even to a loop that need not be, or to another odd one
    QuadStrip best;
    int from = -1, to = -1;
    const QuadsOfEdges on = quadsOfEdges(q.quads);
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const std::vector<int>& loop = loops[l];
      if (loop.size() % 2 == 0 || loopOf[loop.front()] != static_cast<int>(l)) continue;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int a = loop[k], b = loop[(k + 1) % loop.size()];
        QuadStrip s = stripToRim(q.quads, on, blocked, a, b);
        if (s.empty() || (!best.empty() && s.size() >= best.size())) continue;
        const auto& [last, corner] = s.back();
        const int end = loopOf[q.quads[last][(corner + 2) % 4]];
        if (end >= 0 && (end == static_cast<int>(l) || loops[end].size() % 2 == 0)) continue;
        best = std::move(s), from = a, to = b;
      }
    }
    if (best.empty()) return odd;
    q.nodes.push_back(0.5 * (q.nodes[from] + q.nodes[to]));
    halveStrip(q.quads, q.nodes, best, static_cast<int>(q.nodes.size()) - 1);
    blocked.resize(q.quads.size(), 0);
  }
}

bool pillowFlatCorners(QuadMesh& q) {
  std::vector<int> rim = longestRimLoop(q);
  std::vector<std::vector<int>> corners(q.nodes.size());  // per node, the other corners of its quads (with repeats)
  std::vector<std::vector<int>> quadsAt(q.nodes.size());  // per node, its quads, ascending
  for (int e = 0; e < static_cast<int>(q.quads.size()); ++e)
    for (int k = 0; k < 4; ++k) {
      quadsAt[q.quads[e][k]].push_back(e);
      for (int l = 1; l < 4; ++l) corners[q.quads[e][k]].push_back(q.quads[e][(k + l) % 4]);
    }
  auto quadOf = [&](int node) { return quadsAt[node].back(); };  // its last quad
  if (!hasFlatCorner(q, rim, corners)) return false;
  orientLikeItsQuads(q, rim);
  // The ring's loop: the rim, but round the quad of each sharp corner (in one quad, kept as it is) along its inner
  // edges, from the rim node before the corner through the quad's inner corner to the one after.
  const std::size_t n = rim.size();
  std::vector<char> kept(q.quads.size(), 0), onRim(q.nodes.size(), 0);
  for (int c : rim) onRim[c] = 1;
  std::vector<int> loop = rim;
  for (std::size_t i = 0; i < n; ++i) {
    const int c = rim[i], a = rim[(i + n - 1) % n], b = rim[(i + 1) % n];
    if (corners[c].size() != 3 || angleBetween(q.nodes[a] - q.nodes[c], q.nodes[b] - q.nodes[c]) >= kKeptCorner)
      continue;
    const std::array<int, 4>& quad = q.quads[quadOf(c)];
    const int k = static_cast<int>(std::find(quad.begin(), quad.end(), c) - quad.begin());
    const int x = quad[(k + 2) % 4];
    const bool neighbours =
        (quad[(k + 1) % 4] == a && quad[(k + 3) % 4] == b) || (quad[(k + 1) % 4] == b && quad[(k + 3) % 4] == a);
    if (!neighbours || onRim[x] || kept[quadOf(a)] || kept[quadOf(b)]) continue;
    kept[quadOf(c)] = 1, loop[i] = x;
  }
  if (std::set<int>(loop.begin(), loop.end()).size() != n) loop = rim, kept.assign(q.quads.size(), 0);
  std::vector<char> onLoop(q.nodes.size(), 0);
  for (int c : loop) onLoop[c] = 1;
  std::vector<Vec3> inward;  // each loop node moves half way to the mean of the corners off the loop of its quads
  for (int c : loop) {
    Vec3 inner = Vec3::Zero();
    int count = 0;
    for (int e : quadsAt[c])
      if (!kept[e])
        for (int m : q.quads[e])
          if (!onLoop[m]) inner += q.nodes[m], ++count;
    inward.push_back(count ? Vec3(0.5 * (q.nodes[c] + inner / count)) : q.nodes[c]);
  }
  const int first = static_cast<int>(q.nodes.size());
  std::vector<int> copy(q.nodes.size(), -1);
  for (std::size_t i = 0; i < n; ++i) copy[loop[i]] = first + static_cast<int>(i), q.nodes.push_back(q.nodes[loop[i]]);
  for (std::size_t e = 0; e < q.quads.size(); ++e)  // the kept quads on the loop's copies, outside the ring
    if (kept[e])
      for (int& c : q.quads[e])
        if (copy[c] >= 0) c = copy[c];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    q.quads.push_back({loop[j], loop[i], first + static_cast<int>(i), first + static_cast<int>(j)});
    q.nodes[loop[i]] = inward[i];
  }
  return true;
}

}  // namespace hexlayer
