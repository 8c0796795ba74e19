#include "quadmesh/chordal_patches.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <numeric>
#include <unordered_map>

#include "core/union_find.hpp"

namespace hexlayer {
namespace {

constexpr int kSmallPatch = 12;  // triangles: a patch with fewer joins a neighbour (Gmsh would mesh it with slivers)
constexpr int kCleaningRounds = 20;
constexpr int kFitRounds = 10;
constexpr double kFitMargin = 0.02;  // in the cosine of the angle to a patch's mean normal
constexpr double kFlatSeed = 5;  // degrees: a triangle turning less than this to every neighbour seeds patches first

// Triangle adjacency: across side j (corners j, j+1) the other triangle, or -1 on the rim.
using Neighbours = std::vector<std::array<int, 3>>;

Neighbours triangleNeighbours(const std::vector<std::array<int, 3>>& triangles) {
  Neighbours across(triangles.size(), {-1, -1, -1});
  std::unordered_map<std::uint64_t, std::pair<int, int>> first;  // edge -> (triangle, side)
  first.reserve(triangles.size() * 2);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int j = 0; j < 3; ++j) {
      const auto [it, added] = first.emplace(edgeKey(triangles[t][j], triangles[t][(j + 1) % 3]), std::pair{t, j});
      if (added) continue;
      across[t][j] = it->second.first;
      across[it->second.first][it->second.second] = t;
    }
  return across;
}

// Each vertex's triangles (compressed rows). [in] triangles; [in] vertices: their count.
struct VertexTriangles {
  std::vector<int> start, triangle;
};

VertexTriangles vertexTriangles(const std::vector<std::array<int, 3>>& triangles, std::size_t vertices) {
  VertexTriangles vt;
  vt.start.assign(vertices + 1, 0);
  for (const auto& t : triangles)
    for (int v : t) ++vt.start[v + 1];
  for (std::size_t v = 0; v < vertices; ++v) vt.start[v + 1] += vt.start[v];
  vt.triangle.resize(vt.start.back());
  std::vector<int> next(vt.start.begin(), vt.start.end() - 1);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int v : triangles[t]) vt.triangle[next[v]++] = t;
  return vt;
}

// Whether side j of triangle t has vertex v.
bool sideHas(const std::array<int, 3>& t, int j, int v) { return t[j] == v || t[(j + 1) % 3] == v; }

// Connected pieces of each patch, numbered in order of their first triangle. [in] across; [in,out] patch.
// Returns the number of pieces.
int splitIntoPieces(const Neighbours& across, std::vector<int>& patch) {
  UnionFind pieces(patch.size());
  for (int t = 0; t < static_cast<int>(patch.size()); ++t)
    for (int u : across[t])
      if (u >= 0 && patch[u] == patch[t]) pieces.unite(t, u);
  std::vector<int> number(patch.size(), -1);
  int count = 0;
  for (int t = 0; t < static_cast<int>(patch.size()); ++t) {
    int& n = number[pieces.find(t)];
    if (n < 0) n = count++;
    patch[t] = n;
  }
  return count;
}

// The patch sharing the most edges with a group of triangles; -1 if none. [in] counts: patch -> edges shared
// (the group's own patch left out by the caller).
int mostShared(const std::map<int, int>& counts) {
  int best = -1, most = 0;
  for (const auto& [p, n] : counts)
    if (n > most) best = p, most = n;  // ties: the lowest patch (map order)
  return best;
}

// Patches of fewer than kSmallPatch triangles join the neighbour they share most edges with.
// [in] across; [in,out] patch; [in] count: patches. Returns the triangles moved.
std::size_t joinSmallPatches(const Neighbours& across, std::vector<int>& patch, int count) {
  std::vector<int> size(count, 0);
  for (int p : patch) ++size[p];
  std::vector<std::map<int, int>> shared(count);
  for (int t = 0; t < static_cast<int>(patch.size()); ++t)
    if (size[patch[t]] < kSmallPatch)
      for (int u : across[t])
        if (u >= 0 && patch[u] != patch[t]) ++shared[patch[t]][patch[u]];
  std::vector<int> into(count);
  for (int p = 0; p < count; ++p) into[p] = size[p] < kSmallPatch ? mostShared(shared[p]) : -1;
  std::size_t moved = 0;
  for (int& p : patch)
    if (into[p] >= 0) p = into[p], ++moved;
  return moved;
}

