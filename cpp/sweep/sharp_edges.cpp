#include "sweep/sharp_edges.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Extrema_ExtPC.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "core/groups.hpp"
#include "geometry/sheet_edges.hpp"
#include "quality/quality.hpp"
#include "sweep/sweep.hpp"

namespace hexlayer {
namespace {

constexpr double kMaxReach = 0.6;  // of the quad edge crossing the CAD edge: how far its nearer end may be moved
constexpr double kFloor = 0.5;     // no hex round a moved column below this, or below the worst it had
// The same for an edge of a lap's foot (a cut face: a boss's flat merged into a box's wall): the wall's hexes are
// joined to the boss's there only if its hexes' faces follow the flat's edges.
constexpr double kLapFloor = 0.2;
constexpr double kOnEdge = 1e-6;  // of the quad edge: an end this near is on the CAD edge already

// The point of a CAD edge nearest to p (its ends included).
Vec3 nearestOnEdge(const BRepAdaptor_Curve& curve, const Vec3& p) {
  const gp_Pnt q(p.x(), p.y(), p.z());
  gp_Pnt best = curve.Value(curve.FirstParameter());
  if (curve.Value(curve.LastParameter()).SquareDistance(q) < best.SquareDistance(q))
    best = curve.Value(curve.LastParameter());
  Extrema_ExtPC extrema(q, curve);
  if (extrema.IsDone())
    for (int i = 1; i <= extrema.NbExt(); ++i)
      if (extrema.IsMin(i) && extrema.Point(i).Value().SquareDistance(q) < best.SquareDistance(q))
        best = extrema.Point(i).Value();
  return {best.X(), best.Y(), best.Z()};
}

// A wall node to put on a CAD edge: the nearer end of a quad edge crossing it.
struct Capture {
  double distance;
  int node, other, edge;  // the end moved, the other end; edge: index into the sharp edges
  Vec3 onEdge;
  bool operator<(const Capture& o) const {
    return std::tie(distance, node, edge) < std::tie(o.distance, o.node, o.edge);
  }
};

// Per wall node (layer 0 or the top), its column from it to the other wall (columnsByBottom's, read from the top
// for a top node); empty for the other nodes.
std::vector<std::vector<int>> wallColumns(const HexMesh& mesh) {
  std::vector<std::vector<int>> of = columnsByBottom(mesh);
  for (std::size_t i = 0; i < of.size(); ++i)
    if (of[i].size() > 1 && of[of[i].back()].empty()) of[of[i].back()].assign(of[i].rbegin(), of[i].rend());
  return of;
}

// The worst scaled Jacobian of the given hexes.
double worstOf(const HexMesh& mesh, const std::vector<int>& hexes) {
  double worst = 1;
  for (int h : hexes) worst = std::min(worst, hexScaledJacobian(hexCorners(mesh, h)));
  return worst;
}

// The captures: per quad edge of a wall (a hex's bottom face at layer 0, its top face at the top layer) whose ends lie
// on the two faces of a sharp edge, its nearer end if near enough and not on it already; nearest first.
std::vector<Capture> captures(const HexMesh& mesh, const std::vector<FacePairEdge>& edges,
                              const std::vector<BRepAdaptor_Curve>& curves) {
  std::multimap<std::pair<int, int>, int> byFaces;
  for (std::size_t e = 0; e < edges.size(); ++e) byFaces.emplace(std::make_pair(edges[e].a, edges[e].b), e);
  std::vector<Capture> found;
  auto consider = [&](int u, int v) {
    if (mesh.nodeOnRim[u] || mesh.nodeOnRim[v] || mesh.nodeFace[u] < 0 || mesh.nodeFace[v] < 0) return;
    const auto [lo, hi] = byFaces.equal_range(std::minmax(mesh.nodeFace[u], mesh.nodeFace[v]));
    const double length = (mesh.nodes[u] - mesh.nodes[v]).norm();
    for (auto it = lo; it != hi; ++it) {
      const Vec3 pu = nearestOnEdge(curves[it->second], mesh.nodes[u]);
      const Vec3 pv = nearestOnEdge(curves[it->second], mesh.nodes[v]);
      const double du = (pu - mesh.nodes[u]).norm(), dv = (pv - mesh.nodes[v]).norm();
      if (std::min(du, dv) <= kOnEdge * length || std::min(du, dv) > kMaxReach * length) continue;
      found.push_back(du <= dv ? Capture{du, u, v, it->second, pu} : Capture{dv, v, u, it->second, pv});
    }
  };
  for (const auto& h : mesh.hexes)
    for (int base : {0, 4})
      if (mesh.nodeLayer[h[base]] == (base == 0 ? 0 : mesh.layers))
        for (int i = 0; i < 4; ++i) consider(h[base + i], h[base + (i + 1) % 4]);
  std::sort(found.begin(), found.end());
  return found;
}

// Per node, the length of its shortest edge to another rim node of its wall (layer 0 or the top): its rim edges there
// (infinity for the other nodes).
std::vector<double> rimEdgeLengths(const HexMesh& mesh) {
  std::vector<double> shortest(mesh.nodes.size(), std::numeric_limits<double>::infinity());
  auto onWallRim = [&](int v) {
    return mesh.nodeOnRim[v] == kRimSwept && (mesh.nodeLayer[v] == 0 || mesh.nodeLayer[v] == mesh.layers);
  };
  for (const auto& h : mesh.hexes)
    for (int base : {0, 4})
      for (int i = 0; i < 4; ++i)
        if (const int u = h[base + i], v = h[base + (i + 1) % 4]; onWallRim(u) && onWallRim(v)) {
          const double length = (mesh.nodes[u] - mesh.nodes[v]).norm();
          shortest[u] = std::min(shortest[u], length), shortest[v] = std::min(shortest[v], length);
        }
  return shortest;
}

// The captures of the sharp edges' ends on a rim: where a sharp edge ends on a lateral face (a boss's flat merged into
// a wall meets its top or its foot, a box's bend without an outside round meets its rim), the wall's rim node on one
// of the edge's faces nearest that end, if it lies within kMaxReach of its rim edge of it and not on it already (the
// capture's `other` -1: the end is a point). The rim's quad edges cross the edge there (the rim nodes are no interior
// quad edge's, which `captures` takes).
std::vector<Capture> rimCaptures(const HexMesh& mesh, const CadSolid& cad, const WallSides& sides,
                                 const std::vector<FacePairEdge>& edges) {
  TopTools_IndexedDataMapOfShapeListOfShape facesAt;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_VERTEX, TopAbs_FACE, facesAt);
  const std::vector<double> rimEdge = rimEdgeLengths(mesh);
  std::vector<int> rimNodes;
  for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
    if (std::isfinite(rimEdge[v]) && mesh.nodeFace[v] >= 0) rimNodes.push_back(static_cast<int>(v));
  std::vector<Capture> found;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(cad.edges(edges[e].edge + 1));
    for (const TopoDS_Vertex& end : {TopExp::FirstVertex(edge), TopExp::LastVertex(edge)}) {
      if (end.IsNull() || !facesAt.Contains(end)) continue;
      const TopTools_ListOfShape& faces = facesAt.FindFromKey(end);
      if (std::none_of(faces.begin(), faces.end(), [&](const TopoDS_Shape& f) {
            const int face = cad.faces.FindIndex(f) - 1;
            return face >= 0 && sides.faces[face].side == Side::Lateral;
          }))
        continue;
      const gp_Pnt p = BRep_Tool::Pnt(end);
      const Vec3 at(p.X(), p.Y(), p.Z());
      int nearest = -1;
      for (int v : rimNodes)
        if ((mesh.nodeFace[v] == edges[e].a || mesh.nodeFace[v] == edges[e].b) &&
            (nearest < 0 || (mesh.nodes[v] - at).squaredNorm() < (mesh.nodes[nearest] - at).squaredNorm()))
          nearest = v;
      if (nearest < 0) continue;
      if (const double d = (mesh.nodes[nearest] - at).norm();
          d > kOnEdge * rimEdge[nearest] && d <= kMaxReach * rimEdge[nearest])
        found.push_back({d, nearest, -1, static_cast<int>(e), at});
    }
  }
  return found;
}

}  // namespace

