#include "sweep/quadratic.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/error.hpp"
#include "quality/quality.hpp"

namespace hexlayer {
namespace {

constexpr double kMaxWallMove = 0.25;  // largest projection move, in edge lengths, that keeps the element unfolded

using Edge = std::pair<int, int>;  // corner ids, smaller first

Edge edgeKey(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// The mesh's edges, each once in order of first appearance (hexes in order, kHexEdges order), and
// per hex the index of each of its 12 edges: the mid-edge node of edge e gets id corners + e.
struct EdgeTable {
  std::vector<Edge> edges;
  std::map<Edge, int> index;
  std::vector<std::array<int, 12>> ofHex;
};

EdgeTable collectEdges(const HexMesh& mesh) {
  EdgeTable t;
  t.ofHex.reserve(mesh.hexes.size());
  for (const auto& hex : mesh.hexes) {
    std::array<int, 12> local;
    for (int e = 0; e < 12; ++e) {
      const Edge key = edgeKey(hex[kHexEdges[e][0]], hex[kHexEdges[e][1]]);
      const auto [it, added] = t.index.emplace(key, static_cast<int>(t.edges.size()));
      if (added) t.edges.push_back(key);
      local[e] = it->second;
    }
    t.ofHex.push_back(local);
  }
  return t;
}

// The two ends of every node's sweep line (hex edges i -> i+4 chained from the bottom to the top
// wall), and the node's fraction along it: 0 at the bottom, 1 at the top.
struct SweepColumns {
  std::vector<int> bottom, top;
  std::vector<double> fraction;
};

SweepColumns sweepColumns(const HexMesh& mesh) {
  const std::size_t n = mesh.nodes.size();
  std::vector<int> up(n, -1), down(n, -1);
  for (const auto& hex : mesh.hexes)
    for (int c = 0; c < 4; ++c) up[hex[c]] = hex[c + 4], down[hex[c + 4]] = hex[c];
  SweepColumns s{std::vector<int>(n, -1), std::vector<int>(n, -1), std::vector<double>(n, 0)};
  for (std::size_t b = 0; b < n; ++b) {
    if (down[b] >= 0) continue;  // not a column's bottom node
    std::vector<int> column{static_cast<int>(b)};
    while (up[column.back()] >= 0) column.push_back(up[column.back()]);
    const Vec3 base = mesh.nodes[b], axis = mesh.nodes[column.back()] - base;
    for (std::size_t k = 0; k < column.size(); ++k) {
      const int i = column[k];
      s.bottom[i] = column.front(), s.top[i] = column.back();
      const double byLayer = column.size() > 1 ? double(k) / double(column.size() - 1) : 0;  // a collapsed sweep line
      s.fraction[i] = axis.squaredNorm() > 0 ? (mesh.nodes[i] - base).dot(axis) / axis.squaredNorm() : byLayer;
    }
  }
  return s;
}

bool onCap(const HexMesh& mesh, int node) { return mesh.nodeOnRim[node] == kRimCap; }

// Edges of the lateral boundary faces (hex sides 2..5 used by one hex, and every boundary face of a rim cap):
// their mid-edge nodes lie on the rim.
std::vector<char> rimEdges(const HexMesh& mesh, const EdgeTable& t) {
  std::vector<char> rim(t.edges.size(), 0);
  for (const BoundaryFace& f : boundaryFaces(mesh))
    if (f.localFace >= 2 || std::any_of(f.nodes.begin(), f.nodes.end(), [&](int v) { return onCap(mesh, v); }))
      for (int i = 0; i < 4; ++i) rim[t.index.at(edgeKey(f.nodes[i], f.nodes[(i + 1) % 4]))] = 1;
  return rim;
}

// `at` projected onto the `side` faces if that moves it less than kMaxWallMove edge lengths, else `at`.
FacePoint projectIfClose(const FacePoint& at, double edgeLength, Side side, const WallProjection& project,
                         std::size_t& projected, double& maxMove) {
  const std::optional<FacePoint> onCad = project(side, at.point);
  if (!onCad) return at;
  const double move = (onCad->point - at.point).norm();
  if (move > kMaxWallMove * edgeLength) return at;
  ++projected;
  maxMove = std::max(maxMove, move);
  return *onCad;
}

// Mid-edge node of a top or bottom wall edge: the midpoint, projected onto that wall if the move is small enough.
FacePoint wallMidNode(const Vec3& a, const Vec3& b, Side side, const WallProjection& project, QuadraticStats& stats) {
  ++stats.wallNodes;
  return projectIfClose(FacePoint{0.5 * (a + b), -1}, (b - a).norm(), side, project, stats.projected,
                        stats.maxProjectionMove);
}

struct MidEdgeNodes {
  std::vector<Vec3> position;
  std::vector<int> layer;  // the layer of an in-plane edge, -1 for a sweep edge
  std::vector<int> face;   // the CAD face a wall node was projected onto, else -1
};

// Places the node of every edge: sweep and wall edges first, as inner-layer edges interpolate the walls';
// then the nodes of rim edges onto the lateral faces (a rim wall edge's node, on the wall already, then
// lies on the CAD edge between the wall and the lateral face).
MidEdgeNodes placeMidEdgeNodes(const HexMesh& mesh, const EdgeTable& t, const std::vector<char>& rim,
                               const WallProjection& project, QuadraticStats& stats) {
  const SweepColumns col = sweepColumns(mesh);
  MidEdgeNodes mid{std::vector<Vec3>(t.edges.size()), std::vector<int>(t.edges.size()),
                   std::vector<int>(t.edges.size(), -1)};
  // a wall edge: in the bottom or top layer, or from a sweep line's top in its layer (on a column's ledge, lower than
  // its top: to another line's top, or to a step's line where it crosses the ledge's rim)
  std::vector<char> wall(t.edges.size(), 0);
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const auto [a, b] = t.edges[e];
    const int ka = mesh.nodeLayer[a], kb = mesh.nodeLayer[b];
    const bool cap = onCap(mesh, a) || onCap(mesh, b);  // on a rim cap: neither a wall nor a layer
    mid.layer[e] = ka == kb && !cap ? ka : -1;
    wall[e] = mid.layer[e] >= 0 && (ka == 0 || ka == mesh.layers || col.top[a] == a || col.top[b] == b);
    if (mid.layer[e] < 0)
      mid.position[e] = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
    else if (wall[e]) {
      const FacePoint p = wallMidNode(mesh.nodes[a], mesh.nodes[b], ka == 0 ? Side::Bottom : Side::Top, project, stats);
      mid.position[e] = p.point, mid.face[e] = p.face;
    }
  }
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const auto [a, b] = t.edges[e];
    if (mid.layer[e] < 0 || wall[e]) continue;
    const auto below = t.index.find(edgeKey(col.bottom[a], col.bottom[b]));
    const auto above = t.index.find(edgeKey(col.top[a], col.top[b]));
    if (below == t.index.end() || above == t.index.end()) {  // columns of other heights (a column's step): its middle
      mid.position[e] = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
      continue;
    }
    const Vec3 &from = mid.position[below->second], &to = mid.position[above->second];
    mid.position[e] = from + 0.5 * (col.fraction[a] + col.fraction[b]) * (to - from);
  }
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    if (!rim[e]) continue;
    const auto [a, b] = t.edges[e];
    ++stats.rimNodes;
    // An inner layer's rim edge joins two nodes on the rim faces: its node starts from their midpoint, not from
    // the walls' (which cut across a rim that bulges between the walls: a chamfer on both sides, a round).
    const bool inner = mid.layer[e] > 0 && !wall[e];
    const Vec3 start = inner ? Vec3(0.5 * (mesh.nodes[a] + mesh.nodes[b])) : mid.position[e];
    const FacePoint p = projectIfClose({start, mid.face[e]}, (mesh.nodes[b] - mesh.nodes[a]).norm(), Side::Lateral,
                                       project, stats.rimProjected, stats.maxProjectionMove);
    mid.position[e] = p.point, mid.face[e] = p.face;
  }
  return mid;
}

}  // namespace

