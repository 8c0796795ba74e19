#include "chordal/chordal_surface.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <unordered_map>

#include "core/error.hpp"
#include "core/groups.hpp"
#include "core/point_grid.hpp"
#include "core/union_find.hpp"

namespace hexlayer {
namespace {

constexpr int kMaxCollapseRounds = 10;
// A part of the chordal surface with less than this share of the largest part's area is an island of a few tets.
constexpr double kIslandShare = 0.01;

// Area of a facet (a quad as two triangles on its 0-2 diagonal).
double facetArea(const ChordalSurface& s, const std::array<int, 4>& f) {
  const auto& v = s.vertices;
  double a = 0.5 * (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]).norm();
  if (f[3] >= 0) a += 0.5 * (v[f[2]] - v[f[0]]).cross(v[f[3]] - v[f[0]]).norm();
  return a;
}

// The chordal vertex of tet edge (top, bottom), created on first use.
int chordalVertex(ChordalSurface& s, std::unordered_map<std::uint64_t, int>& index, const TetMesh& m, int top,
                  int bottom) {
  const auto [it, added] = index.emplace(edgeKey(top, bottom), static_cast<int>(s.vertices.size()));
  if (added) {
    s.vertices.push_back(0.5 * (m.nodes[top] + m.nodes[bottom]));  // v = (v_t + v_b) / 2 (§5.4)
    s.tetEdge.push_back({top, bottom});
  }
  return it->second;
}

// Orients the facet so that it turns counter-clockwise seen from the top side.
void orientTowardsTop(std::array<int, 4>& facet, const ChordalSurface& s, const Vec3& upward) {
  if (facetNormal(s, facet).dot(upward) >= 0) return;
  if (facet[3] < 0)
    std::swap(facet[0], facet[2]);
  else
    std::swap(facet[1], facet[3]);
}

// Cospherical nodes (a rectangle of two top and two bottom nodes) can make TetGen use both
// diagonals of a planar quad; their midpoints coincide and are one point of the surface.
void joinCoincidentVertices(const ChordalSurface& s, double tolerance, UnionFind& merges) {
  PointGrid grid(std::max(tolerance, 1e-300) * 4);
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    grid.forEachNear(s.vertices[i], tolerance, [&](int j, const Vec3&) { merges.unite(static_cast<int>(i), j); });
    grid.insert(static_cast<int>(i), s.vertices[i]);
  }
}

// A coplanar tet whose top edge is parallel to its bottom edge (two bubbles on each of the parallel
// edges of a bend) or whose three top nodes lie on a line has a facet with all corners on one line.
// The facets on the tet's two sides meet it along different chains of that line; joining the
// facet's inner corners (a quad's inner diagonal, a triangle's middle corner with the nearer end)
// zips the two chains into one edge chain. Returns whether any facet was degenerate.
bool joinDegenerateFacets(const ChordalSurface& s, UnionFind& merges) {
  bool any = false;
  for (const auto& f : s.facets) {
    const int n = f[3] < 0 ? 3 : 4;
    auto at = [&](int k) { return s.vertices[f[(k + n) % n]]; };
    int longest = 0;  // the edge (longest, longest + 1)
    for (int k = 1; k < n; ++k)
      if ((at(k + 1) - at(k)).squaredNorm() > (at(longest + 1) - at(longest)).squaredNorm()) longest = k;
    const double length2 = (at(longest + 1) - at(longest)).squaredNorm();
    const double area2 = n == 3 ? (at(1) - at(0)).cross(at(2) - at(0)).squaredNorm()
                                : (at(2) - at(0)).cross(at(3) - at(1)).squaredNorm();
    if (length2 == 0 || area2 > 1e-12 * length2 * length2) continue;
    any = true;
    if (n == 4) {  // the diagonal with the nearer corners is inside the other one on the line
      const bool inner13 = (at(3) - at(1)).squaredNorm() <= (at(2) - at(0)).squaredNorm();
      merges.unite(f[inner13 ? 1 : 0], f[inner13 ? 3 : 2]);
    } else {
      const int mid = (longest + 2) % 3;
      const bool toStart = (at(mid) - at(longest)).squaredNorm() <= (at(mid) - at(longest + 1)).squaredNorm();
      merges.unite(f[mid], f[(longest + (toStart ? 0 : 1)) % 3]);
    }
  }
  return any;
}