// Where a patch meets itself at a vertex (two or more fans of its triangles round it, apart), the fans but the
// largest go to the patches their triangles' neighbours are in (if `move`). [in] triangles, across, vt;
// [in,out] patch; [in] move. Returns the triangles moved; [out] pinched: the (vertex, patch) pairs found.
std::size_t unpinch(const std::vector<std::array<int, 3>>& triangles, const Neighbours& across,
                    const VertexTriangles& vt, std::vector<int>& patch, bool move, std::size_t& pinched) {
  std::size_t moved = 0;
  pinched = 0;
  std::vector<int> fan(triangles.size(), -1);
  for (std::size_t v = 0; v + 1 < vt.start.size(); ++v) {
    const int vertex = static_cast<int>(v);
    std::vector<int> round(vt.triangle.begin() + vt.start[v], vt.triangle.begin() + vt.start[v + 1]);
    std::vector<std::vector<int>> fans;  // fans of one patch each
    for (int seed : round) {
      if (fan[seed] >= 0) continue;
      fan[seed] = static_cast<int>(fans.size());
      fans.push_back({seed});
      for (std::size_t k = 0; k < fans.back().size(); ++k) {
        const int t = fans.back()[k];
        for (int j = 0; j < 3; ++j)
          if (const int u = across[t][j];
              u >= 0 && fan[u] < 0 && patch[u] == patch[seed] && sideHas(triangles[t], j, vertex))
            fan[u] = fan[seed], fans.back().push_back(u);
      }
    }
    for (int t : round) fan[t] = -1;
    std::map<int, std::vector<int>> byPatch;  // patch -> its fans here
    for (int f = 0; f < static_cast<int>(fans.size()); ++f) byPatch[patch[fans[f][0]]].push_back(f);
    for (auto& [p, list] : byPatch) {
      if (list.size() < 2) continue;
      ++pinched;
      if (!move) continue;
      const int keep =
          *std::max_element(list.begin(), list.end(), [&](int a, int b) { return fans[a].size() < fans[b].size(); });
      for (int f : list) {
        if (f == keep) continue;
        std::map<int, int> around;
        for (int t : fans[f])
          for (int u : across[t])
            if (u >= 0 && patch[u] != p) ++around[patch[u]];
        if (const int to = mostShared(around); to >= 0)
          for (int t : fans[f]) patch[t] = to, ++moved;
      }
    }
  }
  return moved;
}

// The unit normal of each triangle (zero for a degenerate one).
std::vector<Vec3> triangleNormals(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Vec3> normal(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& c = triangles[t];
    const Vec3 n = (points[c[1]] - points[c[0]]).cross(points[c[2]] - points[c[0]]);
    normal[t] = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
  }
  return normal;
}

// Patches grown across edges turning less than the feature angle, normals within it of the patch's first, from the
// triangles in the order given (all of them). Numbered in that order.
// [in] normal: per triangle (triangleNormals).
std::vector<int> grownPatches(const std::vector<Vec3>& normal, const Neighbours& across, double featureAngle,
                              const std::vector<int>& seeds) {
  const double within = std::cos(featureAngle * M_PI / 180);
  auto near = [&](int a, int b) {
    return normal[a].isZero() || normal[b].isZero() || normal[a].dot(normal[b]) >= within;
  };
  std::vector<int> patch(normal.size(), -1);
  int count = 0;
  for (const int seed : seeds) {
    if (patch[seed] >= 0) continue;
    std::deque<int> front{seed};
    patch[seed] = count;
    while (!front.empty()) {
      const int t = front.front();
      front.pop_front();
      for (int u : across[t])
        if (u >= 0 && patch[u] < 0 && near(t, u) && near(seed, u)) patch[u] = count, front.push_back(u);
    }
    ++count;
  }
  return patch;
}

