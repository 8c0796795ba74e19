#include "quadmesh/footprint_insert.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "core/box_grid.hpp"
#include "core/bytes.hpp"
#include "core/child_process.hpp"
#include "core/error.hpp"
#include "core/point_grid.hpp"
#include "core/polygon.hpp"
#include "core/threads.hpp"
#include "core/triangle_tree.hpp"
#include "core/union_find.hpp"
#include "quadmesh/quad_completion.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "quadmesh/quad_strips.hpp"
#include "quadmesh/surface_map.hpp"

namespace hexlayer {
namespace {

constexpr double kBands[] = {2, 3, 4};  // of the quad size: the sheet's quads this near a footprint are meshed again
constexpr double kMergeOpposite = 0.2;  // of a footprint's shortest edge: feet on both sides this near are one
constexpr double kOverlap = 1e-3;       // of the quad size: a foot this near another overlaps it
constexpr double kCoincide = 1e-2;      // of kOnRim: a rim node this near a footprint node is that node
constexpr double kOnRim = 0.1;          // of the quad size: a footprint node this near the sheet's rim lies on it
constexpr double kTinyEdge = 0.3;       // of the quad size: a rim node of the gap this near a footprint's is dropped
constexpr int kMaxStrip = 20;           // quads between two leftover triangles that are paired (quad_completion)
constexpr double kGmshSeconds = 120;    // a gap's Gmsh run (it takes milliseconds)
constexpr int kGapAlgorithms[] = {6, 5, 1};  // Gmsh's 2D algorithms tried: frontal-Delaunay, Delaunay, MeshAdapt
constexpr double kGoodGap = 0.3;             // scaled Jacobian of a gap's worst quad that needs no other way:
                                             // no acute corners cut off (gapQuads), no wider gap
constexpr int kAlongNormal = 4;              // steps of a footprint node onto the chordal surface along a normal
constexpr int kSmoothing = 10;               // iterations of the gap's quads (as the quad stage's)
constexpr double kAcute = 70 * M_PI / 180;   // a boundary corner of the gap below this gets a quad of its own
constexpr int kWedgeSteps = 12;              // the wedge quad's fourth corner: tried at kWedgeSteps^2 places
constexpr double kFlat = 0.05;  // scaled Jacobian of a Gmsh quad of the gap taken out with a neighbour and split anew

using Quad = std::array<int, 4>;
using Edge = std::pair<int, int>;  // directed, the gap on its left
using Loop = std::vector<int>;     // nodes in order, the gap on the left

// Twice the quad's vector area: along its normal.
Vec3 areaVector(const std::vector<Vec3>& nodes, const Quad& q) {
  return (nodes[q[2]] - nodes[q[0]]).cross(nodes[q[3]] - nodes[q[1]]);
}

// Distance from p to the segment ab, and where its nearest point is along it (0 at a, 1 at b).
std::pair<double, double> toSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double t = nearestOnSegment(a, b, p);
  return {(a + t * (b - a) - p).norm(), t};
}

std::array<Triangle, 2> triangles(const std::vector<Vec3>& nodes, const Quad& q) {
  return {Triangle{nodes[q[0]], nodes[q[1]], nodes[q[2]]}, Triangle{nodes[q[0]], nodes[q[2]], nodes[q[3]]}};
}

// Every node, the sheet's then the footprints', in one numbering: node i < sheetNodes is the sheet's.
struct Nodes {
  std::vector<Vec3> at;
  int sheetNodes = 0;
  bool footprint(int n) const { return n >= sheetNodes; }
};

// The footprints that lie close together, and the sheet's quads to mesh again round them: one gap.
struct Gap {
  std::vector<int> footprintQuads;  // into FootprintQuads::quads
  std::vector<int> sheetQuads;      // into the sheet's quads
};

// The footprint's quads joined by nodes into feet. [out] feet: per quad, its foot's root. Returns root -> its quads.
std::map<int, std::vector<int>> feetOf(const FootprintQuads& footprint, UnionFind& feet) {
  std::map<int, int> quadOfNode;
  for (int q = 0; q < static_cast<int>(footprint.quads.size()); ++q)
    for (int n : footprint.quads[q])
      if (const auto [it, added] = quadOfNode.emplace(n, q); !added) feet.unite(it->second, q);
  std::map<int, std::vector<int>> footQuads;
  for (int q = 0; q < static_cast<int>(footprint.quads.size()); ++q) footQuads[feet.find(q)].push_back(q);
  return footQuads;
}

// A foot's quads as triangles, in a tree.
TriangleTree footTree(const FootprintQuads& footprint, const std::vector<int>& quads) {
  std::vector<Triangle> t;
  for (int q : quads)
    for (const Triangle& tri : triangles(footprint.nodes, footprint.quads[q])) t.push_back(tri);
  return TriangleTree(std::move(t));
}

// The footprint quads joined by nodes into feet, and the sheet's quads within the band of each; feet whose bands
// share a quad are one gap. [in] sheet, footprint, size; [in] band: how near. Returns the gaps; `removed` flags the
// sheet's quads in one.
std::vector<Gap> gapsRoundFeet(const QuadMesh& sheet, const FootprintQuads& footprint, double size, double band,
                               std::vector<char>& removed) {
  UnionFind feet(footprint.quads.size());
  std::map<int, std::vector<int>> footQuads = feetOf(footprint, feet);
  std::vector<int> roots;
  std::vector<TriangleTree> trees;
  for (const auto& [root, quads] : footQuads) roots.push_back(root), trees.push_back(footTree(footprint, quads));
  for (std::size_t f = 0; f < trees.size(); ++f)  // feet on both sides of the sheet at one place
    for (int q : footQuads[roots[f]])
      for (int n : footprint.quads[q])
        for (std::size_t g = 0; g < trees.size(); ++g)
          if (g != f && trees[g].anyWithin(footprint.nodes[n], kOverlap * size)) {
            const Vec3& p = footprint.nodes[n];
            std::ostringstream msg;
            msg << "junction: walls stand on both sides of a sheet near (" << p.x() << ", " << p.y() << ", " << p.z()
                << ") with feet that are not one another's node for node (ribs crossing obliquely, or meshed "
                   "unlike), which is not meshed yet";
            throw geometryError(msg.str());
          }
  removed.assign(sheet.quads.size(), 0);
  std::vector<int> claimedBy(sheet.quads.size(), -1);
  for (std::size_t q = 0; q < sheet.quads.size(); ++q) {
    Vec3 centre = Vec3::Zero();
    for (int n : sheet.quads[q]) centre += 0.25 * sheet.nodes[n];
    for (std::size_t f = 0; f < trees.size(); ++f) {
      bool near = trees[f].anyWithin(centre, band);
      for (int n : sheet.quads[q]) near = near || trees[f].anyWithin(sheet.nodes[n], band);
      if (!near) continue;
      if (claimedBy[q] >= 0) feet.unite(claimedBy[q], roots[f]);
      claimedBy[q] = roots[f], removed[q] = 1;
    }
  }
  std::map<int, Gap> gaps;
  for (int q = 0; q < static_cast<int>(footprint.quads.size()); ++q) gaps[feet.find(q)].footprintQuads.push_back(q);
  for (int q = 0; q < static_cast<int>(sheet.quads.size()); ++q)
    if (claimedBy[q] >= 0) gaps[feet.find(claimedBy[q])].sheetQuads.push_back(q);
  std::vector<Gap> out;
  for (auto& [root, gap] : gaps) {
    if (gap.sheetQuads.empty()) throw geometryError("junction: a wall's foot does not lie on the sheet it stands on");
    out.push_back(std::move(gap));
  }
  return out;
}

// The gap unfolded onto the plane: the sheet's quads taken out, on a diagonal, by the least-squares conformal map
// (surface_map.hpp), so that a gap on a curved sheet or across a bend is meshed in 2D as a flat one is. 2D
// coordinates of the points near the gap, 2D points back on it, and the sheet's side seen counter-clockwise in 2D.
class GapMap {
 public:
  // Throws geometryError if the quads do not unfold (not one patch, or folded).
  GapMap(const QuadMesh& sheet, const Gap& gap) {
    std::map<int, int> local;  // the sheet's node -> the map's point
    std::vector<Vec3> points;
    std::vector<std::array<int, 3>> triangles;
    auto point = [&](int n) {
      const auto [it, added] = local.emplace(n, static_cast<int>(points.size()));
      if (added) points.push_back(sheet.nodes[n]);
      return it->second;
    };
    for (int q : gap.sheetQuads) {
      const Quad& c = sheet.quads[q];
      triangles.push_back({point(c[0]), point(c[1]), point(c[2])});
      triangles.push_back({point(c[0]), point(c[2]), point(c[3])});
    }
    map_ = unfoldConformally(points, triangles);
    if (map_.empty()) map_ = unfoldRing(std::move(points), std::move(triangles));  // walls all round a boss
    if (map_.empty()) {
      const Vec3& p = sheet.nodes[sheet.quads[gap.sheetQuads.front()][0]];
      std::ostringstream msg;
      msg << "junction: the sheet round a wall's foot near (" << p.x() << ", " << p.y() << ", " << p.z()
          << ") does not unfold onto a plane";
      throw geometryError(msg.str());
    }
    locator_ = std::make_unique<MapLocator>(map_);
    std::vector<Vec3> lo, hi;  // the triangles' boxes, in a grid of cells as large as the median triangle
    std::vector<double> extent;
    for (const auto& t : map_.triangles) {
      const Vec3 &a = map_.points[t[0]], &b = map_.points[t[1]], &c = map_.points[t[2]];
      lo.push_back(a.cwiseMin(b).cwiseMin(c)), hi.push_back(a.cwiseMax(b).cwiseMax(c));
      extent.push_back((hi.back() - lo.back()).maxCoeff());
    }
    triangles_ = BoxGrid(median(extent));
    for (std::size_t t = 0; t < lo.size(); ++t) triangles_.insert(static_cast<int>(t), lo[t], hi[t]);
  }
  GapMap(const GapMap&) = delete;  // locator_ refers to map_
  GapMap& operator=(const GapMap&) = delete;