SharpEdgeStats captureSharpEdges(HexMesh& mesh, const CadSolid& cad, const WallSides& sides) {
  SharpEdgeStats stats;
  std::vector<FacePairEdge> edges;
  for (const FacePairEdge& e : sharpEdges(cad))
    if (sides.faces[e.a].side != Side::Lateral && sides.faces[e.a].side == sides.faces[e.b].side) edges.push_back(e);
  stats.edges = edges.size();
  if (edges.empty() || mesh.quadratic()) return stats;
  std::vector<BRepAdaptor_Curve> curves;
  for (const FacePairEdge& e : edges) curves.emplace_back(TopoDS::Edge(cad.edges(e.edge + 1)));
  const std::vector<std::vector<int>> columns = wallColumns(mesh);
  const Groups<int> hexesAt = groupByKey<int>(mesh.nodes.size(), [&](auto emit) {
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
      for (int v : mesh.hexes[h]) emit(v, static_cast<int>(h));
  });
  std::vector<char> moved(mesh.nodes.size(), 0);
  std::vector<Capture> all = captures(mesh, edges, curves), ends = rimCaptures(mesh, cad, sides, edges);
  all.insert(all.end(), ends.begin(), ends.end());
  std::sort(all.begin(), all.end());
  for (const Capture& c : all) {
    // the other end on an edge already: this one crosses it no more
    if (moved[c.node] || (c.other >= 0 && moved[c.other])) continue;
    const std::vector<int>& column = columns[c.node];
    if (column.empty()) continue;
    const Vec3 move = c.onEdge - mesh.nodes[c.node];
    auto moveColumn = [&](double sign) {  // the node by `move`, the others less towards the other wall (0 at it)
      const double last = static_cast<double>(column.size() - 1);
      for (std::size_t k = 0; k < column.size(); ++k) mesh.nodes[column[k]] += sign * (1 - k / last) * move;
    };
    std::vector<int> around;
    for (int v : column)
      around.insert(around.end(), hexesAt.items.begin() + hexesAt.start[v],
                    hexesAt.items.begin() + hexesAt.start[v + 1]);
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    const double before = worstOf(mesh, around);
    moveColumn(1);
    const FacePairEdge& e = edges[c.edge];
    const double floor = isCutFace(cad, e.a) || isCutFace(cad, e.b) ? kLapFloor : kFloor;
    if (worstOf(mesh, around) < std::min(before, floor)) {
      moveColumn(-1);
      ++stats.nodesKept;
      continue;
    }
    moved[c.node] = 1, ++stats.nodesMoved;
    if (c.other >= 0) mesh.nodeFace[c.node] = edges[c.edge].a;  // an end's node stays on its rim face
  }
  return stats;
}

}  // namespace hexlayer