// The triangles in index order.
std::vector<int> inOrder(std::size_t triangles) {
  std::vector<int> order(triangles);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

// The triangles lying flat among their neighbours (none turning more than kFlatSeed from them) first, then the others,
// each in index order (PatchSeeds::FlatFirst).
// [in] normal: per triangle (triangleNormals).
std::vector<int> flatFirst(const std::vector<Vec3>& normal, const Neighbours& across) {
  const double flat = std::cos(kFlatSeed * M_PI / 180);
  std::vector<int> order = inOrder(normal.size());
  std::stable_partition(order.begin(), order.end(), [&](int t) {
    return std::all_of(across[t].begin(), across[t].end(),
                       [&](int u) { return u < 0 || normal[t].dot(normal[u]) >= flat; });
  });
  return order;
}

// Patches renumbered in order of their lowest triangle. [in,out] patch.
void numberByFirstTriangle(std::vector<int>& patch) {
  std::map<int, int> number;
  for (int& p : patch) p = number.emplace(p, static_cast<int>(number.size())).first->second;
}

// The triangles of patches narrower than minWidth (twice their area over their perimeter: a strip's width) go, a row at
// a time from the wider patches' edges, to the patch of the neighbour whose normal is nearest theirs: the facets of a
// bend split between the faces on either side where the surface turns from the one to the other.
// [in] points, triangles, across; [in] normal: per triangle (triangleNormals); [in,out] patch; [in] minWidth.
void dissolveNarrowPatches(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                           const Neighbours& across, const std::vector<Vec3>& normal, std::vector<int>& patch,
                           double minWidth) {
  std::map<int, double> area, perimeter;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& c = triangles[t];
    area[patch[t]] += 0.5 * (points[c[1]] - points[c[0]]).cross(points[c[2]] - points[c[0]]).norm();
    for (int j = 0; j < 3; ++j)
      if (const int u = across[t][j]; u < 0 || patch[u] != patch[t])
        perimeter[patch[t]] += (points[c[(j + 1) % 3]] - points[c[j]]).norm();
  }
  std::vector<int> label(patch.size());
  for (std::size_t t = 0; t < patch.size(); ++t)
    label[t] = 2 * area[patch[t]] >= minWidth * perimeter[patch[t]] ? patch[t] : -1;
  if (std::none_of(label.begin(), label.end(), [](int l) { return l >= 0; })) return;
  // The rows: the triangles not yet given beside given ones, each row labelled from the labels before it.
  auto unlabelledBeside = [&](const std::vector<int>& given) {
    std::vector<int> next;
    for (int t : given)
      for (int u : across[t])
        if (u >= 0 && label[u] < 0) next.push_back(u);
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    return next;
  };
  std::vector<int> given;
  for (int t = 0; t < static_cast<int>(patch.size()); ++t)
    if (label[t] >= 0) given.push_back(t);
  for (std::vector<int> front = unlabelledBeside(given); !front.empty(); front = unlabelledBeside(given)) {
    std::vector<std::pair<int, int>> row;  // triangle, its new patch
    for (int t : front) {
      int best = -1;
      for (int u : across[t])
        if (u >= 0 && label[u] >= 0 && (best < 0 || normal[t].dot(normal[u]) > normal[t].dot(normal[best]))) best = u;
      row.emplace_back(t, label[best]);
    }
    given.clear();
    for (const auto& [t, l] : row) label[t] = l, given.push_back(t);
  }
  for (std::size_t t = 0; t < patch.size(); ++t)
    if (label[t] >= 0) patch[t] = label[t];
}

// The patches' rims fitted to their normals (variational shape approximation's normal proxies, Cohen-Steiner et al.
// 2004): round after round, a triangle on a patch's rim goes to the neighbouring patch whose mean normal (area
// weighted) is nearer its own by more than kFitMargin, within the feature angle of it; the moves of a round are
// decided together. Growing from a seed leaves a patch's rim wherever the normal cone ran out; a box's corner, where
// three faces' bends meet, had one face's patch reach a quad into the floor. [in] points, triangles, across; [in]
// normal: per triangle; [in] featureAngle: degrees; [in,out] patch. Returns the moves made.
std::size_t fitRimsToNormals(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                             const Neighbours& across, const std::vector<Vec3>& normal, double featureAngle,
                             std::vector<int>& patch) {
  const double within = std::cos(featureAngle * M_PI / 180);
  const int patches = patch.empty() ? 0 : 1 + *std::max_element(patch.begin(), patch.end());
  std::size_t moved = 0;
  for (int round = 0; round < kFitRounds; ++round) {
    std::vector<Vec3> proxy(patches, Vec3::Zero());  // per patch, its area-weighted mean normal
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto& c = triangles[t];
      proxy[patch[t]] += (points[c[1]] - points[c[0]]).cross(points[c[2]] - points[c[0]]);
    }
    for (Vec3& n : proxy) n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    std::vector<std::pair<int, int>> moves;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      if (normal[t].isZero()) continue;
      int best = patch[t];
      double nearest = normal[t].dot(proxy[patch[t]]) + kFitMargin;
      for (int u : across[t])
        if (u >= 0 && patch[u] != patch[t])
          if (const double d = normal[t].dot(proxy[patch[u]]); d > nearest && d >= within) best = patch[u], nearest = d;
      if (best != patch[t]) moves.emplace_back(t, best);
    }
    if (moves.empty()) break;
    for (const auto& [t, p] : moves) patch[t] = p;
    moved += moves.size();
  }
  return moved;
}