  // The point p of the nearest triangle's plane, in 2D (its affine weights there, not clamped to it).
  Eigen::Vector2d at(const Vec3& p) const {
    const auto& t = map_.triangles[nearest(p)];
    const Vec3 &a = map_.points[t[0]], &b = map_.points[t[1]], &c = map_.points[t[2]];
    Eigen::Matrix<double, 3, 2> e;
    e << b - a, c - a;
    const Eigen::Vector2d st = (e.transpose() * e).ldlt().solve(e.transpose() * (p - a));
    return map_.uv[t[0]] + st.x() * (map_.uv[t[1]] - map_.uv[t[0]]) + st.y() * (map_.uv[t[2]] - map_.uv[t[0]]);
  }
  // at(p) as a point of the plane z = 0, for the 3D segment and quad tools.
  Vec3 flat(const Vec3& p) const {
    const Eigen::Vector2d q = at(p);
    return {q.x(), q.y(), 0};
  }
  // Lengths in the map near p per length on the sheet: about 1 on a disc's map (scaled to the sheet's area), from
  // about e^-M to e^M times the mean round a ring's (the annulus of modulus M).
  double scale(const Vec3& p) const {
    const auto& t = map_.triangles[nearest(p)];
    const double onSheet = (map_.points[t[1]] - map_.points[t[0]]).cross(map_.points[t[2]] - map_.points[t[0]]).norm();
    const Eigen::Vector2d u = map_.uv[t[1]] - map_.uv[t[0]], v = map_.uv[t[2]] - map_.uv[t[0]];
    return std::sqrt(std::abs(u.x() * v.y() - u.y() * v.x()) / onSheet);
  }
  // The gap's point at q (on the sheet's quads; put it on the chordal surface after).
  Vec3 lift(const Eigen::Vector2d& q) const { return (*locator_)(q); }
  // The sheet's normal near p, on the side from which the map is counter-clockwise.
  Vec3 normal(const Vec3& p) const {
    const auto& t = map_.triangles[nearest(p)];
    const Vec3 &a = map_.points[t[0]], &b = map_.points[t[1]], &c = map_.points[t[2]];
    return (b - a).cross(c - a).normalized();
  }

 private:
  // The triangle nearest to p, the first of those as near (the first triangle if p is not finite).
  int nearest(const Vec3& p) const {
    const int t = triangles_.nearest(p, [&](int id, double) {
      const auto& c = map_.triangles[id];
      return squaredDistanceToTriangle(p, {map_.points[c[0]], map_.points[c[1]], map_.points[c[2]]});
    });
    return std::max(t, 0);
  }
  SurfaceMap map_;
  std::unique_ptr<MapLocator> locator_;
  BoxGrid triangles_{1.0};  // map_'s triangles by their boxes
};

// The quad turned counter-clockwise in the gap's map.
Quad counterClockwise(const Nodes& nodes, const GapMap& map, Quad q) {
  std::vector<Eigen::Vector2d> p;
  for (int n : q) p.push_back(map.at(nodes.at[n]));
  if (polygonArea(p) < 0) std::reverse(q.begin(), q.end());
  return q;
}

// The gap's boundary edges, the gap on their left: the taken-out quads' edges shared with a quad kept (fixed),
// the footprints' edges not on the sheet's rim (fixed), and the sheet's rim between them (free: divided anew).
struct GapEdges {
  std::vector<Edge> edges;
  std::set<Edge> free;  // on the sheet's rim
};

// The rim edges of the taken-out quads, cut where a footprint reaches the rim: its nodes on an edge split it, and
// the pieces the footprint covers are left out; a rim node where a footprint node is (a sheet's grid line through
// the foot's corner) is that node. A node of a foot's edge along the rim splits the rim edge nearest to it also
// beyond the tolerance (the sheet's rim and the foot's can lie apart by more where the rim turns: round a boss, its
// chords cut inside the foot's circle). [in] rim: those edges; [in] footNodes: the footprint's boundary nodes; [in]
// alongRim: those of its edges along the rim; [in] covered: whether a point (a piece's middle) lies under the
// footprint.
std::vector<Edge> rimPieces(const Nodes& nodes, const std::vector<Edge>& rim, const std::set<int>& footNodes,
                            const std::set<int>& alongRim, double tolerance,
                            const std::function<bool(const Vec3&)>& covered) {
  const double same = kCoincide * tolerance;
  auto footNodeAt = [&](int n) {
    for (int f : footNodes)
      if ((nodes.at[f] - nodes.at[n]).norm() <= same) return f;
    return n;
  };
  std::map<int, std::size_t> nearestEdge;  // per node of a foot's edge along the rim, the rim edge nearest to it
  for (int f : alongRim) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < rim.size(); ++e)
      if (const double d = toSegment(nodes.at[f], nodes.at[rim[e].first], nodes.at[rim[e].second]).first; d < best)
        best = d, nearestEdge[f] = e;
  }
  std::vector<Edge> pieces;
  for (std::size_t e = 0; e < rim.size(); ++e) {
    const int a = footNodeAt(rim[e].first), b = footNodeAt(rim[e].second);
    std::vector<std::pair<double, int>> along{{0.0, a}, {1.0, b}};
    for (int f : footNodes)
      if (const auto [d, t] = toSegment(nodes.at[f], nodes.at[a], nodes.at[b]);
          (d <= tolerance || (nearestEdge.count(f) && nearestEdge.at(f) == e)) && f != a && f != b && t > 0 && t < 1)
        along.emplace_back(t, f);
    std::sort(along.begin(), along.end());
    for (std::size_t k = 0; k + 1 < along.size(); ++k) {
      const int u = along[k].second, v = along[k + 1].second;
      if (u != v && !covered(0.5 * (nodes.at[u] + nodes.at[v]))) pieces.emplace_back(u, v);
    }
  }
  return pieces;
}

// How many of the sheet's quads have each (undirected) edge.
using EdgeUses = std::map<std::pair<int, int>, int>;

EdgeUses edgeUses(const QuadMesh& sheet) {
  EdgeUses uses;
  for (const Quad& q : sheet.quads)
    for (int c = 0; c < 4; ++c) ++uses[std::minmax(q[c], q[(c + 1) % 4])];
  return uses;
}

GapEdges gapEdges(const Nodes& nodes, const GapMap& map, const QuadMesh& sheet, const EdgeUses& quadsOfEdge,
                  const FootprintQuads& footprint, const Gap& gap, double size) {
  std::set<Edge> inGap;
  for (int q : gap.sheetQuads) {
    const Quad c = counterClockwise(nodes, map, sheet.quads[q]);
    for (int k = 0; k < 4; ++k) inGap.emplace(c[k], c[(k + 1) % 4]);
  }
  GapEdges g;
  std::vector<Edge> rim;
  for (const auto& [a, b] : inGap) {
    if (inGap.count({b, a})) continue;
    if (quadsOfEdge.at(std::minmax(a, b)) > 1)
      g.edges.emplace_back(a, b);  // shared with a quad kept
    else
      rim.emplace_back(a, b);
  }
  std::set<Edge> inFoot;
  const int offset = nodes.sheetNodes;
  for (int q : gap.footprintQuads) {
    Quad c = footprint.quads[q];
    for (int& n : c) n += offset;
    c = counterClockwise(nodes, map, c);
    for (int k = 0; k < 4; ++k) inFoot.emplace(c[k], c[(k + 1) % 4]);
  }
  const double tolerance = kOnRim * size;
  auto onRim = [&](const Vec3& p) {  // in the map: a foot running along the rim round a bend lies on it there too
    const Vec3 at = map.flat(p);
    for (const auto& [a, b] : rim)
      if (toSegment(at, map.flat(nodes.at[a]), map.flat(nodes.at[b])).first <= tolerance * map.scale(p)) return true;
    return false;
  };
  std::vector<Edge> footRim;
  std::set<int> footNodes;
  for (const auto& [a, b] : inFoot) {
    if (inFoot.count({b, a})) continue;
    footNodes.insert(a), footNodes.insert(b);
    if (onRim(nodes.at[a]) && onRim(nodes.at[b]) && onRim(0.5 * (nodes.at[a] + nodes.at[b])))
      footRim.emplace_back(a, b);
    else
      g.edges.emplace_back(b, a);  // the gap is outside the footprint
  }
  std::vector<std::vector<Eigen::Vector2d>> footInPlane;  // the footprints' quads in the map
  for (int q : gap.footprintQuads) {
    footInPlane.emplace_back();
    for (int n : footprint.quads[q]) footInPlane.back().push_back(map.at(nodes.at[n + offset]));
  }
  std::map<int, int> footRimEdges;  // per node of the footprints' edges along the rim, how many such edges it ends
  for (const auto& [a, b] : footRim) ++footRimEdges[a], ++footRimEdges[b];
  // in the map: along a footprint's rim edge, not beyond its ends (but round a node between two, where the rim turns),
  // or in its quad
  auto covered = [&](const Vec3& p) {
    const Vec3 at = map.flat(p);
    for (const auto& [a, b] : footRim)
      if (const auto [d, t] = toSegment(at, map.flat(nodes.at[a]), map.flat(nodes.at[b]));
          d <= tolerance * map.scale(p) && t > 0 && t < 1)
        return true;
    for (const auto& [n, edges] : footRimEdges)
      if (edges > 1 && (at - map.flat(nodes.at[n])).norm() <= tolerance * map.scale(p)) return true;
    return std::any_of(footInPlane.begin(), footInPlane.end(),
                       [&](const auto& q) { return insidePolygon(q, at.head<2>()); });
  };
  std::set<int> alongRim;
  for (const auto& [a, b] : footRim) alongRim.insert(a), alongRim.insert(b);
  for (const Edge& e : rimPieces(nodes, rim, footNodes, alongRim, tolerance, covered))
    g.edges.push_back(e), g.free.insert(e);
  return g;
}