QuadraticStats addMidEdgeNodes(HexMesh& mesh, const WallProjection& project) {
  if (mesh.quadratic()) throw Error(ExitCode::Internal, "the mesh already has mid-edge nodes");
  if (mesh.nodeLayer.size() != mesh.nodes.size() || mesh.nodeOnRim.size() != mesh.nodes.size())
    throw Error(ExitCode::Internal, "mid-edge nodes need the layer and rim flag of every node");
  const EdgeTable t = collectEdges(mesh);
  QuadraticStats stats;
  stats.midNodes = t.edges.size();
  const std::vector<char> rim = rimEdges(mesh, t);
  const MidEdgeNodes mid = placeMidEdgeNodes(mesh, t, rim, project, stats);
  const int corners = static_cast<int>(mesh.nodes.size());
  mesh.nodes.insert(mesh.nodes.end(), mid.position.begin(), mid.position.end());
  mesh.nodeLayer.insert(mesh.nodeLayer.end(), mid.layer.begin(), mid.layer.end());
  mesh.nodeOnRim.insert(mesh.nodeOnRim.end(), rim.begin(), rim.end());
  if (mesh.nodeFace.size() == static_cast<std::size_t>(corners))
    mesh.nodeFace.insert(mesh.nodeFace.end(), mid.face.begin(), mid.face.end());
  mesh.midEdges = t.ofHex;
  for (auto& hex : mesh.midEdges)
    for (int& e : hex) e += corners;
  return stats;
}

}  // namespace hexlayer