// The cleaning rounds of chordalPatches: small patches joined, pinches undone, pieces numbered apart.
// [in] triangles, across, vt; [in,out] patch.
void cleanPatches(const std::vector<std::array<int, 3>>& triangles, const Neighbours& across, const VertexTriangles& vt,
                  std::vector<int>& patch) {
  int count = splitIntoPieces(across, patch);
  for (int round = 0; round < kCleaningRounds; ++round) {
    std::size_t moved = joinSmallPatches(across, patch, count);
    count = splitIntoPieces(across, patch);
    std::size_t pinched = 0;
    moved += unpinch(triangles, across, vt, patch, true, pinched);
    count = splitIntoPieces(across, patch);
    if (moved == 0) break;
  }
}

}  // namespace

std::vector<int> facePatches(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                             double featureAngle, double minWidth, PatchSeeds seeds, PatchRims rims,
                             std::size_t* fitted) {
  const Neighbours across = triangleNeighbours(triangles);
  const std::vector<Vec3> normal = triangleNormals(points, triangles);
  std::vector<int> patch =
      grownPatches(normal, across, featureAngle,
                   seeds == PatchSeeds::FlatFirst ? flatFirst(normal, across) : inOrder(normal.size()));
  numberByFirstTriangle(patch);
  splitIntoPieces(across, patch);
  dissolveNarrowPatches(points, triangles, across, normal, patch, minWidth);
  const std::size_t moved =
      rims == PatchRims::FittedToNormals ? fitRimsToNormals(points, triangles, across, normal, featureAngle, patch) : 0;
  if (fitted) *fitted = moved;
  cleanPatches(triangles, across, vertexTriangles(triangles, points.size()), patch);
  return patch;
}

std::vector<int> chordalPatches(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                                double featureAngle) {
  const Neighbours across = triangleNeighbours(triangles);
  std::vector<int> patch =
      grownPatches(triangleNormals(points, triangles), across, featureAngle, inOrder(triangles.size()));
  cleanPatches(triangles, across, vertexTriangles(triangles, points.size()), patch);
  return patch;
}

PatchTopology patchTopology(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch) {
  struct Edge {
    int a, b;
    std::array<int, 2> patches;
  };
  const Neighbours across = triangleNeighbours(triangles);
  std::vector<Edge> edges;  // the patches' rim edges, once each
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int j = 0; j < 3; ++j) {
      const int u = across[t][j], a = triangles[t][j], b = triangles[t][(j + 1) % 3];
      if (u < 0)
        edges.push_back({a, b, {-1, patch[t]}});
      else if (patch[u] != patch[t] && t < u)
        edges.push_back({a, b, {std::min(patch[t], patch[u]), std::max(patch[t], patch[u])}});
    }
  std::map<int, std::vector<int>> at;  // vertex -> its rim edges
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) at[edges[e].a].push_back(e), at[edges[e].b].push_back(e);
  PatchTopology topology;
  std::map<int, bool> corner;
  for (const auto& [v, list] : at) corner[v] = list.size() != 2 || edges[list[0]].patches != edges[list[1]].patches;
  std::vector<char> used(edges.size(), 0);
  // The curve from corner `from` along edge e, to the next corner. [in] from, e.
  auto trace = [&](int from, int e) {
    PatchCurve curve{{from}, edges[e].patches};
    for (int v = from;;) {
      used[e] = 1;
      v = edges[e].a == v ? edges[e].b : edges[e].a;
      curve.vertices.push_back(v);
      if (corner[v]) break;
      const auto& list = at[v];
      e = list[0] == e ? list[1] : list[0];
    }
    topology.curves.push_back(std::move(curve));
  };
  for (const auto& [v, list] : at)
    if (corner[v])
      for (int e : list)
        if (!used[e]) trace(v, e);
  for (const auto& [v, list] : at)  // loops without a corner: from their lowest vertex
    if (!used[list[0]]) corner[v] = true, trace(v, list[0]);
  for (const auto& [v, isCorner] : corner)
    if (isCorner) topology.corners.push_back(v);
  const int patches = patch.empty() ? 0 : 1 + *std::max_element(patch.begin(), patch.end());
  topology.bounding.resize(patches);
  for (int c = 0; c < static_cast<int>(topology.curves.size()); ++c)
    for (int p : topology.curves[c].patches)
      if (p >= 0) topology.bounding[p].push_back(c);
  return topology;
}

std::size_t pinchedPatchVertices(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch) {
  std::size_t vertices = 0;
  for (const auto& t : triangles) vertices = std::max<std::size_t>(vertices, 1 + *std::max_element(t.begin(), t.end()));
  std::vector<int> copy = patch;
  std::size_t pinched = 0;
  unpinch(triangles, triangleNeighbours(triangles), vertexTriangles(triangles, vertices), copy, false, pinched);
  return pinched;
}

}  // namespace hexlayer