// The edges chained into closed loops. Throws if a node starts two edges (the gap pinched at a node).
std::vector<Loop> chainLoops(const std::vector<Edge>& edges) {
  std::map<int, int> next;
  for (const auto& [a, b] : edges)
    if (!next.emplace(a, b).second)
      throw geometryError(
          "junction: the gap round a wall's foot is pinched at a node (a foot touching another "
          "or the sheet's rim at a point)");
  std::vector<Loop> loops;
  std::set<int> done;
  for (const auto& [start, unused] : next) {
    if (done.count(start)) continue;
    Loop loop;
    for (int n = start; !done.count(n);) {
      done.insert(n), loop.push_back(n);
      const auto it = next.find(n);
      if (it == next.end()) throw geometryError("junction: the gap round a wall's foot is not closed");
      n = it->second;
    }
    if (loop.front() != next.at(loop.back()))
      throw geometryError("junction: the gap round a wall's foot is not closed");
    loops.push_back(std::move(loop));
  }
  return loops;
}

// A free rim node (none of a kept quad's, none of a footprint's) this near a footprint node beside it is left out:
// the rim edge between them would be tiny.
void dropTinyRimEdges(const Nodes& nodes, const std::set<Edge>& free, double size, std::vector<Loop>& loops) {
  for (Loop& loop : loops) {
    for (std::size_t k = 0; loop.size() > 4 && k < loop.size(); ++k) {
      const int prev = loop[(k + loop.size() - 1) % loop.size()], n = loop[k], next = loop[(k + 1) % loop.size()];
      if (nodes.footprint(n) || !free.count({prev, n}) || !free.count({n, next})) continue;
      const bool tiny = (nodes.footprint(prev) && (nodes.at[n] - nodes.at[prev]).norm() < kTinyEdge * size) ||
                        (nodes.footprint(next) && (nodes.at[n] - nodes.at[next]).norm() < kTinyEdge * size);
      if (tiny) loop.erase(loop.begin() + static_cast<long>(k)), --k;
    }
  }
}

// One planar surface of the gap: its outer loop, then its holes.
using Surface = std::vector<Loop>;

std::vector<Eigen::Vector2d> inPlane(const Nodes& nodes, const GapMap& map, const Loop& loop) {
  std::vector<Eigen::Vector2d> p;
  for (int n : loop) p.push_back(map.at(nodes.at[n]));
  return p;
}

// The loops sorted into surfaces: counter-clockwise ones are outer loops (the gap on the left), each clockwise one a
// hole of the smallest outer loop round it.
std::vector<Surface> surfacesOf(const Nodes& nodes, const GapMap& map, const std::vector<Loop>& loops) {
  std::vector<std::vector<Eigen::Vector2d>> flat;
  for (const Loop& loop : loops) flat.push_back(inPlane(nodes, map, loop));
  const auto regions = loopRegions(flat);
  if (!regions) throw geometryError("junction: a loop of the gap round a wall's foot lies outside it");
  std::vector<Surface> surfaces;
  for (const std::vector<std::size_t>& region : *regions) {
    surfaces.emplace_back();
    for (std::size_t k : region) surfaces.back().push_back(loops[k]);
  }
  return surfaces;
}

// The sheet's quads, the ones taken out into gaps flagged; a strip of kept quads halved (quad_strips) adds quads.
struct KeptQuads {
  std::vector<Quad> quads;
  std::vector<char> removed;
};

// All quads need an even number of boundary edges: where a surface has an odd one, its longest free rim edge is
// halved (a node appended to `nodes`); with none (a gap inside the sheet round feet whose nodes another wall's mesh
// fixed), a fixed edge of the kept quads is, and the strip of kept quads from it to the sheet's rim with it (the
// shortest such strip). Throws if there is neither. [in,out] nodes; [in] free; [in,out] surfaces, kept.
void evenBoundaries(Nodes& nodes, const std::set<Edge>& free, std::vector<Surface>& surfaces, KeptQuads& kept) {
  for (Surface& s : surfaces) {
    std::size_t edges = 0;
    for (const Loop& loop : s) edges += loop.size();
    if (edges % 2 == 0) continue;
    double longest = 0;
    Loop* in = nullptr;
    std::size_t at = 0;
    for (Loop& loop : s)
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int a = loop[k], b = loop[(k + 1) % loop.size()];
        if (const double l = (nodes.at[a] - nodes.at[b]).norm(); free.count({a, b}) && l > longest)
          longest = l, in = &loop, at = k;
      }
    QuadStrip strip;
    const QuadsOfEdges on = in ? QuadsOfEdges{} : quadsOfEdges(kept.quads);
    if (!in)
      for (Loop& loop : s)
        for (std::size_t k = 0; k < loop.size(); ++k) {
          const int a = loop[k], b = loop[(k + 1) % loop.size()];
          if (nodes.footprint(a) || nodes.footprint(b)) continue;
          QuadStrip found = stripToRim(kept.quads, on, kept.removed, a, b);
          if (!found.empty() && (strip.empty() || found.size() < strip.size()))
            strip = std::move(found), in = &loop, at = k;
        }
    if (!in)
      throw geometryError("junction: the gap round a wall's foot has an odd number of fixed edges (no quad mesh)");
    const int a = (*in)[at], b = (*in)[(at + 1) % in->size()];
    nodes.at.push_back(0.5 * (nodes.at[a] + nodes.at[b]));
    const int middle = static_cast<int>(nodes.at.size()) - 1;
    in->insert(in->begin() + static_cast<long>(at) + 1, middle);
    if (!strip.empty()) halveStrip(kept.quads, nodes.at, strip, middle), kept.removed.resize(kept.quads.size(), 0);
  }
}

// The surfaces as Gmsh geometry: a point per node (tag: the node + 1, mesh size spacing[node]), a line of two nodes
// per boundary edge. [in] at, spacing, surfaces. Returns the nodes used.
std::set<int> addGapGeometry(const std::vector<Eigen::Vector2d>& at, const std::vector<double>& spacing,
                             const std::vector<Surface>& surfaces) {
  std::set<int> used;
  for (const Surface& s : surfaces)
    for (const Loop& loop : s) used.insert(loop.begin(), loop.end());
  for (int n : used) gmsh::model::geo::addPoint(at[n].x(), at[n].y(), 0, spacing[n], n + 1);
  std::vector<int> lines;
  for (const Surface& s : surfaces) {
    std::vector<int> loops;
    for (const Loop& loop : s) {
      std::vector<int> curve;
      for (std::size_t k = 0; k < loop.size(); ++k)
        curve.push_back(gmsh::model::geo::addLine(loop[k] + 1, loop[(k + 1) % loop.size()] + 1));
      lines.insert(lines.end(), curve.begin(), curve.end());
      loops.push_back(gmsh::model::geo::addCurveLoop(curve));
    }
    gmsh::model::geo::addPlaneSurface(loops);
  }
  gmsh::model::geo::synchronize();
  for (int l : lines) gmsh::model::mesh::setTransfiniteCurve(l, 2);
  return used;
}

