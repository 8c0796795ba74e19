#include "quadmesh/column_foot.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <GeomAPI_IntCS.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Line.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "core/polygon.hpp"
#include "quadmesh/footprint_insert.hpp"

namespace hexlayer {
namespace {

constexpr double kOnOutline = 1e-2;  // of the quad size: an outline node this near the foot's edges lies on them
constexpr double kStraight = 1e-9;   // an edge whose chord is this much shorter than it, relative, or less is straight

// One edge of a wire in the wire's order: its curve, run from `first` to `last` (reversed where the wire runs it
// backwards), its length and how many segments it gets.
struct WireEdge {
  BRepAdaptor_Curve curve;
  double first = 0, last = 0, length = 0;
  int segments = 1;
  bool straight = true;
};

std::vector<WireEdge> wireEdges(const TopoDS_Wire& wire, const TopoDS_Face& face, double size) {
  std::vector<WireEdge> edges;
  for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
    const TopoDS_Edge& edge = e.Current();
    WireEdge w{BRepAdaptor_Curve(edge)};
    w.first = w.curve.FirstParameter(), w.last = w.curve.LastParameter();
    if (edge.Orientation() == TopAbs_REVERSED) std::swap(w.first, w.last);
    w.length = GCPnts_AbscissaPoint::Length(w.curve);
    // a line, or a B-spline along one (a part scaled to metres): its chord as long as it
    w.straight = w.curve.Value(w.first).Distance(w.curve.Value(w.last)) >= (1 - kStraight) * w.length;
    w.segments = std::max(TopExp::FirstVertex(edge).IsSame(TopExp::LastVertex(edge)) ? 3 : 1,
                          static_cast<int>(std::ceil(w.length / size - 1e-9)));
    edges.push_back(w);
  }
  return edges;
}

// The loop's count made kMinRoundLoop or more where it is not all straight, and even: the edge with the longest
// segments gets one more, in turn.
void evenLoop(std::vector<WireEdge>& edges) {
  auto count = [&] {
    int n = 0;
    for (const WireEdge& e : edges) n += e.segments;
    return n;
  };
  const bool round = std::any_of(edges.begin(), edges.end(), [](const WireEdge& e) { return !e.straight; });
  while ((round && count() < kMinRoundLoop) || count() % 2 != 0) {
    auto longest = std::max_element(edges.begin(), edges.end(), [](const WireEdge& a, const WireEdge& b) {
      return a.length / a.segments < b.length / b.segments;
    });
    ++longest->segments;
  }
}

// The loop's points: each edge's start and the points dividing it evenly by arc length (its end is the next's start).
std::vector<Vec3> loopPoints(const std::vector<WireEdge>& edges) {
  std::vector<Vec3> points;
  for (const WireEdge& e : edges) {
    const bool forward = e.first < e.last;
    GCPnts_UniformAbscissa divide(e.curve, e.segments + 1, std::min(e.first, e.last), std::max(e.first, e.last));
    if (!divide.IsDone() || divide.NbPoints() != e.segments + 1)
      throw geometryError("column: an edge of a column's foot could not be divided");
    for (int k = 0; k < e.segments; ++k) {
      const gp_Pnt p = e.curve.Value(divide.Parameter(forward ? k + 1 : e.segments + 1 - k));
      points.emplace_back(p.X(), p.Y(), p.Z());
    }
  }
  return points;
}

// Where the line through p along the axis meets the surface, the crossing nearest to p (the nearest point of the
// surface if the line misses it). [in] surface, p, axis.
Vec3 alongAxisOnto(const Handle(Geom_Surface) & surface, const Vec3& p, const Vec3& axis) {
  const Handle(Geom_Line) line = new Geom_Line(gp_Pnt(p.x(), p.y(), p.z()), gp_Dir(axis.x(), axis.y(), axis.z()));
  GeomAPI_IntCS crossing(line, surface);
  std::optional<Vec3> nearest;
  for (int k = 1; crossing.IsDone() && k <= crossing.NbPoints(); ++k)
    if (const Vec3 q = toVec(crossing.Point(k)); !nearest || (q - p).norm() < (*nearest - p).norm()) nearest = q;
  if (nearest) return *nearest;
  GeomAPI_ProjectPointOnSurf onto(gp_Pnt(p.x(), p.y(), p.z()), surface);
  return onto.NbPoints() > 0 ? toVec(onto.NearestPoint()) : p;
}

// The outer loop's index: the loop of the largest area (per loop, its signed area in the foot's plane).
long outerLoop(const std::vector<double>& area) {
  return std::max_element(area.begin(), area.end(), [](double x, double y) { return std::abs(x) < std::abs(y); }) -
         area.begin();
}

// A foot with its plane's axes (e1 x e2 = the column's axis) and nothing on it yet.
ColumnFoot footPlane(const ColumnPiece& column) {
  ColumnFoot foot;
  const Vec3& a = column.axis;
  foot.e1 = (std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(a).normalized();
  foot.e2 = a.cross(foot.e1);
  return foot;
}

// The loops of the quads' boundary edges (each edge in one quad only), each in the quads' direction: the outer loop
// counter-clockwise and the holes clockwise where the quads are. Empty if the edges do not close into simple loops.
std::vector<std::vector<int>> boundaryLoops(const QuadMesh& quads) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& q : quads.quads)
    for (int c = 0; c < 4; ++c) ++uses[{std::min(q[c], q[(c + 1) % 4]), std::max(q[c], q[(c + 1) % 4])}];
  std::map<int, int> next;
  for (const auto& q : quads.quads)
    for (int c = 0; c < 4; ++c)
      if (const int a = q[c], b = q[(c + 1) % 4]; uses[{std::min(a, b), std::max(a, b)}] == 1)
        if (!next.emplace(a, b).second) return {};  // a node twice on the outline
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop{next.begin()->first};
    for (auto at = next.find(loop.back()); at != next.end() && at->second != loop.front(); at = next.find(loop.back()))
      loop.push_back(at->second), next.erase(at);
    if (next.erase(loop.back()) == 0) return {};  // open
    loops.push_back(loop);
  }
  return loops;
}

}  // namespace

