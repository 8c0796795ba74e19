#include "chordal/chordal_rim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "core/threads.hpp"

namespace hexlayer {
namespace {

constexpr double kMinAreaShare = 0.5;  // a facet may not shrink below this share of its area
constexpr double kMaxAlongRim = 0.5;   // share of a rim vertex's move that may run along the rim
constexpr double kMinMove = 0.1;       // share of the reach below which a rim vertex stays: it is on its rim
// of fillTears' maxLength: the longest loop with material all round it filled
constexpr double kRoundMaterialTears = 3;

// Area vector of a facet (half the cross product of its diagonals for a quad): its normal times its area.
Vec3 areaVector(const ChordalSurface& s, const std::array<int, 4>& f) {
  const auto& v = s.vertices;
  if (f[3] < 0) return 0.5 * (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]);
  return 0.5 * (v[f[2]] - v[f[0]]).cross(v[f[3]] - v[f[1]]);
}

bool spoiled(const Vec3& before, const Vec3& after) {
  return after.dot(before) <= kMinAreaShare * before.squaredNorm();
}

// The rim's edges (in one facet only), lower vertex first, sorted; and per vertex whether it ends one (most
// facet edges asked about end at no rim vertex).
class RimEdges {
 public:
  explicit RimEdges(const ChordalSurface& s) : atVertex_(s.vertices.size(), 0) {
    for (const auto& [edge, uses] : facetEdgeUses(s))
      if (uses == 1) edges_.push_back(edge), atVertex_[edge.first] = atVertex_[edge.second] = 1;
  }
  bool has(int a, int b) const {
    return atVertex_[a] && atVertex_[b] &&
           std::binary_search(edges_.begin(), edges_.end(), std::pair<int, int>(std::minmax(a, b)));
  }