// Gmsh's quads in the plane, its leftover triangles paired (quad_completion) or counted as holes; the first
// at.size() nodes the given points. [in] at; [in] used: the nodes that are Gmsh's points.
QuadMesh collectGapQuads(const std::vector<Eigen::Vector2d>& at, const std::set<int>& used) {
  QuadMesh q;
  std::map<std::size_t, int> index;  // Gmsh's node tag -> ours
  for (int n : used) {
    std::vector<std::size_t> tags;
    std::vector<double> coord, param;
    gmsh::model::mesh::getNodes(tags, coord, param, 0, n + 1);
    if (tags.size() != 1) throw internalError("Gmsh lost a point of the gap");
    index[tags[0]] = n;
  }
  for (const Eigen::Vector2d& p : at) q.nodes.emplace_back(p.x(), p.y(), 0);
  std::vector<std::size_t> all;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(all, coord, param, -1, -1, true, false);
  for (std::size_t k = 0; k < all.size(); ++k)
    if (index.emplace(all[k], static_cast<int>(q.nodes.size())).second)
      q.nodes.emplace_back(coord[3 * k], coord[3 * k + 1], 0);
  std::vector<std::size_t> tags, nodeTags;  // Gmsh 4.8 leaves the vectors as they were if there are none: new ones
  gmsh::model::mesh::getElementsByType(3, tags, nodeTags);
  for (std::size_t e = 0; e < tags.size(); ++e)
    q.quads.push_back({index.at(nodeTags[4 * e]), index.at(nodeTags[4 * e + 1]), index.at(nodeTags[4 * e + 2]),
                       index.at(nodeTags[4 * e + 3])});
  std::vector<std::size_t> triangleTags, triangleNodes;
  gmsh::model::mesh::getElementsByType(2, triangleTags, triangleNodes);
  std::vector<std::array<int, 3>> left;
  for (std::size_t e = 0; e < triangleTags.size(); ++e)
    left.push_back(
        {index.at(triangleNodes[3 * e]), index.at(triangleNodes[3 * e + 1]), index.at(triangleNodes[3 * e + 2])});
  q.pairedTriangles = pairTriangles(q.quads, left, kMaxStrip).paired;
  q.holes = left.size();
  return q;
}

// The mesh size at each node of the loops: the mean length of its two edges.
std::vector<double> loopSpacing(const std::vector<Vec3>& at, const std::vector<Surface>& surfaces) {
  std::vector<double> sum(at.size(), 0), count(at.size(), 0);
  for (const Surface& s : surfaces)
    for (const Loop& loop : s)
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int a = loop[k], b = loop[(k + 1) % loop.size()];
        const double l = (at[a] - at[b]).norm();
        sum[a] += l, sum[b] += l, count[a] += 1, count[b] += 1;
      }
  for (std::size_t n = 0; n < at.size(); ++n) sum[n] = count[n] > 0 ? sum[n] / count[n] : 1;
  return sum;
}

// A gap's Gmsh run as bytes (gapQuadsRun's request). [in] at, spacing, surfaces, algorithm: as startGapQuads's.
std::string gapRequest(const std::vector<Eigen::Vector2d>& at, const std::vector<double>& spacing,
                       const std::vector<Surface>& surfaces, int algorithm) {
  std::vector<double> xy;  // Eigen's vectors are not trivially copyable: their coordinates are
  for (const Eigen::Vector2d& p : at) xy.push_back(p.x()), xy.push_back(p.y());
  ByteWriter w;
  w.put(algorithm), w.put(xy), w.put(spacing), w.put(surfaces);
  return w.bytes();
}

// Gmsh meshes the surfaces with quads, every boundary node fixed: Blossom's recombination of the triangles of 2D
// algorithm `algorithm`, in Gmsh's open session. [in] request: gapRequest's bytes. Returns the quads as bytes
// (toBytes).
std::string gapQuadsRun(const std::string& request) {
  int algorithm = 0;
  std::vector<double> xy, spacing;
  std::vector<Surface> surfaces;
  ByteReader r(request);
  r.get(algorithm), r.get(xy), r.get(spacing), r.get(surfaces);
  std::vector<Eigen::Vector2d> at;
  for (std::size_t k = 0; k + 1 < xy.size(); k += 2) at.emplace_back(xy[k], xy[k + 1]);
  return namingGmshErrors([&] {
    gmsh::model::add("gap");
    const std::set<int> used = addGapGeometry(at, spacing, surfaces);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);  // Blossom (the full-quad ones refine the lines)
    gmsh::option::setNumber("Mesh.Smoothing", 5);
    gmsh::option::setNumber("Mesh.RandomFactor", 1e-9);
    gmsh::option::setNumber("Mesh.Algorithm", algorithm);
    gmsh::model::mesh::generate(2);
    return toBytes(collectGapQuads(at, used));
  });
}

// A gap's Gmsh run, started (startGapQuads): the child, and which of the given points are its points.
struct GapRun {
  StartedChild child;
  std::vector<int> points;  // Gmsh's points in order (the surfaces' nodes, ascending): into the given points
  std::size_t given = 0;    // how many points were given
};

// gapQuadsRun in a child process started here (finishGapQuads waits for its quads), so that a gap's tries run side by
// side: the fork server's child, or this process's. Gmsh gets the surfaces' nodes alone, numbered in their order: its
// quads are the same whatever the numbers of the nodes (and the nodes before them). [in] server: may be null; [in] at:
// 2D points; [in] spacing: the mesh size at each; [in] surfaces: loops of them; [in] algorithm. Returns the run.
GapRun startGapQuads(ForkServer* server, const std::vector<Eigen::Vector2d>& at, const std::vector<double>& spacing,
                     const std::vector<Surface>& surfaces, int algorithm) {
  std::set<int> used;
  for (const Surface& s : surfaces)
    for (const Loop& loop : s) used.insert(loop.begin(), loop.end());
  GapRun run{{}, std::vector<int>(used.begin(), used.end()), at.size()};
  std::vector<int> local(at.size(), -1);
  std::vector<Eigen::Vector2d> points;
  std::vector<double> sizes;
  for (int n : run.points)
    local[n] = static_cast<int>(points.size()), points.push_back(at[n]), sizes.push_back(spacing[n]);
  std::vector<Surface> renumbered = surfaces;
  for (Surface& s : renumbered)
    for (Loop& loop : s)
      for (int& n : loop) n = local[n];
  run.child =
      startRun(server, &gapQuadsRun, gapRequest(points, sizes, renumbered, algorithm), kGmshSeconds, inGmshSession);
  return run;
}

// [in,out] run: a started startGapQuads, waited for. Returns the quads in the plane, their first nodes the given
// points (the others at 0), then Gmsh's new ones. Throws geometryError if Gmsh failed or left triangles.
QuadMesh finishGapQuads(GapRun& run) {
  const ChildResult done = waitForChild(run.child);
  if (!done.ok)
    throw geometryError("junction: the gap round a wall's foot was not meshed (Gmsh: " + done.failure + ")");
  QuadMesh q = fromBytes(done.output);
  if (q.holes > 0)
    throw geometryError("junction: Gmsh left " + std::to_string(q.holes) + " triangles in the gap round a wall's foot");
  const std::size_t points = run.points.size();
  std::vector<Vec3> nodes(run.given, Vec3::Zero());
  for (std::size_t k = 0; k < points; ++k) nodes[run.points[k]] = q.nodes[k];
  nodes.insert(nodes.end(), q.nodes.begin() + static_cast<long>(points), q.nodes.end());
  for (Quad& quad : q.quads)
    for (int& n : quad)
      n = static_cast<std::size_t>(n) < points ? run.points[n] : static_cast<int>(run.given + n - points);
  q.nodes = std::move(nodes);
  return q;
}

// Checks that the gap's quads fill it: their boundary is the gap's (every edge of it once, no other).
void checkGapQuads(const QuadMesh& q, const std::vector<Surface>& surfaces) {
  std::map<std::pair<int, int>, int> uses;
  for (const Quad& quad : q.quads)
    for (int c = 0; c < 4; ++c) ++uses[std::minmax(quad[c], quad[(c + 1) % 4])];
  std::size_t boundary = 0;
  for (const Surface& s : surfaces)
    for (const Loop& loop : s)
      for (std::size_t k = 0; k < loop.size(); ++k, ++boundary)
        if (uses[std::minmax(loop[k], loop[(k + 1) % loop.size()])] != 1)
          throw geometryError("junction: the gap's quads do not end on its boundary");
  std::size_t once = 0;
  for (const auto& [edge, n] : uses) once += n == 1;
  if (once != boundary) throw geometryError("junction: the gap's quads have a boundary of their own");
}

// The gap's quads on the sheet: its boundary nodes where they are, the others lifted from the plane onto the chordal
// surface. [in] at: every node so far (the first at.size() of the quads'); [in] map, chordal; [in,out] q: Gmsh's
// quads in the map, then on the sheet.
void liftGap(const std::vector<Vec3>& at, const GapMap& map, const ChordalLocator& chordal, QuadMesh& q) {
  for (std::size_t n = 0; n < q.nodes.size(); ++n)
    q.nodes[n] = n < at.size() ? at[n] : chordal.locate(map.lift({q.nodes[n].x(), q.nodes[n].y()})).point;
}

// A gap quad's scaled Jacobian in the plane z = 0: negative for a clockwise one (turned over) or a bow tie.
// [in] nodes, quad.
double quadInPlane(const std::vector<Vec3>& nodes, const Quad& quad) {
  return quadScaledJacobian({nodes[quad[0]], nodes[quad[1]], nodes[quad[2]], nodes[quad[3]]}, Vec3::UnitZ());
}

