#include "quadmesh/quad_completion.hpp"

#include <algorithm>
#include <tuple>
#include <unordered_map>

#include "core/union_find.hpp"

namespace hexlayer {
namespace {

// Quads are elements 0..Q-1, triangles Q..Q+T-1.
class Elements {
 public:
  Elements(const std::vector<std::array<int, 4>>& quads, const std::vector<std::array<int, 3>>& triangles)
      : quads_(quads), triangles_(triangles) {
    for (int e = 0; e < count(); ++e)
      for (int k = 0; k < corners(e); ++k) byEdge_[edgeKey(corner(e, k), corner(e, k + 1))].push_back(e);
  }
  int count() const { return static_cast<int>(quads_.size() + triangles_.size()); }
  bool isTriangle(int e) const { return e >= static_cast<int>(quads_.size()); }
  int corners(int e) const { return isTriangle(e) ? 3 : 4; }
  int corner(int e, int k) const {
    k %= corners(e);
    return isTriangle(e) ? triangles_[e - quads_.size()][k] : quads_[e][k];
  }
  int position(int e, int v) const {
    for (int k = 0; k < corners(e); ++k)
      if (corner(e, k) == v) return k;
    return -1;
  }
  // The one other element on edge (a, b), -1 at the boundary or a non-manifold edge.
  int across(int e, int a, int b) const {
    const std::vector<int>& on = byEdge_.at(edgeKey(a, b));
    if (on.size() != 2) return -1;
    return on[0] == e ? on[1] : on[0];
  }

 private:
  const std::vector<std::array<int, 4>>& quads_;
  const std::vector<std::array<int, 3>>& triangles_;
  std::unordered_map<std::uint64_t, std::vector<int>> byEdge_;
};

// Triangle (a, b0, c0), quads (c_k, b_k, b_k+1, c_k+1) in some rotation and orientation, triangle
// (c_n, b_n, z): the strip between two triangles.
struct Strip {
  int from = -1, to = -1;
  std::vector<int> quads;
  int a = -1, z = -1;
  std::vector<int> b, c;
};

// Follows the quads straight across from edge k + 1, k + 2 of triangle t until another triangle.
bool walkStrip(const Elements& el, int t, int k, int maxStrip, Strip& s) {
  s = Strip{t, -1, {}, el.corner(t, k), -1, {el.corner(t, k + 1)}, {el.corner(t, k + 2)}};
  for (int prev = t;;) {
    const int b = s.b.back(), c = s.c.back();
    const int next = el.across(prev, b, c);
    if (next < 0 || next == t || std::count(s.quads.begin(), s.quads.end(), next)) return false;
    if (el.isTriangle(next)) {
      s.to = next;
      for (int k2 = 0; k2 < 3; ++k2)
        if (const int v = el.corner(next, k2); v != b && v != c) s.z = v;
      return true;
    }
    if (static_cast<int>(s.quads.size()) == maxStrip) return false;
    const int ib = el.position(next, b), ic = el.position(next, c);
    const bool cAfterB = el.corner(next, ib + 1) == c;  // then b's other neighbour is before it
    s.b.push_back(el.corner(next, cAfterB ? ib + 3 : ib + 1));
    s.c.push_back(el.corner(next, cAfterB ? ic + 1 : ic + 3));
    s.quads.push_back(next);
    prev = next;
  }
}

// The n + 1 quads (c_k-1, b_k, b_k+1, c_k), k = 0..n, with c_-1 = a and b_n+1 = z; empty if a
// corner repeats (a strip that runs into itself).
std::vector<std::array<int, 4>> retile(const Strip& s) {
  std::vector<std::array<int, 4>> out;
  const int n = static_cast<int>(s.quads.size());
  for (int k = 0; k <= n; ++k) {
    std::array<int, 4> q{k == 0 ? s.a : s.c[k - 1], s.b[k], k == n ? s.z : s.b[k + 1], s.c[k]};
    std::array<int, 4> sorted = q;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};
    out.push_back(q);
  }
  return out;
}

// One round: every triangle's shortest strips, applied shortest first where they touch nothing
// already changed. Returns how many triangles were paired.
std::size_t pairingRound(std::vector<std::array<int, 4>>& quads, std::vector<std::array<int, 3>>& triangles,
                         int maxStrip) {
  const Elements el(quads, triangles);
  std::vector<Strip> strips;
  for (int t = static_cast<int>(quads.size()); t < el.count(); ++t)
    for (int k = 0; k < 3; ++k)
      if (Strip s; walkStrip(el, t, k, maxStrip, s)) strips.push_back(std::move(s));
  std::stable_sort(strips.begin(), strips.end(),
                   [](const Strip& x, const Strip& y) { return x.quads.size() < y.quads.size(); });
  std::vector<char> used(el.count(), 0);
  std::vector<std::array<int, 4>> added;
  std::size_t paired = 0;
  for (const Strip& s : strips) {
    bool free = !used[s.from] && !used[s.to];
    for (int q : s.quads) free = free && !used[q];
    const std::vector<std::array<int, 4>> tiles = free ? retile(s) : std::vector<std::array<int, 4>>{};
    if (tiles.empty()) continue;
    used[s.from] = used[s.to] = 1;
    for (int q : s.quads) used[q] = 1;
    added.insert(added.end(), tiles.begin(), tiles.end());
    paired += 2;
  }
  std::vector<std::array<int, 4>> keptQuads;
  for (std::size_t q = 0; q < quads.size(); ++q)
    if (!used[q]) keptQuads.push_back(quads[q]);
  keptQuads.insert(keptQuads.end(), added.begin(), added.end());
  std::vector<std::array<int, 3>> keptTriangles;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (!used[quads.size() + t]) keptTriangles.push_back(triangles[t]);
  quads.swap(keptQuads);
  triangles.swap(keptTriangles);
  return paired;
}

// Every edge that gets a midpoint: the triangles' edges, and across each quad from a split edge to
// its opposite edge, until the rim or an edge already split.
std::unordered_map<std::uint64_t, int> edgesToSplit(const std::vector<std::array<int, 4>>& quads,
                                                    const std::vector<std::array<int, 3>>& triangles) {
  std::unordered_map<std::uint64_t, std::vector<int>> quadsOnEdge;
  for (std::size_t q = 0; q < quads.size(); ++q)
    for (int k = 0; k < 4; ++k) quadsOnEdge[edgeKey(quads[q][k], quads[q][(k + 1) % 4])].push_back(static_cast<int>(q));
  std::unordered_map<std::uint64_t, int> split;  // edge -> midpoint node, set later
  std::vector<std::pair<int, int>> todo;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) todo.push_back({t[k], t[(k + 1) % 3]});
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    if (!split.emplace(edgeKey(a, b), -1).second) continue;
    const auto on = quadsOnEdge.find(edgeKey(a, b));
    if (on == quadsOnEdge.end()) continue;
    for (int q : on->second)
      for (int k = 0; k < 4; ++k)
        if (edgeKey(quads[q][k], quads[q][(k + 1) % 4]) == edgeKey(a, b))
          todo.push_back({quads[q][(k + 2) % 4], quads[q][(k + 3) % 4]});
  }
  return split;
}

}  // namespace

