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
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/polygon.hpp"
#include "quadmesh/footprint_insert.hpp"

namespace hexlayer {
namespace {

constexpr double kOnOutline = 1e-2;    // of the quad size: an outline node this near the foot's edges lies on them
constexpr double kGoodStepQuad = 0.6;  // a stepped foot whose worst quad is this good is kept (bestSteppedQuads)
constexpr double kStraight = 1e-9;  // an edge whose chord is this much shorter than it, relative, or less is straight

// One edge of a wire in the wire's order: its curve, run from `first` to `last` (reversed where the wire runs it
// backwards), its length and how many segments it gets.
struct WireEdge {
  BRepAdaptor_Curve curve;
  double first = 0, last = 0, length = 0;
  int segments = 1;
  bool straight = true;
};

std::vector<WireEdge> wireEdges(const TopoDS_Wire& wire, const TopoDS_Face& face, double size) {
  TopTools_IndexedMapOfShape seen, twice;  // a seam runs in the wire both ways
  for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next())
    if (seen.Contains(e.Current()))
      twice.Add(e.Current());
    else
      seen.Add(e.Current());
  std::vector<WireEdge> edges;
  for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
    const TopoDS_Edge& edge = e.Current();
    if (BRep_Tool::Degenerated(edge) || twice.Contains(edge)) continue;  // a cone's apex, its seam: no outline
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

// The loop given `more` segments than it has: the edge with the longest segments gets one more, in turn. [in,out]
// edges; [in] more.
void moreSegments(std::vector<WireEdge>& edges, int more) {
  for (int k = 0; k < more; ++k)
    ++std::max_element(edges.begin(), edges.end(), [](const WireEdge& a, const WireEdge& b) {
        return a.length / a.segments < b.length / b.segments;
      })->segments;
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
  while ((round && count() < kMinRoundLoop) || count() % 2 != 0) moreSegments(edges, 1);
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

// Where p is on the foot along the axis: on its plane, or on its face if it is off its plane. [in] surface: the
// foot's; [in] column, p.
Vec3 downToFoot(const Handle(Geom_Surface) & surface, const ColumnPiece& column, const Vec3& p) {
  return column.footOffPlane ? alongAxisOnto(surface, p, column.axis)
                             : Vec3(p - (p - column.origin).dot(column.axis) * column.axis);
}

// The steps' outlines on the foot (ColumnLedge::steps: where a side rises from a ledge), each divided as the foot's
// loops are and put on the foot along the axis, counter-clockwise in its plane. [in] cad, column, foot (its plane's
// axes), size; [in] more: segments each loop gets beyond those (moreSegments); [in] surface: the foot's; [in,out]
// points, at: each loop's points appended, on the foot and in its plane. Returns the loops. Throws geometryError for a
// ledge that a rising side shares part of a wire of.
std::vector<std::vector<int>> stepLoops(const CadSolid& cad, const ColumnPiece& column, const ColumnFoot& foot,
                                        double size, int more, const Handle(Geom_Surface) & surface,
                                        std::vector<Vec3>& points, std::vector<Eigen::Vector2d>& at) {
  std::vector<std::vector<int>> loops;
  for (const ColumnLedge& ledge : column.ledges) {
    if (ledge.partial)
      throw geometryError(
          "column: a step in it runs out to its side, or round a ledge not level all round, which is not meshed yet");
    const TopoDS_Face& face = TopoDS::Face(cad.faces(ledge.face + 1));
    for (const TopoDS_Wire& wire : ledge.steps) {
      std::vector<WireEdge> edges = wireEdges(wire, face, size);
      evenLoop(edges);
      moreSegments(edges, more);
      std::vector<int> loop;
      std::vector<Eigen::Vector2d> flat;
      for (const Vec3& p : loopPoints(edges)) {
        loop.push_back(static_cast<int>(points.size()));
        points.push_back(downToFoot(surface, column, p)), flat.push_back(onFootPlane(foot, column, p));
        at.push_back(flat.back());
      }
      if (polygonArea(flat) < 0) std::reverse(loop.begin(), loop.end());
      loops.push_back(loop);
    }
  }
  return loops;
}

// The foot's quads where steps divide it: every region between the loops filled on its own (quadsInPolygon), the
// loops' nodes shared. [in] at: every loop's points; [in] loops: the foot's (the outer loop counter-clockwise first,
// the holes clockwise); [in] steps: counter-clockwise; [in] server. Returns the quads, their first at.size() nodes at.
QuadMesh quadsInSteppedFoot(const std::vector<Eigen::Vector2d>& at, const std::vector<std::vector<int>>& loops,
                            const std::vector<std::vector<int>>& steps, ForkServer* server) {
  std::vector<std::vector<int>> all = loops;  // each step once round each way: a region's outer loop and a hole
  for (const std::vector<int>& step : steps) all.push_back(step), all.emplace_back(step.rbegin(), step.rend());
  std::vector<std::vector<Eigen::Vector2d>> flat;
  for (const std::vector<int>& loop : all) {
    flat.emplace_back();
    for (int n : loop) flat.back().push_back(at[n]);
  }
  QuadMesh quads;
  for (const Eigen::Vector2d& p : at) quads.nodes.emplace_back(p.x(), p.y(), 0);
  const auto regions = loopRegions(flat);
  if (!regions) throw geometryError("column: a step's outline lies outside its foot");
  for (const std::vector<std::size_t>& loopsOf : *regions) {
    std::vector<std::vector<int>> region;
    for (std::size_t k : loopsOf) region.push_back(all[k]);
    const QuadMesh q = quadsInPolygon(at, region, server);
    const int first = static_cast<int>(quads.nodes.size()) - static_cast<int>(at.size());
    quads.nodes.insert(quads.nodes.end(), q.nodes.begin() + static_cast<long>(at.size()), q.nodes.end());
    for (std::array<int, 4> quad : q.quads) {
      for (int& n : quad) n += n < static_cast<int>(at.size()) ? 0 : first;
      quads.quads.push_back(quad);
    }
  }
  return quads;
}

// The foot's quads where steps divide it, of several divisions of the steps' loops, tried in turn: as the size asks
// (`steps`), with as many nodes as a loop of the foot has where that is up to twice as many (a ring between loops of
// one count is a row of near squares), and with two and four more (Gmsh can leave triangles between loops of other
// counts): the first whose worst quad is kGoodStepQuad or better, else the one whose worst quad is best. [in] cad,
// column, foot, size, surface: as stepLoops's; [in,out] steps: its loops as the size asks, then the kept division's;
// [in,out] points, at: the foot's loops' points, then those of `steps`, which the kept division's replace; [in] server.
// Throws the first division's error if none fills the foot with quads.
QuadMesh bestSteppedQuads(const CadSolid& cad, const ColumnPiece& column, const ColumnFoot& foot, double size,
                          const Handle(Geom_Surface) & surface, std::vector<std::vector<int>>& steps,
                          std::vector<Vec3>& points, std::vector<Eigen::Vector2d>& at, ForkServer* server) {
  std::size_t stepPoints = 0;
  for (const std::vector<int>& step : steps) stepPoints += step.size();
  const std::size_t footPoints = points.size() - stepPoints;
  const int natural = static_cast<int>(steps.front().size());
  std::vector<int> tries{0};
  for (const std::vector<int>& loop : foot.loops)
    if (const int m = static_cast<int>(loop.size()); m > natural && m <= 2 * natural) tries.push_back(m - natural);
  tries.push_back(2), tries.push_back(4);
  QuadMesh best;
  double bestWorst = -std::numeric_limits<double>::infinity();
  std::vector<Vec3> bestPoints;
  std::vector<Eigen::Vector2d> bestAt;
  std::vector<std::vector<int>> bestSteps;
  std::exception_ptr first;
  std::set<int> tried;
  for (const int more : tries) {
    if (!tried.insert(more).second) continue;
    std::vector<Vec3> p = points;
    std::vector<Eigen::Vector2d> a = at;
    std::vector<std::vector<int>> loops = steps;
    if (more > 0) {
      p.resize(footPoints), a.resize(footPoints);
      loops = stepLoops(cad, column, foot, size, more, surface, p, a);
    }
    try {
      QuadMesh q = quadsInSteppedFoot(a, foot.loops, loops, server);
      if (const double worst = worstInPlane(q.nodes, q.quads); worst > bestWorst)
        best = std::move(q), bestWorst = worst, bestPoints = std::move(p), bestAt = std::move(a),
        bestSteps = std::move(loops);
      if (bestWorst >= kGoodStepQuad) break;
    } catch (const Error&) {
      if (!first) first = std::current_exception();
    }
  }
  if (best.quads.empty()) std::rethrow_exception(first);
  points = std::move(bestPoints), at = std::move(bestAt), steps = std::move(bestSteps);
  return best;
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
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  foot.steps = stepLoops(cad, column, foot, size, 0, surface, points, at);
  try {
    foot.quads = foot.steps.empty()
                     ? quadsInPolygon(at, foot.loops, server)
                     : bestSteppedQuads(cad, column, foot, size, surface, foot.steps, points, at, server);
  } catch (const Error& e) {  // its message speaks of a gap round a wall's foot
    throw geometryError(std::string("column: its foot was not filled with quads (") + e.what() + ")");
  }
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