// A gap quad's scaled Jacobian on the sheet, turned the map's way. [in] map; [in] nodes, quad.
double onSheet(const GapMap& map, const std::vector<Vec3>& nodes, const Quad& quad) {
  const std::array<Vec3, 4> c{nodes[quad[0]], nodes[quad[1]], nodes[quad[2]], nodes[quad[3]]};
  return quadScaledJacobian(c, map.normal(0.25 * (c[0] + c[1] + c[2] + c[3])));
}

// The gap's quads on the sheet (liftGap's) smoothed (quad_smoothing; the boundary stays).
// [in] map, chordal; [in,out] q. Returns the worst quad's scaled Jacobian, turned the map's way (<= 0: one is folded).
double smoothGap(const GapMap& map, const ChordalLocator& chordal, QuadMesh& q) {
  QuadMesh local;  // the gap's nodes only
  std::map<int, int> index;
  std::vector<int> of;
  for (const Quad& quad : q.quads) {
    Quad l;
    for (int c = 0; c < 4; ++c) {
      const auto [it, added] = index.emplace(quad[c], static_cast<int>(of.size()));
      if (added) of.push_back(quad[c]), local.nodes.push_back(q.nodes[quad[c]]);
      l[c] = it->second;
    }
    local.quads.push_back(l);
  }
  smoothQuadMesh(local, chordal, kSmoothing, false);
  for (std::size_t l = 0; l < of.size(); ++l) q.nodes[of[l]] = local.nodes[l];
  double worst = 1;
  for (const Quad& quad : q.quads) worst = std::min(worst, onSheet(map, q.nodes, quad));
  return worst;
}

// The angle from u counter-clockwise to v, in [0, 2 pi).
double ccwAngle(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  const double a = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  return a < 0 ? a + 2 * M_PI : a;
}

// Whether the segments pq and rs cross (touching at an end is not crossing).
bool segmentsCross(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r,
                   const Eigen::Vector2d& s) {
  auto side = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    const Eigen::Vector2d u = b - a, v = c - a;
    return u.x() * v.y() - u.y() * v.x();
  };
  return side(p, q, r) * side(p, q, s) < 0 && side(r, s, p) * side(r, s, q) < 0;
}

// The gap with a quad cut off each acute corner of its boundary: Gmsh's triangles there span the wedge from side to
// side (its first edges are shorter than the mesh size), and the triangle at the tip, one edge inside, pairs with the
// next one along a side into a quad with three boundary nodes in a line (a 180-degree corner: folded, every try).
struct WedgeCut {
  std::vector<Eigen::Vector2d> at;  // the points given, then the new corners
  std::vector<double> spacing;      // per new corner, the mean length of its two edges
  std::vector<Surface> surfaces;    // each acute corner replaced in its loop by its quad's new corner
  std::vector<Quad> quads;          // the quads cut off, counter-clockwise
};

// How good the quad (prev, c, next, p) cut off the corner c is and what it leaves: the least sine of its corners at
// prev, next and p and of the gap's corners left at prev and next (a reflex one counts as good), at most the ratio of
// its new edges' lengths to h (or of h to them). [in] before, prev, c, next, after: the loop's points round c;
// [in] p, h. Returns it, <= 0 if the quad folds.
double wedgeQuality(const std::array<Eigen::Vector2d, 5>& round, const Eigen::Vector2d& p, double h) {
  const auto& [before, prev, c, next, after] = round;
  const double inQuad[] = {ccwAngle(c - prev, p - prev), ccwAngle(p - next, c - next), ccwAngle(prev - p, next - p)};
  double q = 1;
  for (double a : inQuad) q = a < M_PI ? std::min(q, std::sin(a)) : -1;
  for (double a : {ccwAngle(p - prev, before - prev), ccwAngle(after - next, p - next)})
    q = std::min(q, a < M_PI ? std::sin(a) : 1.0);
  for (double l : {(p - prev).norm(), (p - next).norm()}) q = std::min(q, std::min(l / h, h / l));
  return q;
}

// The best fourth corner of the quad cut off the acute corner at loop[k] (wedgeQuality, over directions inside the
// corner and distances up to twice its edges' mean length h). [in] at, loop, k; [out] h. Returns it and its quality.
std::pair<Eigen::Vector2d, double> wedgeCorner(const std::vector<Eigen::Vector2d>& at, const Loop& loop, std::size_t k,
                                               double& h) {
  const std::size_t m = loop.size();
  std::array<Eigen::Vector2d, 5> round;
  for (std::size_t i = 0; i < 5; ++i) round[i] = at[loop[(k + m + i - 2) % m]];
  const Eigen::Vector2d &prev = round[1], &c = round[2], &next = round[3];
  h = 0.5 * ((prev - c).norm() + (next - c).norm());
  const double opening = ccwAngle(next - c, prev - c), from = std::atan2((next - c).y(), (next - c).x());
  std::pair<Eigen::Vector2d, double> best{c, -1};
  for (int i = 1; i < kWedgeSteps; ++i)
    for (int j = 1; j <= kWedgeSteps; ++j) {
      const double a = from + opening * i / kWedgeSteps, r = 2 * h * j / kWedgeSteps;
      const Eigen::Vector2d p = c + r * Eigen::Vector2d(std::cos(a), std::sin(a));
      if (const double q = wedgeQuality(round, p, h); q > best.second) best = {p, q};
    }
  return best;
}

// Whether the new edges prev-p and p-next cross none of the surface's boundary edges.
bool clearOfBoundary(const std::vector<Eigen::Vector2d>& at, const Surface& s, int prev, int next,
                     const Eigen::Vector2d& p) {
  for (const Loop& loop : s)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d &u = at[loop[k]], &v = at[loop[(k + 1) % loop.size()]];
      if (segmentsCross(at[prev], p, u, v) || segmentsCross(p, at[next], u, v)) return false;
    }
  return true;
}

// The gap's acute boundary corners (below kAcute) cut off, each by the best quad (wedgeCorner) that folds nothing;
// a corner next to one cut stays. [in] at: the loops' points in the map; [in] surfaces.
WedgeCut cutAcuteCorners(const std::vector<Eigen::Vector2d>& at, const std::vector<Surface>& surfaces) {
  WedgeCut cut{at, {}, surfaces, {}};
  for (Surface& s : cut.surfaces)
    for (Loop& loop : s) {
      std::set<int> touched;
      for (std::size_t k = 0; loop.size() >= 4 && k < loop.size(); ++k) {
        const int prev = loop[(k + loop.size() - 1) % loop.size()], c = loop[k], next = loop[(k + 1) % loop.size()];
        if (touched.count(prev) || touched.count(c) ||
            ccwAngle(cut.at[next] - cut.at[c], cut.at[prev] - cut.at[c]) >= kAcute)
          continue;
        double h = 0;
        const auto [p, quality] = wedgeCorner(cut.at, loop, k, h);
        if (quality <= 0 || !clearOfBoundary(cut.at, s, prev, next, p)) continue;
        const int added = static_cast<int>(cut.at.size());
        cut.at.push_back(p), cut.spacing.push_back(h), cut.quads.push_back({prev, c, next, added});
        loop[k] = added, touched.insert({prev, next});
      }
    }
  return cut;
}

// The ways of splitting a hexagon (corners h, counter-clockwise) into quads: along each of its three long diagonals
// into two, and round the node `centre` into three, from an even or from an odd corner.
std::vector<std::vector<Quad>> hexagonSplits(const std::array<int, 6>& h, int centre) {
  std::vector<std::vector<Quad>> ways;
  for (int k = 0; k < 3; ++k)
    ways.push_back({{h[k], h[k + 1], h[k + 2], h[k + 3]}, {h[k + 3], h[(k + 4) % 6], h[(k + 5) % 6], h[k]}});
  for (int k = 0; k < 2; ++k)
    ways.push_back({{h[k], h[k + 1], h[k + 2], centre},
                    {h[k + 2], h[k + 3], h[(k + 4) % 6], centre},
                    {h[(k + 4) % 6], h[(k + 5) % 6], h[k], centre}});
  return ways;
}

// The hexagon of the quads a and b sharing the edge from a's corner k to the next (counter-clockwise, b with it the
// other way round).
std::array<int, 6> hexagonOf(const Quad& a, int k, const Quad& b) {
  const int at = static_cast<int>(std::find(b.begin(), b.end(), a[k]) - b.begin());
  return {a[(k + 1) % 4], a[(k + 2) % 4], a[(k + 3) % 4], a[k], b[(at + 1) % 4], b[(at + 2) % 4]};
}

// A quad's quality: its scaled Jacobian in the plane (quadInPlane) or on the sheet (onSheet). [in] nodes, quad.
using QuadQuality = std::function<double(const std::vector<Vec3>& nodes, const Quad& quad)>;

// The worst of the quads by `quality`. [in] quality, nodes, quads.
double worstBy(const QuadQuality& quality, const std::vector<Vec3>& nodes, const std::vector<Quad>& quads) {
  double worst = 1;
  for (const Quad& quad : quads) worst = std::min(worst, quality(nodes, quad));
  return worst;
}