std::optional<ColumnFoot> columnFootAcross(const CadSolid& cad, const ColumnPiece& column, const FootprintQuads& other,
                                           double size) {
  ColumnFoot foot = footPlane(column);
  const TopoDS_Face& face = TopoDS::Face(cad.faces(column.foot + 1));
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  for (const Vec3& p : other.nodes) foot.quads.nodes.push_back(alongAxisOnto(surface, p, column.axis));
  foot.quads.quads = other.quads;
  std::vector<Eigen::Vector2d> flat;
  for (const Vec3& p : foot.quads.nodes) flat.push_back(onFootPlane(foot, column, p));
  double area = 0;  // the quads' in the plane, counter-clockwise positive
  for (const auto& q : foot.quads.quads) area += polygonArea({flat[q[0]], flat[q[1]], flat[q[2]], flat[q[3]]});
  if (area < 0)
    for (auto& q : foot.quads.quads) std::reverse(q.begin(), q.end());
  foot.loops = boundaryLoops(foot.quads);
  int wires = 0;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (foot.loops.empty() || static_cast<int>(foot.loops.size()) != wires) return std::nullopt;
  TopoDS_Compound edges;
  BRep_Builder builder;
  builder.MakeCompound(edges);
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) builder.Add(edges, e.Current());
  for (const std::vector<int>& loop : foot.loops)
    for (int n : loop) {
      const Vec3& p = foot.quads.nodes[n];
      BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z())).Vertex(), edges);
      if (!d.IsDone() || d.Value() > kOnOutline * size) return std::nullopt;
    }
  std::vector<double> loopArea;
  for (const std::vector<int>& loop : foot.loops) {
    std::vector<Eigen::Vector2d> polygon;
    for (int n : loop) polygon.push_back(flat[n]);
    loopArea.push_back(polygonArea(polygon));
  }
  const long outer = outerLoop(loopArea);  // first
  std::rotate(foot.loops.begin(), foot.loops.begin() + outer, foot.loops.begin() + outer + 1);
  return foot;
}

ColumnFoot columnFootQuads(const CadSolid& cad, const ColumnPiece& column, double size, ForkServer* server) {
  ColumnFoot foot = footPlane(column);
  const TopoDS_Face& face = TopoDS::Face(cad.faces(column.foot + 1));
  std::vector<Eigen::Vector2d> at;
  std::vector<Vec3> points;
  std::vector<double> area;  // per loop, in the plane
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    std::vector<WireEdge> edges = wireEdges(TopoDS::Wire(w.Current()), face, size);
    evenLoop(edges);
    std::vector<int> loop;
    std::vector<Eigen::Vector2d> flat;
    for (const Vec3& p : loopPoints(edges)) {
      loop.push_back(static_cast<int>(points.size()));
      points.push_back(p), flat.push_back(onFootPlane(foot, column, p)), at.push_back(flat.back());
    }
    area.push_back(polygonArea(flat));
    foot.loops.push_back(loop);
  }
  if (foot.loops.empty()) throw geometryError("column: a column's foot has no edges");
  // the outer loop (the largest) first and counter-clockwise, the holes clockwise
  const long outer = outerLoop(area);
  for (std::size_t l = 0; l < foot.loops.size(); ++l)
    if ((static_cast<long>(l) == outer) != (area[l] > 0)) std::reverse(foot.loops[l].begin(), foot.loops[l].end());
  std::rotate(foot.loops.begin(), foot.loops.begin() + outer, foot.loops.begin() + outer + 1);
  try {
    foot.quads = quadsInPolygon(at, foot.loops, server);
  } catch (const Error& e) {  // its message speaks of a gap round a wall's foot
    throw geometryError(std::string("column: its foot was not filled with quads (") + e.what() + ")");
  }
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  for (std::size_t n = 0; n < foot.quads.nodes.size(); ++n) {
    const Vec3 p = foot.quads.nodes[n];
    const Vec3 inPlane = column.origin + p.x() * foot.e1 + p.y() * foot.e2;
    foot.quads.nodes[n] = n < points.size()     ? points[n]
                          : column.footOffPlane ? alongAxisOnto(surface, inPlane, column.axis)
                                                : inPlane;
  }
  return foot;
}

}  // namespace hexlayer