 private:
  std::vector<std::pair<int, int>> edges_;
  std::vector<char> atVertex_;
};

// The rim's edges in the direction of their facets (the surface on their left seen from the top): per
// vertex, the next and the previous rim vertex (-1 if none, or if the rim passes it twice).
struct RimWalk {
  std::vector<int> next, previous;
};

RimWalk rimWalk(const ChordalSurface& s) {
  const RimEdges rim(s);
  RimWalk w{std::vector<int>(s.vertices.size(), -1), std::vector<int>(s.vertices.size(), -1)};
  std::vector<int> passes(s.vertices.size(), 0);
  for (const auto& f : s.facets) {
    const int n = f[3] < 0 ? 3 : 4;
    for (int k = 0; k < n; ++k)
      if (const int a = f[k], b = f[(k + 1) % n]; rim.has(a, b)) w.next[a] = b, w.previous[b] = a, ++passes[a];
  }
  for (std::size_t v = 0; v < passes.size(); ++v)
    if (passes[v] > 1) w.next[v] = w.previous[v] = -1;
  return w;
}

// The walls' rim middles found so far, by the point they were asked for (a vertex still where it was asks again for
// nothing when the rim is measured again).
using KnownMiddles = std::map<std::array<double, 3>, std::optional<Vec3>>;

// Where each rim vertex goes: midway between the walls' rim edges nearest to it, if that is farther than
// kMinMove of the reach (nearer, the vertex is on its rim: a flat rim's), within reach, and across the rim (a
// move mostly along the rim is a corner's ambiguity, not the rim's profile). [in,out] known: the middles.
std::vector<std::optional<Vec3>> rimTargets(const ChordalSurface& s, const RimWalk& walk, const RimMiddle& middle,
                                            double reach, KnownMiddles& known) {
  auto keyOf = [&](long v) { return std::array<double, 3>{s.vertices[v].x(), s.vertices[v].y(), s.vertices[v].z()}; };
  std::vector<std::optional<Vec3>> to(s.vertices.size()), found(s.vertices.size());
  std::vector<char> asked(s.vertices.size(), 0);
  ParallelErrors errors;  // each vertex on its own: the walls' projections on every thread (`known` only read)
#pragma omp parallel for schedule(dynamic, 16)
  for (long v = 0; v < static_cast<long>(s.vertices.size()); ++v) {
    if (walk.next[v] < 0 || walk.previous[v] < 0) continue;
    errors.run([&] {
      const auto was = known.find(keyOf(v));
      if (was == known.end()) found[v] = middle(s.vertices[v]), asked[v] = 1;
      const std::optional<Vec3>& m = was == known.end() ? found[v] : was->second;
      if (!m) return;
      const Vec3 move = *m - s.vertices[v];
      const Vec3 along = (s.vertices[walk.next[v]] - s.vertices[walk.previous[v]]).normalized();
      if (move.norm() > kMinMove * reach && move.norm() <= reach &&
          std::abs(move.dot(along)) <= kMaxAlongRim * move.norm())
        to[v] = m;
    });
  }
  errors.rethrow();
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    if (asked[v]) known.emplace(keyOf(static_cast<long>(v)), found[v]);
  return to;
}

// The facets on the rim (with an edge of no other facet) that the moves of the rim vertices turn over or
// shrink: they lie in the rim's profile, beyond where the rim goes.
std::vector<char> spoiledRimFacets(const ChordalSurface& s, const std::vector<Vec3>& before) {
  const RimEdges rim(s);
  std::vector<char> spoilt(s.facets.size(), 0);
  for (std::size_t f = 0; f < s.facets.size(); ++f) {
    if (!spoiled(before[f], areaVector(s, s.facets[f]))) continue;
    const auto& facet = s.facets[f];
    const int n = facet[3] < 0 ? 3 : 4;
    for (int k = 0; k < n; ++k) spoilt[f] |= rim.has(facet[k], facet[(k + 1) % n]);
  }
  return spoilt;
}

// The angle at vertex b between its rim neighbours a and c.
double rimAngle(const ChordalSurface& s, int a, int b, int c) {
  const Vec3 ba = s.vertices[a] - s.vertices[b], bc = s.vertices[c] - s.vertices[b];
  return angleBetween(ba, bc);
}

constexpr double kMaxSliver = 15 * M_PI / 180;
constexpr int kMaxSliverRounds = 100;

// Drops the facets that end a narrow spike of the rim (a rim vertex of that facet only, the rim turning back
// by more than 180 - kMaxSliver degrees there). Returns how many.
std::size_t dropSpikes(ChordalSurface& s, const RimWalk& w) {
  std::vector<int> uses(s.vertices.size(), 0);
  for (const auto& f : s.facets)
    for (int v : f)
      if (v >= 0) ++uses[v];
  const std::size_t before = s.facets.size();
  s.facets.erase(std::remove_if(s.facets.begin(), s.facets.end(),
                                [&](const std::array<int, 4>& f) {
                                  for (int b : f)
                                    if (b >= 0 && uses[b] == 1 && w.previous[b] >= 0 && w.next[b] >= 0 &&
                                        rimAngle(s, w.previous[b], b, w.next[b]) < kMaxSliver)
                                      return true;
                                  return false;
                                }),
                 s.facets.end());
  return before - s.facets.size();
}

// Drops the facets at narrow spikes of the rim (where a tet's cut reached into a rim's profile) until none is
// left, and the rim's pinches that leaves. Returns how many facets.
std::size_t dropRimSpikes(ChordalSurface& s) {
  std::size_t dropped = 0;
  for (int round = 0; round < kMaxSliverRounds; ++round) {
    const std::size_t spikes = dropSpikes(s, rimWalk(s));
    if (spikes == 0) break;
    dropped += spikes + dropPinchedFacets(s) + dropIslands(s);
  }
  if (dropped) dropUnusedVertices(s);
  return dropped;
}

// Whether the rim cycle (in the facets' direction) is a hole of the surface round material (fillTears). [in] s, cycle,
// inMaterial.
bool holeRoundMaterial(const ChordalSurface& s, const std::vector<int>& cycle, const InMaterial& inMaterial) {
  Vec3 middle = Vec3::Zero();
  for (int v : cycle) middle += s.vertices[v];
  middle /= static_cast<double>(cycle.size());
  if (!inMaterial(middle) ||  // a hole's middle is air: asked first, the facets' walk below is over all of them
      !std::all_of(cycle.begin(), cycle.end(), [&](int v) { return inMaterial(0.5 * (middle + s.vertices[v])); }))
    return false;
  Vec3 turn = Vec3::Zero();  // the cycle's area vector
  for (std::size_t i = 0; i < cycle.size(); ++i)
    turn += (s.vertices[cycle[i]] - middle).cross(s.vertices[cycle[(i + 1) % cycle.size()]] - middle);
  const std::set<int> on(cycle.begin(), cycle.end());
  Vec3 normal = Vec3::Zero();  // of the facets round it
  for (const auto& f : s.facets)
    if (std::any_of(f.begin(), f.end(), [&](int v) { return v >= 0 && on.count(v) > 0; })) normal += areaVector(s, f);
  return turn.dot(normal) < 0;
}

// The first vertex of a rim cycle from which a fan of triangles closes it without an edge the surface has already (a
// chord of the loop between two of its vertices that facets elsewhere join: a fan along it would put that edge in
// four facets). [in] cycle; [in] edges: facetEdgeUses's. Returns its place in the cycle; none if every vertex has one.
std::optional<std::size_t> fanApex(const std::vector<int>& cycle,
                                   const std::vector<std::pair<std::pair<int, int>, int>>& edges) {
  const std::size_t n = cycle.size();
  for (std::size_t a = 0; a < n; ++a) {
    bool free = true;
    for (std::size_t i = 2; i + 1 < n && free; ++i) free = !isFacetEdge(edges, cycle[a], cycle[(a + i) % n]);
    if (free) return a;
  }
  return std::nullopt;
}

}  // namespace