// Quads a (poor) and b (its neighbour) split anew the best way (hexagonSplits), if that is better than both by
// `quality`: a node at the hexagon's centroid added to q's if used. [in,out] q; [in] a, b: indices of its quads;
// [in] k: their edge, from a's corner k; [in] quality. Returns whether they were.
bool splitPairAnew(QuadMesh& q, int a, int b, int k, const QuadQuality& quality) {
  const std::array<int, 6> h = hexagonOf(q.quads[a], k, q.quads[b]);
  Vec3 centroid = Vec3::Zero();
  for (int n : h) centroid += q.nodes[n] / 6;
  q.nodes.push_back(centroid);
  const int centre = static_cast<int>(q.nodes.size()) - 1;
  std::vector<Quad> best;
  double bestWorst = worstBy(quality, q.nodes, {q.quads[a], q.quads[b]});
  for (const std::vector<Quad>& way : hexagonSplits(h, centre))
    if (const double w = worstBy(quality, q.nodes, way); w > bestWorst) best = way, bestWorst = w;
  if (best.size() < 3) q.nodes.pop_back();
  if (best.empty()) return false;
  q.quads[a] = best[0], q.quads[b] = best[1];
  if (best.size() == 3) q.quads.push_back(best[2]);
  return true;
}

// Gmsh's quads of the gap with a poor one (below kFlat by `quality`: in the plane, where Blossom left two triangles in
// an acute corner, paired by quad_completion, three boundary nodes in a line; on the sheet, where the map bent such a
// corner straight) split anew with a neighbour (splitPairAnew) while that makes them better. [in,out] q; [in]
// quality. Returns whether any was.
bool repairPoorQuads(QuadMesh& q, const QuadQuality& quality) {
  bool repaired = false;
  for (std::size_t tries = 0; tries <= q.quads.size(); ++tries) {
    std::map<std::pair<int, int>, std::vector<int>> quadsOf;
    for (int i = 0; i < static_cast<int>(q.quads.size()); ++i)
      for (int c = 0; c < 4; ++c) quadsOf[std::minmax(q.quads[i][c], q.quads[i][(c + 1) % 4])].push_back(i);
    bool split = false;
    for (int i = 0; !split && i < static_cast<int>(q.quads.size()); ++i) {
      if (quality(q.nodes, q.quads[i]) >= kFlat) continue;
      for (int c = 0; !split && c < 4; ++c)
        for (int j : quadsOf[std::minmax(q.quads[i][c], q.quads[i][(c + 1) % 4])])
          if (j != i && !split) split = splitPairAnew(q, i, j, c, quality);
    }
    if (!split) return repaired;
    repaired = true;
  }
  return repaired;
}

// One try at the gap: Gmsh's quads of the surfaces (the wedge quads added), checked to fill the gap, smoothed on the
// sheet; where a quad is then still poor, it and a neighbour split anew on the sheet and smoothed again. [in] at: every
// node so far; [in] map, chordal; [in] surfaces: the gap's; [in] cut: what Gmsh meshes; [in] q: Gmsh's quads
// (finishGapQuads). Returns the quads; [out] worst: the worst's scaled Jacobian (smoothGap). Throws geometryError if
// its quads do not fill the gap.
QuadMesh gapTry(const std::vector<Vec3>& at, const GapMap& map, const ChordalLocator& chordal,
                const std::vector<Surface>& surfaces, const WedgeCut& cut, QuadMesh q, double& worst) {
  q.quads.insert(q.quads.end(), cut.quads.begin(), cut.quads.end());
  repairPoorQuads(q, quadInPlane);
  checkGapQuads(q, surfaces);
  liftGap(at, map, chordal, q);
  worst = smoothGap(map, chordal, q);
  const std::size_t lifted = q.nodes.size();
  if (worst < kFlat &&  // the map bent angles: three boundary nodes nearly in a line on the sheet, not in the plane
      repairPoorQuads(q, [&](const std::vector<Vec3>& nodes, const Quad& quad) { return onSheet(map, nodes, quad); })) {
    for (std::size_t n = lifted; n < q.nodes.size(); ++n) q.nodes[n] = chordal.locate(q.nodes[n]).point;
    checkGapQuads(q, surfaces);
    worst = smoothGap(map, chordal, q);
  }
  return q;
}

// Where along a loop (segment k from its node k to k + 1, plus the share of it) its point nearest to p lies, in 3D.
double nearestAlong(const std::vector<Vec3>& at, const Loop& loop, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity(), along = 0;
  for (std::size_t k = 0; k < loop.size(); ++k)
    if (const auto [d, t] = toSegment(p, at[loop[k]], at[loop[(k + 1) % loop.size()]]); d < best)
      best = d, along = static_cast<double>(k) + t;
  return along;
}

// The point of a loop at a position along it (nearestAlong's).
Vec3 pointAlong(const std::vector<Vec3>& at, const Loop& loop, double along) {
  const std::size_t k = static_cast<std::size_t>(along) % loop.size();
  const double t = along - std::floor(along);
  return (1 - t) * at[loop[k]] + t * at[loop[(k + 1) % loop.size()]];
}

// Where the points of a rim loop nearest to the nodes of a fixed loop round the same ring lie along it (nearestAlong),
// if they go round it once, in order: the two loops run round the ring opposite ways (the gap on the left of each),
// so the points go down the rim loop. [in] at, fixed, rim. Returns them, per fixed node; empty if not so.
std::vector<double> ringPoints(const std::vector<Vec3>& at, const Loop& fixed, const Loop& rim) {
  const double turn = static_cast<double>(rim.size());
  std::vector<double> along;
  for (int b : fixed) along.push_back(nearestAlong(at, rim, at[b]));
  double turned = 0;
  for (std::size_t i = 0; i < along.size(); ++i) {
    const double step = std::fmod(along[i] - along[(i + 1) % along.size()] + turn, turn);
    if (!(step > 0)) return {};
    turned += step;
  }
  return std::abs(turned - turn) <= 1e-9 * turn ? along : std::vector<double>{};
}

// A surface of the gap between a fixed loop (a footprint's or the kept quads' edges, no rim edge) and a loop of the
// sheet's rim alone (a hole through the sheet inside a boss's ring foot): a thin ring, where Gmsh's quads fold between
// loops of other node counts (every boundary node is fixed). It gets one ring of quads: the rim loop's nodes replaced
// by as many as the fixed loop has, each the rim loop's point nearest to its fixed node (ringPoints), a quad between
// each fixed edge and the rim points of its ends.
// [in,out] nodes: the new rim points appended; [in] map, free, s. Returns the ring's quads (counter-clockwise in the
// map) and their worst scaled Jacobian in the map; none if s is not such a ring, its points are not in order or a quad
// folds.
std::pair<std::vector<Quad>, double> rimRing(Nodes& nodes, const GapMap& map, const std::set<Edge>& free,
                                             const Surface& s) {
  if (s.size() != 2) return {};
  auto freeEdges = [&](const Loop& l) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < l.size(); ++k) count += free.count({l[k], l[(k + 1) % l.size()]});
    return count;
  };
  const bool firstFree = freeEdges(s[0]) == s[0].size() && freeEdges(s[1]) == 0;
  if (!firstFree && !(freeEdges(s[1]) == s[1].size() && freeEdges(s[0]) == 0)) return {};
  const Loop &rim = s[firstFree ? 0 : 1], &fixed = s[firstFree ? 1 : 0];
  const std::vector<double> along = ringPoints(nodes.at, fixed, rim);
  if (along.empty()) return {};
  const int m = static_cast<int>(fixed.size()), first = static_cast<int>(nodes.at.size());
  std::vector<Vec3> flat;  // the ring in the map: the fixed nodes, then the rim points
  for (int b : fixed) flat.push_back(map.flat(nodes.at[b]));
  for (double a : along) nodes.at.push_back(pointAlong(nodes.at, rim, a)), flat.push_back(map.flat(nodes.at.back()));
  std::vector<Quad> local, quads;
  for (int i = 0; i < m; ++i) {
    local.push_back({i, (i + 1) % m, m + (i + 1) % m, m + i});
    quads.push_back({fixed[i], fixed[(i + 1) % m], first + (i + 1) % m, first + i});
  }
  const double worst = worstInPlane(flat, local);
  if (worst > 0) return {quads, worst};
  nodes.at.resize(first);
  return {};
}

// A gap ready for Gmsh: the nodes so far, its map and surfaces, the ways to mesh it (as it is, and with its acute
// corners cut off: cutAcuteCorners), each way's mesh sizes at its points, and its tries: every way with each of Gmsh's
// algorithms (kGapAlgorithms), in this order (gapQuads runs the second way only where the first is poor). (Finer mesh
// sizes at the points are not tried: every boundary edge is one segment, and Gmsh 4.8 sizes the inside from those, not
// from the points'.)
struct GapTries {
  struct Try {
    std::size_t way;
    int algorithm;
    GapRun gmsh;
  };
  std::vector<Vec3> at;  // every node when the gap was made ready (the first of its quads')
  const GapMap* map = nullptr;
  std::vector<Surface> surfaces;
  std::vector<WedgeCut> ways;
  std::vector<std::vector<double>> spacing;  // per way, at each of its points
  std::vector<Try> tries;
};