// Rebuilds the surface with every group of joined vertices as one vertex at the group's centroid;
// facets that lose corners become triangles or are dropped.
void applyMerges(ChordalSurface& s, UnionFind& merges) {
  std::vector<int> newIndex(s.vertices.size(), -1);
  std::vector<int> members;
  ChordalSurface merged;
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    const int root = merges.find(static_cast<int>(i));
    if (newIndex[root] < 0) {
      newIndex[root] = static_cast<int>(merged.vertices.size());
      merged.vertices.push_back(Vec3::Zero());
      merged.tetEdge.push_back(s.tetEdge[root]);
      members.push_back(0);
    }
    merged.vertices[newIndex[root]] += s.vertices[i];
    ++members[newIndex[root]];
  }
  for (size_t v = 0; v < merged.vertices.size(); ++v) merged.vertices[v] /= members[v];
  for (const auto& f : s.facets) {
    std::vector<int> ring;  // corners with repeats removed, cyclically
    for (int k = 0; k < 4 && f[k] >= 0; ++k)
      if (const int v = newIndex[merges.find(f[k])]; ring.empty() || ring.back() != v) ring.push_back(v);
    if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    const int n = static_cast<int>(ring.size());
    if (n < 3 || (n == 4 && (ring[0] == ring[2] || ring[1] == ring[3]))) continue;
    std::array<int, 4> g{-1, -1, -1, -1};
    std::copy(ring.begin(), ring.end(), g.begin());
    (n == 3 ? merged.triangles : merged.quads)++;
    merged.facets.push_back(g);
  }
  s = std::move(merged);
}

// Joins coincident vertices, then collapses degenerate facets until none is left (a collapse can
// leave a neighbour degenerate).
void collapseDegenerateFacets(ChordalSurface& s, double tolerance) {
  UnionFind coincident(s.vertices.size());
  joinCoincidentVertices(s, tolerance, coincident);
  applyMerges(s, coincident);
  for (int round = 0; round < kMaxCollapseRounds; ++round) {
    UnionFind merges(s.vertices.size());
    if (!joinDegenerateFacets(s, merges)) return;
    applyMerges(s, merges);
  }
}

void requireManifold(const ChordalSurface& s, double unit) {
  std::vector<Vec3> junctions;
  for (const auto& [edge, uses] : facetEdgeUses(s))
    if (uses > 2) junctions.push_back(0.5 * (s.vertices[edge.first] + s.vertices[edge.second]));
  if (junctions.empty()) return;
  std::sort(junctions.begin(), junctions.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  std::ostringstream msg;
  const Vec3 at = junctions[0] / unit;
  msg << "non-manifold chordal surface: " << junctions.size() << " edges shared by more than two facets, e.g. at ("
      << at.x() << ", " << at.y() << ", " << at.z() << ") (a rib or T-junction?)";
  throw geometryError(msg.str());
}

}  // namespace

RimLoops rimLoops(const ChordalSurface& s) {
  const auto edges = facetEdgeUses(s);
  UnionFind rims(s.vertices.size());
  std::vector<char> onRim(s.vertices.size(), 0);
  for (const auto& [edge, uses] : edges)
    if (uses == 1) rims.unite(edge.first, edge.second), onRim[edge.first] = onRim[edge.second] = 1;
  RimLoops out{std::vector<int>(s.vertices.size(), -1), {}};
  std::vector<int> loopOfRoot(s.vertices.size(), -1);
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    if (!onRim[v]) continue;
    int& loop = loopOfRoot[rims.find(static_cast<int>(v))];
    if (loop < 0) loop = static_cast<int>(out.length.size()), out.length.push_back(0);
    out.loopOf[v] = loop;
  }
  for (const auto& [edge, uses] : edges)
    if (uses == 1) out.length[out.loopOf[edge.first]] += (s.vertices[edge.first] - s.vertices[edge.second]).norm();
  return out;
}

std::size_t dropUnusedVertices(ChordalSurface& s) {
  std::vector<int> renumber(s.vertices.size(), -1);
  for (const auto& f : s.facets)
    for (int v : f)
      if (v >= 0) renumber[v] = 0;
  ChordalSurface kept;
  const bool measured = s.normals.size() == s.vertices.size() && s.radius.size() == s.vertices.size();
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    if (renumber[v] == 0) {
      renumber[v] = static_cast<int>(kept.vertices.size());
      kept.vertices.push_back(s.vertices[v]), kept.tetEdge.push_back(s.tetEdge[v]);
      if (measured) kept.normals.push_back(s.normals[v]), kept.radius.push_back(s.radius[v]);
    }
  for (auto f : s.facets) {
    for (int& v : f) v = v >= 0 ? renumber[v] : -1;
    kept.facets.push_back(f);
    ++(f[3] < 0 ? kept.triangles : kept.quads);
  }
  s = std::move(kept);
  return s.facets.size();
}