std::size_t splitTriangles(std::vector<Vec3>& nodes, std::vector<std::array<int, 4>>& quads,
                           std::vector<std::array<int, 3>>& triangles) {
  if (triangles.empty()) return 0;
  std::unordered_map<std::uint64_t, int> split = edgesToSplit(quads, triangles);
  auto mid = [&](int a, int b) {  // the midpoint node of edge (a, b), or -1 if it is not split
    const auto it = split.find(edgeKey(a, b));
    if (it == split.end()) return -1;
    if (it->second < 0) it->second = static_cast<int>(nodes.size()), nodes.push_back(0.5 * (nodes[a] + nodes[b]));
    return it->second;
  };
  auto centre = [&](const auto& corners, int n) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < n; ++k) c += nodes[corners[k]] / n;
    nodes.push_back(c);
    return static_cast<int>(nodes.size()) - 1;
  };
  std::vector<std::array<int, 4>> out;
  for (const auto& q : quads) {
    const std::array<int, 4> m{mid(q[0], q[1]), mid(q[1], q[2]), mid(q[2], q[3]), mid(q[3], q[0])};
    if (m[0] >= 0 && m[1] >= 0) {  // quartered (v_k, m_k, c, m_k-1)
      const int c = centre(q, 4);
      for (int k = 0; k < 4; ++k) out.push_back({q[k], m[k], c, m[(k + 3) % 4]});
    } else if (m[0] >= 0 || m[1] >= 0) {  // halved across: edges k and k + 2 split
      const int k = m[0] >= 0 ? 0 : 1;
      out.push_back({q[k], m[k], m[k + 2], q[(k + 3) % 4]});
      out.push_back({m[k], q[k + 1], q[k + 2], m[k + 2]});
    } else {
      out.push_back(q);
    }
  }
  for (const auto& t : triangles) {  // three quads (v_k, m_k, c, m_k-1)
    const int c = centre(t, 3);
    for (int k = 0; k < 3; ++k) out.push_back({t[k], mid(t[k], t[(k + 1) % 3]), c, mid(t[(k + 2) % 3], t[k])});
  }
  quads.swap(out);
  const std::size_t count = triangles.size();
  triangles.clear();
  return count;
}

QuadCompletion pairTriangles(std::vector<std::array<int, 4>>& quads, std::vector<std::array<int, 3>>& triangles,
                             int maxStrip) {
  QuadCompletion done;
  while (!triangles.empty()) {
    const std::size_t paired = pairingRound(quads, triangles, maxStrip);
    if (paired == 0) break;
    done.paired += paired;
  }
  done.unpaired = triangles.size();
  return done;
}

}  // namespace hexlayer