// [in] at: every node so far; [in] map: the gap's, kept by the caller; [in] surfaces. Returns its tries, not started.
GapTries gapTries(const std::vector<Vec3>& at, const GapMap& map, std::vector<Surface> surfaces) {
  GapTries g{at, &map, std::move(surfaces), {}, {}, {}};
  std::vector<Eigen::Vector2d> flat(at.size(), Eigen::Vector2d::Zero());  // the surfaces' nodes only are Gmsh's
  for (const Surface& s : g.surfaces)
    for (const Loop& loop : s)
      for (int n : loop) flat[n] = map.at(at[n]);
  g.ways.push_back({flat, {}, g.surfaces, {}});
  if (WedgeCut cut = cutAcuteCorners(flat, g.surfaces); !cut.quads.empty()) g.ways.push_back(std::move(cut));
  for (const WedgeCut& way : g.ways) {
    g.spacing.push_back(loopSpacing(at, g.surfaces));
    g.spacing.back().insert(g.spacing.back().end(), way.spacing.begin(), way.spacing.end());
  }
  for (std::size_t w = 0; w < g.ways.size(); ++w)
    for (int algorithm : kGapAlgorithms) g.tries.push_back({w, algorithm, {}});
  return g;
}

// The gaps' quads on the sheet: of each gap's tries (gapTries), the one whose worst quad, smoothed, is best (the first
// on a tie). A gap's tries with its acute corners cut off (its second way) are run only if the best of the gap as it
// is has its worst quad below kGoodGap: which tries run depends on their quads alone, not on the threads. The tries run
// in the gaps' order, as many children at once as there are threads and one more, which runs while this process
// smooths the quads of the tries taken (on one thread, one child): the next started once a try's quads are in, before
// they are smoothed, also a later gap's; a gap's second way is started first once it is found needed.
// [in,out] gaps; [in] chordal; [in] server: forks the Gmsh runs (null: this process); [in] meshed(g, quads, worst):
// called with each gap's quads (their first nodes gaps[g].at) and their worst quad's scaled Jacobian, in the gaps'
// order. Throws geometryError for the first gap, in their order, that no try gives unfolded quads.
void gapQuads(std::vector<GapTries>& gaps, const ChordalLocator& chordal, ForkServer* server,
              const std::function<void(std::size_t, QuadMesh, double)>& meshed) {
  struct StopLeft {  // a child not waited for (an exception) is not left running
    std::vector<GapTries>& gaps;
    ~StopLeft() {
      for (GapTries& g : gaps)
        for (GapTries::Try& t : g.tries) stopChild(t.gmsh.child);
    }
  } stopLeft{gaps};
  struct Taken {  // a gap's tries taken so far
    QuadMesh best;
    double worst = 0;
    std::string failure = "its quads are folded";
    std::size_t left = 0;  // tries queued or running, not yet taken
  };
  std::vector<Taken> taken(gaps.size());
  using Run = std::pair<std::size_t, std::size_t>;  // (gap, try)
  std::deque<Run> waiting, running;
  auto wayTries = [&](std::size_t g, std::size_t way) {
    std::vector<Run> runs;
    for (std::size_t k = 0; k < gaps[g].tries.size(); ++k)
      if (gaps[g].tries[k].way == way) runs.emplace_back(g, k);
    taken[g].left += runs.size();
    return runs;
  };
  for (std::size_t g = 0; g < gaps.size(); ++g)
    for (const Run& r : wayTries(g, 0)) waiting.push_back(r);
  const std::size_t children = static_cast<std::size_t>(threadCount() > 1 ? threadCount() + 1 : 1);
  auto startWaiting = [&] {
    for (; running.size() < children && !waiting.empty(); waiting.pop_front()) {
      GapTries& g = gaps[waiting.front().first];
      GapTries::Try& t = g.tries[waiting.front().second];
      t.gmsh = startGapQuads(server, g.ways[t.way].at, g.spacing[t.way], g.ways[t.way].surfaces, t.algorithm);
      running.push_back(waiting.front());
    }
  };
  std::size_t reported = 0;
  for (startWaiting(); !running.empty(); startWaiting()) {
    const auto [gi, k] = running.front();
    running.pop_front();
    GapTries& g = gaps[gi];
    Taken& gap = taken[gi];
    std::optional<QuadMesh> made;
    try {
      made = finishGapQuads(g.tries[k].gmsh);
    } catch (const Error& e) {
      gap.failure = e.what();
    }
    startWaiting();
    if (made) try {
        double tried = 0;
        QuadMesh q = gapTry(g.at, *g.map, chordal, g.surfaces, g.ways[g.tries[k].way], std::move(*made), tried);
        if (tried > gap.worst) gap.best = std::move(q), gap.worst = tried;
      } catch (const Error& e) {
        gap.failure = e.what();
      }
    if (--gap.left == 0 && g.tries[k].way == 0 && g.ways.size() > 1 && gap.worst < kGoodGap) {
      const std::vector<Run> cut = wayTries(gi, 1);
      waiting.insert(waiting.begin(), cut.begin(), cut.end());
    }
    for (; reported < gaps.size() && taken[reported].left == 0; ++reported) {
      if (taken[reported].best.quads.empty())
        throw geometryError("junction: the gap round a wall's foot was not meshed: " + taken[reported].failure);
      meshed(reported, std::move(taken[reported].best), taken[reported].worst);
    }
  }
}

// A foot of a footprint: its quads and its nodes (sorted).
struct FootParts {
  std::vector<int> quads, nodes;
};

std::vector<FootParts> feetParts(const FootprintQuads& footprint) {
  UnionFind feet(footprint.quads.size());
  std::vector<FootParts> parts;
  for (auto& [root, quads] : feetOf(footprint, feet)) {
    std::set<int> n;
    for (int q : quads) n.insert(footprint.quads[q].begin(), footprint.quads[q].end());
    parts.push_back({std::move(quads), std::vector<int>(n.begin(), n.end())});
  }
  return parts;
}

// The mean of the points.
Vec3 centroid(const std::vector<Vec3>& at, const std::vector<int>& nodes) {
  Vec3 c = Vec3::Zero();
  for (int n : nodes) c += at[n];
  return c / static_cast<double>(nodes.size());
}

// Foot g as foot f moved by the shift between their centroids: per node of f, the node of g within `near` of it so
// moved. Empty if the feet are not so alike (another node count, a node with none or two).
std::vector<int> alikeNodes(const std::vector<Vec3>& at, const std::vector<int>& f, const std::vector<int>& g,
                            double near) {
  if (f.size() != g.size()) return {};
  const Vec3 shift = centroid(at, g) - centroid(at, f);
  PointGrid grid(near);
  for (int n : g) grid.insert(n, at[n]);
  std::vector<int> partner;
  std::set<int> taken;
  for (int n : f) {
    int found = -1, count = 0;
    grid.forEachNear(at[n] + shift, near, [&](int m, const Vec3&) { found = m, ++count; });
    if (count != 1 || !taken.insert(found).second) return {};
    partner.push_back(found);
  }
  return partner;
}

}  // namespace

double worstInPlane(const std::vector<Vec3>& nodes, const std::vector<Quad>& quads) {
  return worstBy(quadInPlane, nodes, quads);
}

FootprintQuads onChordalSurface(FootprintQuads footprint, const ChordalLocator& chordal) {
  std::vector<Vec3> normal(footprint.nodes.size(), Vec3::Zero());
  for (const Quad& q : footprint.quads) {
    Vec3 n = areaVector(footprint.nodes, q), centre = Vec3::Zero();
    for (int c : q) centre += 0.25 * footprint.nodes[c];
    if (n.dot(chordal.locate(centre).point - centre) < 0) n = -n;  // towards the surface: feet across a bend agree
    for (int c : q) normal[c] += n;
  }
  for (std::size_t k = 0; k < footprint.nodes.size(); ++k) {
    const Vec3 p = footprint.nodes[k], n = normal[k].normalized();
    Vec3 at = chordal.locate(p).point;
    for (int step = 0; step < kAlongNormal && n.allFinite(); ++step)  // onto the line p + t n, then the surface
      at = chordal.locate(p + (at - p).dot(n) * n).point;
    footprint.nodes[k] = at;
  }
  return footprint;
}