std::size_t dropPinchedFacets(ChordalSurface& s) {
  std::size_t dropped = 0;
  for (;;) {
    std::vector<int> rimDegree(s.vertices.size(), 0);
    for (const auto& [edge, uses] : facetEdgeUses(s))
      if (uses == 1) ++rimDegree[edge.first], ++rimDegree[edge.second];
    // Per pinched vertex, its facets; two of them are in one fan when they share an edge at the vertex.
    std::map<int, std::vector<int>> around;
    for (std::size_t f = 0; f < s.facets.size(); ++f)
      for (int v : s.facets[f])
        if (v >= 0 && rimDegree[v] > 2) around[v].push_back(static_cast<int>(f));
    std::vector<char> drop(s.facets.size(), 0);
    for (const auto& [v, facets] : around) {
      UnionFind fans(static_cast<int>(facets.size()));
      std::map<int, int> byOtherEnd;  // the other end of an edge at v: the first facet seen with it
      for (std::size_t i = 0; i < facets.size(); ++i) {
        const auto& f = s.facets[facets[i]];
        const int n = f[3] < 0 ? 3 : 4;
        const int at = static_cast<int>(std::find(f.begin(), f.begin() + n, v) - f.begin());
        for (int w : {f[(at + 1) % n], f[(at + n - 1) % n]})
          if (auto [it, fresh] = byOtherEnd.emplace(w, static_cast<int>(i)); !fresh)
            fans.unite(it->second, static_cast<int>(i));
      }
      std::map<int, int> size;  // per fan (its root), its facets
      for (std::size_t i = 0; i < facets.size(); ++i) ++size[fans.find(static_cast<int>(i))];
      int largest = -1;
      for (const auto& [root, n] : size)
        if (largest < 0 || n > size[largest]) largest = root;
      for (std::size_t i = 0; i < facets.size(); ++i)
        if (fans.find(static_cast<int>(i)) != largest) drop[facets[i]] = 1;
    }
    const std::size_t before = s.facets.size();
    std::size_t f = 0;
    s.facets.erase(std::remove_if(s.facets.begin(), s.facets.end(), [&](const auto&) { return drop[f++]; }),
                   s.facets.end());
    if (s.facets.size() == before) break;
    dropped += before - s.facets.size();
  }
  if (dropped) dropUnusedVertices(s);
  return dropped;
}

std::size_t dropIslands(ChordalSurface& s) {
  UnionFind parts(s.vertices.size());
  for (const auto& f : s.facets)
    for (int k = 1; k < 4 && f[k] >= 0; ++k) parts.unite(f[0], f[k]);
  std::map<int, double> area;  // per part (its root), its facets' area
  for (const auto& f : s.facets) area[parts.find(f[0])] += facetArea(s, f);
  double largest = 0;
  for (const auto& [root, a] : area) largest = std::max(largest, a);
  const std::size_t before = s.facets.size();
  s.facets.erase(std::remove_if(s.facets.begin(), s.facets.end(),
                                [&](const auto& f) { return area[parts.find(f[0])] < kIslandShare * largest; }),
                 s.facets.end());
  const std::size_t dropped = before - s.facets.size();
  if (dropped) dropUnusedVertices(s);
  return dropped;
}

Vec3 facetNormal(const ChordalSurface& s, const std::array<int, 4>& f) {
  const auto& v = s.vertices;
  const bool triangle = f[3] < 0;
  const Vec3 e1 = triangle ? Vec3(v[f[0]] - v[f[1]]) : Vec3(v[f[3]] - v[f[1]]);  // Eq. 1
  const Vec3 e2 = triangle ? Vec3(v[f[2]] - v[f[1]]) : Vec3(v[f[2]] - v[f[0]]);
  const Vec3 n = e2.cross(e1);
  const double len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3(Vec3::Zero());
}