std::size_t fillTears(ChordalSurface& s, const NearRim& nearRim, const InMaterial& inMaterial, double maxLength) {
  const RimLoops loops = rimLoops(s);
  const RimWalk walk = rimWalk(s);
  std::optional<std::vector<std::pair<std::pair<int, int>, int>>> edges;  // measured once a loop is to be filled
  std::vector<std::vector<int>> members(loops.length.size());
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    if (loops.loopOf[v] >= 0) members[loops.loopOf[v]].push_back(static_cast<int>(v));
  std::size_t filled = 0;
  for (std::size_t loop = 0; loop < members.size(); ++loop) {
    const std::vector<int>& ring = members[loop];
    const bool longer = loops.length[loop] > maxLength;  // a tear only where material is all round it
    if (loops.length[loop] > kRoundMaterialTears * maxLength || ring.size() < 3) continue;
    if (std::any_of(ring.begin(), ring.end(), [&](int v) { return walk.next[v] < 0; })) continue;  // a vertex twice
    const auto near = std::count_if(ring.begin(), ring.end(), [&](int v) { return nearRim(s.vertices[v]); });
    std::vector<int> cycle{ring[0]};  // in the facets' direction along the rim
    while (cycle.size() <= ring.size() && walk.next[cycle.back()] != ring[0]) cycle.push_back(walk.next[cycle.back()]);
    if (cycle.size() != ring.size()) continue;
    // along lateral faces: the part's own rim or hole, unless material is all round it
    if ((longer || 2 * near >= static_cast<long>(ring.size())) && !holeRoundMaterial(s, cycle, inMaterial)) continue;
    if (!edges) edges = facetEdgeUses(s);  // before any fill: the surface's own edges
    const std::optional<std::size_t> apex = fanApex(cycle, *edges);
    if (!apex) continue;
    std::rotate(cycle.begin(), cycle.begin() + static_cast<long>(*apex), cycle.end());
    for (std::size_t i = 1; i + 1 < cycle.size(); ++i)  // the rim edges taken the other way: facing as the rest
      s.facets.push_back({cycle[0], cycle[i + 1], cycle[i], -1}), ++s.triangles;
    ++filled;
  }
  return filled;
}

RimSnapStats snapRimBetweenWallEdges(ChordalSurface& s, const RimMiddle& middle, double reach) {
  RimSnapStats stats;
  KnownMiddles known;
  for (;;) {
    const RimWalk walk = rimWalk(s);
    std::vector<std::optional<Vec3>> to = rimTargets(s, walk, middle, reach, known);
    std::vector<Vec3> before;
    for (const auto& f : s.facets) before.push_back(areaVector(s, f));
    const std::vector<Vec3> original = s.vertices;
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
      if (to[v]) s.vertices[v] = *to[v];
    // A facet on the rim that the moves turn over (a tet's cut that reached into the rim's profile) goes,
    // and the rim is measured again without it.
    const std::vector<char> spikes = spoiledRimFacets(s, before);
    if (std::count(spikes.begin(), spikes.end(), 1) > 0) {
      s.vertices = original;
      std::size_t f = 0;
      s.facets.erase(std::remove_if(s.facets.begin(), s.facets.end(), [&](const auto&) { return spikes[f++] != 0; }),
                     s.facets.end());
      stats.spikesDropped += before.size() - s.facets.size();
      dropPinchedFacets(s);
      stats.spikesDropped += dropIslands(s);  // what the spikes held to the rest
      dropUnusedVertices(s);
      continue;
    }
    // Back where they were, the moved vertices of facets that turned over or shrank, and of rim edges that
    // turned round (two rim vertices put on one place or past each other along the rim), until none is left.
    auto back = [&](int v) { s.vertices[v] = original[v], to[v].reset(); };
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t f = 0; f < s.facets.size(); ++f) {
        if (!spoiled(before[f], areaVector(s, s.facets[f]))) continue;
        for (int v : s.facets[f])
          if (v >= 0 && to[v]) back(v), changed = true;
      }
      for (std::size_t a = 0; a < s.vertices.size(); ++a) {
        const int b = walk.next[a];
        if (b < 0 || (!to[a] && !to[b])) continue;
        const Vec3 was = original[b] - original[a];
        if ((s.vertices[b] - s.vertices[a]).dot(was) > kMinAreaShare * was.squaredNorm()) continue;
        for (int v : {static_cast<int>(a), b})
          if (to[v]) back(v), changed = true;
      }
    }
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {  // before the spikes go: they renumber the vertices
      stats.rimVertices += walk.next[v] >= 0;
      if (to[v]) ++stats.moved, stats.largestMove = std::max(stats.largestMove, (s.vertices[v] - original[v]).norm());
    }
    stats.spikesDropped += dropRimSpikes(s);
    return stats;
  }
}

}  // namespace hexlayer