MergedFootprints mergeFeetOnBothSides(const FootprintQuads& footprint, const ChordalLocator& chordal) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Quad& q : footprint.quads)
    for (int c = 0; c < 4; ++c)
      shortest = std::min(shortest, (footprint.nodes[q[c]] - footprint.nodes[q[(c + 1) % 4]]).norm());
  const double near = kMergeOpposite * shortest;
  const std::vector<FootParts> feet = feetParts(footprint);
  std::vector<int> partner(footprint.nodes.size(), -1);  // the node on the other side, for the first foot's nodes
  std::vector<TriangleTree> trees;                       // per foot, built once
  for (const FootParts& foot : feet) trees.push_back(footTree(footprint, foot.quads));
  MergedFootprints out;
  for (std::size_t f = 0; f < feet.size(); ++f)
    for (std::size_t g = f + 1; g < feet.size(); ++g) {
      const std::vector<int>&a = feet[f].nodes, &b = feet[g].nodes;
      if (partner[a.front()] >= 0 || partner[b.front()] >= 0) continue;
      if (std::none_of(a.begin(), a.end(), [&](int n) { return trees[g].anyWithin(footprint.nodes[n], near); }))
        continue;  // not at one place
      const std::vector<int> alike = alikeNodes(footprint.nodes, a, b, near);
      for (std::size_t k = 0; k < alike.size(); ++k) {
        partner[a[k]] = alike[k], partner[alike[k]] = a[k];
        out.shift = std::max(out.shift, 0.5 * (footprint.nodes[alike[k]] - footprint.nodes[a[k]]).norm());
      }
    }
  out.node.assign(footprint.nodes.size(), -1);
  for (std::size_t n = 0; n < footprint.nodes.size(); ++n) {
    if (out.node[n] >= 0) continue;
    const int p = partner[n];
    const Vec3 at = p < 0 ? footprint.nodes[n] : chordal.locate(0.5 * (footprint.nodes[n] + footprint.nodes[p])).point;
    out.node[n] = static_cast<int>(out.footprint.nodes.size());
    if (p >= 0) out.node[p] = out.node[n];
    out.footprint.nodes.push_back(at);
  }
  std::set<Quad> seen;  // sorted corners
  for (const Quad& q : footprint.quads) {
    Quad m{out.node[q[0]], out.node[q[1]], out.node[q[2]], out.node[q[3]]}, key = m;
    std::sort(key.begin(), key.end());
    if (std::adjacent_find(key.begin(), key.end()) != key.end())
      throw geometryError("junction: a wall's footprint folds onto itself on the sheet it stands on");
    if (seen.insert(key).second) out.footprint.quads.push_back(m);
  }
  return out;
}

// insertFootprints with the sheet's quads within `band` of a footprint meshed again.
FootprintInsertion insertWithin(const QuadMesh& sheet, const FootprintQuads& footprint, const ChordalLocator& chordal,
                                double size, double band, ForkServer* server) {
  Nodes nodes;
  nodes.at = sheet.nodes;
  nodes.sheetNodes = static_cast<int>(sheet.nodes.size());
  nodes.at.insert(nodes.at.end(), footprint.nodes.begin(), footprint.nodes.end());
  KeptQuads kept{sheet.quads, {}};
  const std::vector<Gap> gaps = gapsRoundFeet(sheet, footprint, size, band, kept.removed);
  std::vector<Quad> added;  // in the numbering of `nodes`
  FootprintInsertion out;
  const EdgeUses quadsOfEdge = edgeUses(sheet);
  // Every gap made ready in turn (its rim rings, its even boundaries), then all meshed by Gmsh side by side: a gap's
  // quads use its own nodes and the nodes before it, so its new nodes are numbered after all, and the quads are taken
  // gap by gap as before. The first error in the gaps' order is thrown.
  std::vector<std::unique_ptr<GapMap>> maps;
  std::vector<GapTries> ready;
  std::vector<std::vector<Quad>> rings(gaps.size()), meshed(gaps.size());
  std::vector<int> readyGap;  // per ready gap, its gap
  std::exception_ptr notReady;
  for (std::size_t made = 0; made < gaps.size() && !notReady; ++made) try {
      const Gap& gap = gaps[made];
      maps.push_back(std::make_unique<GapMap>(sheet, gap));
      const GapMap& map = *maps.back();
      const GapEdges edges = gapEdges(nodes, map, sheet, quadsOfEdge, footprint, gap, size);
      std::vector<Loop> loops = chainLoops(edges.edges);
      dropTinyRimEdges(nodes, edges.free, size, loops);
      std::vector<Surface> surfaces;
      for (Surface& s : surfacesOf(nodes, map, loops)) {
        auto [ring, worst] = rimRing(nodes, map, edges.free, s);
        if (ring.empty()) {
          surfaces.push_back(std::move(s));
          continue;
        }
        rings[made].insert(rings[made].end(), ring.begin(), ring.end());
        out.worstQuad = std::min(out.worstQuad, worst), out.quadsMeshed += ring.size();
      }
      evenBoundaries(nodes, edges.free, surfaces, kept);
      if (!surfaces.empty()) ready.push_back(gapTries(nodes.at, map, std::move(surfaces))), readyGap.push_back(made);
    } catch (...) {
      notReady = std::current_exception();
    }
  gapQuads(ready, chordal, server, [&](std::size_t r, QuadMesh q, double worst) {
    const int before = static_cast<int>(ready[r].at.size()), first = static_cast<int>(nodes.at.size());
    nodes.at.insert(nodes.at.end(), q.nodes.begin() + before, q.nodes.end());
    for (Quad& quad : q.quads)
      for (int& n : quad)
        if (n >= before) n += first - before;
    meshed[readyGap[r]] = std::move(q.quads);
    out.worstQuad = std::min(out.worstQuad, worst);
    out.quadsMeshed += meshed[readyGap[r]].size();
  });
  if (notReady) std::rethrow_exception(notReady);
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    added.insert(added.end(), rings[g].begin(), rings[g].end());
    added.insert(added.end(), meshed[g].begin(), meshed[g].end());
    for (int f : gaps[g].footprintQuads) {
      Quad quad = footprint.quads[f];
      for (int& n : quad) n += nodes.sheetNodes;
      added.push_back(quad);
    }
    out.quadsRemoved += gaps[g].sheetQuads.size();
  }
  // Renumber: the kept quads' nodes in their order, then the others as the added quads use them.
  std::vector<int> id(nodes.at.size(), -1);
  auto use = [&](int n) {
    if (id[n] < 0) id[n] = static_cast<int>(out.quads.nodes.size()), out.quads.nodes.push_back(nodes.at[n]);
    return id[n];
  };
  for (std::size_t q = 0; q < kept.quads.size(); ++q)
    if (!kept.removed[q]) out.quads.quads.push_back({0, 0, 0, 0});
  std::vector<int> keptNodes;
  for (std::size_t q = 0; q < kept.quads.size(); ++q)
    if (!kept.removed[q]) keptNodes.insert(keptNodes.end(), kept.quads[q].begin(), kept.quads[q].end());
  std::sort(keptNodes.begin(), keptNodes.end());
  keptNodes.erase(std::unique(keptNodes.begin(), keptNodes.end()), keptNodes.end());
  for (int n : keptNodes) use(n);
  std::size_t k = 0;
  for (std::size_t q = 0; q < kept.quads.size(); ++q)
    if (!kept.removed[q]) {
      for (int c = 0; c < 4; ++c) out.quads.quads[k][c] = id[kept.quads[q][c]];
      ++k;
    }
  for (const Quad& quad : added) out.quads.quads.push_back({use(quad[0]), use(quad[1]), use(quad[2]), use(quad[3])});
  out.node.resize(footprint.nodes.size());
  for (std::size_t f = 0; f < footprint.nodes.size(); ++f) {
    out.node[f] = id[nodes.sheetNodes + f];
    if (out.node[f] < 0) throw geometryError("junction: a footprint node is in none of its quads");
  }
  out.quads.layout = sheet.layout;
  out.quads.tries = sheet.tries;
  return out;
}

FootprintInsertion insertFootprints(const QuadMesh& sheet, const FootprintQuads& footprint,
                                    const ChordalLocator& chordal, double size, ForkServer* server) {
  if (footprint.quads.empty()) throw geometryError("junction: no footprint to put in the sheet's quads");
  FootprintInsertion best;
  std::string failure;
  for (double band : kBands) {  // a wider gap where the boundary leaves Gmsh no good quads
    try {
      FootprintInsertion in = insertWithin(sheet, footprint, chordal, size, band * size, server);
      if (best.quads.quads.empty() || in.worstQuad > best.worstQuad) best = std::move(in);
      if (best.worstQuad >= kGoodGap) break;
    } catch (const Error& e) {
      if (failure.empty()) failure = e.what();
    }
  }
  if (best.quads.quads.empty()) throw geometryError(failure);
  return best;
}

QuadMesh quadsInPolygon(const std::vector<Eigen::Vector2d>& at, const std::vector<std::vector<int>>& loops,
                        ForkServer* server) {
  std::vector<Vec3> at3;
  for (const Eigen::Vector2d& p : at) at3.emplace_back(p.x(), p.y(), 0);
  const std::vector<Surface> surfaces{loops};
  const std::vector<double> spacing = loopSpacing(at3, surfaces);
  std::vector<GapRun> runs;  // every algorithm side by side; the best worst quad kept, the first on a tie
  for (int algorithm : kGapAlgorithms) runs.push_back(startGapQuads(server, at, spacing, surfaces, algorithm));
  QuadMesh best;
  double bestWorst = -std::numeric_limits<double>::infinity();
  std::string failure;
  for (GapRun& run : runs) {
    try {
      QuadMesh q = finishGapQuads(run);
      checkGapQuads(q, surfaces);
      if (const double worst = worstInPlane(q.nodes, q.quads); worst > bestWorst)
        best = std::move(q), bestWorst = worst;
    } catch (const Error& e) {
      if (failure.empty()) failure = e.what();
    }
  }
  if (best.quads.empty()) throw geometryError(failure);
  return best;
}

}  // namespace hexlayer