ChordalSurface buildChordalSurface(const TetMesh& m, double unit) {
  ChordalSurface s;
  std::unordered_map<std::uint64_t, int> index;
  for (const auto& t : m.tets) {
    std::vector<int> top, bottom;
    for (int v : t) (m.side[v] == Side::Top ? top : bottom).push_back(v);
    if (top.empty() || bottom.empty()) continue;  // flat tet: not cut
    std::array<int, 4> facet{-1, -1, -1, -1};
    if (top.size() == 2) {  // 2-2: the four top-bottom edges form a quad (T0B0, T0B1, T1B1, T1B0)
      facet = {chordalVertex(s, index, m, top[0], bottom[0]), chordalVertex(s, index, m, top[0], bottom[1]),
               chordalVertex(s, index, m, top[1], bottom[1]), chordalVertex(s, index, m, top[1], bottom[0])};
      ++s.quads;
    } else {  // 3-1 or 1-3: the three edges at the lone node form a triangle
      const std::vector<int>& many = top.size() == 3 ? top : bottom;
      const int lone = top.size() == 3 ? bottom[0] : top[0];
      for (int k = 0; k < 3; ++k)
        facet[k] =
            top.size() == 3 ? chordalVertex(s, index, m, many[k], lone) : chordalVertex(s, index, m, lone, many[k]);
      ++s.triangles;
    }
    Vec3 upward = Vec3::Zero();
    for (int v : top) upward += m.nodes[v] / top.size();
    for (int v : bottom) upward -= m.nodes[v] / bottom.size();
    orientTowardsTop(facet, s, upward);
    s.facets.push_back(facet);
  }
  if (s.facets.empty()) throw geometryError("empty chordal surface: no tet spans the top and bottom walls");
  collapseDegenerateFacets(s, 1e-9 * boxDiagonal(m.nodes));
  requireManifold(s, unit);
  s.pinchedFacetsDropped = dropPinchedFacets(s);
  s.islandFacetsDropped = dropIslands(s);
  return s;
}

std::vector<std::pair<std::pair<int, int>, int>> facetEdgeUses(const ChordalSurface& s) {
  // A counting sort by the lower end, then each lower end's higher ends sorted: the order of sorting the edges whole,
  // in time linear in the facets (this runs at every step that changes the facets).
  int ends = 0;
  for (const auto& f : s.facets)
    for (int v : f) ends = std::max(ends, v + 1);
  auto forEachEdge = [&](auto emit) {
    for (const auto& f : s.facets) {
      const int n = f[3] < 0 ? 3 : 4;
      for (int k = 0; k < n; ++k) emit(std::min(f[k], f[(k + 1) % n]), std::max(f[k], f[(k + 1) % n]));
    }
  };
  Groups<int> higher = groupByKey<int>(static_cast<std::size_t>(ends), forEachEdge);
  std::vector<std::pair<std::pair<int, int>, int>> uses;
  for (int a = 0; a < ends; ++a) {
    const auto from = higher.items.begin() + higher.start[a], to = higher.items.begin() + higher.start[a + 1];
    std::sort(from, to);
    for (auto b = from; b != to; ++b)
      if (b == from || *b != *(b - 1))
        uses.push_back({{a, *b}, 1});
      else
        ++uses.back().second;
  }
  return uses;
}

std::size_t trimKnifeEdges(ChordalSurface& s, double minRadius) {
  const std::size_t before = s.facets.size();
  for (bool dropped = true; dropped;) {
    std::vector<char> thinRim(s.vertices.size(), 0);
    for (const auto& [edge, uses] : facetEdgeUses(s))
      if (uses == 1)
        for (int v : {edge.first, edge.second}) thinRim[v] |= s.radius[v] < minRadius;
    const auto thin = [&](const std::array<int, 4>& f) {
      for (int v : f)
        if (v >= 0 && thinRim[v]) return true;
      return false;
    };
    const std::size_t n = s.facets.size();
    s.facets.erase(std::remove_if(s.facets.begin(), s.facets.end(), thin), s.facets.end());
    dropped = s.facets.size() < n;
  }
  return before - dropUnusedVertices(s);
}

std::vector<Vec3> vertexNormals(const ChordalSurface& s) {
  std::vector<Vec3> sum(s.vertices.size(), Vec3::Zero());
  for (const auto& f : s.facets) {
    const Vec3 n = facetNormal(s, f);
    for (int k = 0; k < (f[3] < 0 ? 3 : 4); ++k) sum[f[k]] += n;
  }
  for (Vec3& n : sum)  // Eq. 2: N̄ = Σ n_i / k, n̄ = N̄ / |N̄| (the 1/k drops out)
    if (n.norm() > 0) n.normalize();
  return sum;
}

void computeNormalsAndRadius(ChordalSurface& s, const TetMesh& m) {
  s.normals = vertexNormals(s);
  s.radius.resize(s.vertices.size());
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    if (s.normals[v].norm() == 0) s.normals[v] = Vec3::UnitZ();
    const Vec3 l = m.nodes[s.tetEdge[v][0]] - s.vertices[v];  // l = v_t - v
    s.radius[v] = std::abs(s.normals[v].dot(l));              // Eq. 3: r = n̄ · l
  }
}

bool isFacetEdge(const std::vector<std::pair<std::pair<int, int>, int>>& edges, int a, int b) {
  const std::pair<int, int> e = std::minmax(a, b);
  const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(e, 0));
  return it != edges.end() && it->first == e;
}

std::vector<std::array<int, 3>> chordalTriangles(const ChordalSurface& chordal) {
  const bool quads = std::any_of(chordal.facets.begin(), chordal.facets.end(), [](const auto& f) { return f[3] >= 0; });
  const auto edges = quads ? facetEdgeUses(chordal) : std::vector<std::pair<std::pair<int, int>, int>>{};
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(chordal.facets.size() * 2);
  for (const auto& f : chordal.facets) {
    if (f[3] < 0) {
      triangles.push_back({f[0], f[1], f[2]});
    } else if (!isFacetEdge(edges, f[0], f[2]) || isFacetEdge(edges, f[1], f[3])) {
      triangles.push_back({f[0], f[1], f[2]}), triangles.push_back({f[0], f[2], f[3]});
    } else {
      triangles.push_back({f[0], f[1], f[3]}), triangles.push_back({f[1], f[2], f[3]});
    }
  }
  return triangles;
}

double chordalArea(const ChordalSurface& c) {
  double a = 0;
  for (const auto& f : c.facets) a += facetArea(c, f);
  return a;
}

std::map<std::string, std::size_t> classifyTets(const TetMesh& m) {
  static const int faceOf[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  static const int edgeOf[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  auto triKey = [&](std::size_t tet, int face) {
    std::array<int, 3> t{m.tets[tet][faceOf[face][0]], m.tets[tet][faceOf[face][1]], m.tets[tet][faceOf[face][2]]};
    std::sort(t.begin(), t.end());
    return (static_cast<std::uint64_t>(t[0]) << 42) ^ (static_cast<std::uint64_t>(t[1]) << 21) ^
           static_cast<std::uint64_t>(t[2]);
  };
  // Every tet face as (key, 4 tet + face), sorted: a key found once is an exterior triangle.
  std::vector<std::pair<std::uint64_t, std::size_t>> faces;
  faces.reserve(4 * m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    for (int f = 0; f < 4; ++f) faces.emplace_back(triKey(t, f), 4 * t + f);
  std::sort(faces.begin(), faces.end());
  std::vector<char> exterior(faces.size(), 0);
  std::vector<std::uint64_t> exteriorEdges;  // edges of exterior triangles
  for (std::size_t i = 0, j; i < faces.size(); i = j) {
    for (j = i + 1; j < faces.size() && faces[j].first == faces[i].first;) ++j;
    if (j - i != 1) continue;
    const std::size_t t = faces[i].second / 4;
    const int* f = faceOf[faces[i].second % 4];
    exterior[faces[i].second] = 1;
    for (int k = 0; k < 3; ++k) exteriorEdges.push_back(edgeKey(m.tets[t][f[k]], m.tets[t][f[(k + 1) % 3]]));
  }
  std::sort(exteriorEdges.begin(), exteriorEdges.end());
  exteriorEdges.erase(std::unique(exteriorEdges.begin(), exteriorEdges.end()), exteriorEdges.end());
  std::array<std::array<std::size_t, 7>, 5> counts{};  // [exterior triangles][exterior edges]
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    int tris = 0, edges = 0;
    for (int f = 0; f < 4; ++f) tris += exterior[4 * t + f];
    for (const auto& e : edgeOf)
      edges +=
          std::binary_search(exteriorEdges.begin(), exteriorEdges.end(), edgeKey(m.tets[t][e[0]], m.tets[t][e[1]]));
    ++counts[tris][edges];
  }
  std::map<std::string, std::size_t> classes;
  for (int tris = 0; tris < 5; ++tris)
    for (int edges = 0; edges < 7; ++edges)
      if (counts[tris][edges] > 0) classes[std::to_string(tris) + "/" + std::to_string(edges)] = counts[tris][edges];
  return classes;
}

}  // namespace hexlayer
