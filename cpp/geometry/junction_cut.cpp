#include "geometry/junction_cut.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Plane.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <ShapeFix_Face.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/union_find.hpp"
#include "geometry/sheet_edges.hpp"

namespace hexlayer {
namespace {

constexpr double kRunsOn = 0.999;  // cosine: a closing segment this near an open foot chain's direction continues it
// Cosine: a segment closing a foot chain on itself turns back along it where it leaves an end at more than 120 degrees
// to the chain's direction there (a line or a shallow arc across a narrow face: a sliver of no or little area).
constexpr double kTurnsBack = -0.5;
constexpr double kOppositeWalls = 0.9;  // cosine: a sheet's two walls at its foot face opposite ways
constexpr int kSeamSamples = 4;         // points per foot edge, less one, that the seam of its surface keeps away from
constexpr double kOnBoth = 100;         // x kJoin: a gap's closing edge along a curved wall also lies on the base's
constexpr double kJoin = 1e-7;          // times the part's diagonal: ends of foot edges this close are one point
constexpr double kRimTurn = 1e-6;       // sine: rims running on from a foot's two ends meet if they turn more
constexpr double kPlanesMeet = 1e-3;    // three planes whose normals' triple product is smaller meet in no point

double areaOf(const TopoDS_Shape& face) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  return props.Mass();
}

// Per edge of the solid, its faces.
TopTools_IndexedDataMapOfShapeListOfShape facesOfEdges(const CadSolid& cad) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  return edgeFaces;
}

// Per face (0-based), the sheet whose bend it is inside, -1 if none: a lateral face of no sheet (not a column's side)
// that meets two or more walls of the first sheet it meets (walls standing on it aside), all on one side, each in a
// concave edge (a chamfer or round filling a bend's inside corner), where a rim face meets walls on both sides, and
// meets no other sheet's wall in a convex edge (a rim face of that sheet: a boss's top in a box's corner). [in]
// cad, sides, sheets; [in] concave: footEdges(cad, sides).
std::vector<int> bendSheetOfFaces(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets,
                                  const std::vector<FacePairEdge>& concave) {
  const int n = static_cast<int>(sides.faces.size());
  const std::vector<int> wallSheet = wallSheetOfFaces(sheets, sides.faces.size());
  std::set<int> concaveEdge;
  for (const FacePairEdge& c : concave) concaveEdge.insert(c.edge);
  struct Meeting {
    int wall;
    Side side;
    bool concave;
  };
  std::vector<std::map<int, std::vector<Meeting>>> bySheet(n);  // per lateral face: per sheet, its walls met
  const TopTools_IndexedDataMapOfShapeListOfShape edgeFaces = facesOfEdges(cad);
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> faces;
    for (const TopoDS_Shape& f : edgeFaces(e)) faces.push_back(cad.faces.FindIndex(f) - 1);
    const bool isConcave = concaveEdge.count(cad.edges.FindIndex(edgeFaces.FindKey(e)) - 1) > 0;
    for (int a : faces)
      for (int b : faces)
        if (sides.faces[a].side == Side::Lateral && wallSheet[b] >= 0)
          bySheet[a][wallSheet[b]].push_back({b, sides.faces[b].side, isConcave});
  }
  std::vector<int> bendSheet(n, -1);
  for (int a = 0; a < n; ++a) {
    if (bySheet[a].empty() || wallSheet[a] >= 0) continue;  // no lateral face of a sheet (a column's side)
    const auto& [sheet, met] = *bySheet[a].begin();
    const bool rimOfAnother = std::any_of(std::next(bySheet[a].begin()), bySheet[a].end(), [](const auto& other) {
      return std::any_of(other.second.begin(), other.second.end(), [](const Meeting& m) { return !m.concave; });
    });
    if (rimOfAnother) continue;  // a standing sheet's rim face against the walls (a boss's top in a box's corner)
    std::set<int> walls;
    for (const Meeting& m : met) walls.insert(m.wall);
    if (walls.size() >= 2 &&
        std::all_of(met.begin(), met.end(), [&](const Meeting& m) { return m.concave && m.side == met.front().side; }))
      bendSheet[a] = sheet;
  }
  return bendSheet;
}

// Per face (0-based), the sheet it belongs to: a sheet's walls, the faces inside its bends (bendSheet: a wall may stand
// across one, its foot on it too) and the rim faces beside a standing sheet's walls (a rib's end face); -1 for the
// other rim faces. [in] cad, sides, sheets; [in] bendSheet: bendSheetOfFaces'.
std::vector<int> sheetOfFaces(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets,
                              const std::vector<int>& bendSheet) {
  const std::vector<int> sheet = wallSheetOfFaces(sheets, sides.faces.size());
  const TopTools_IndexedDataMapOfShapeListOfShape edgeFaces = facesOfEdges(cad);
  std::vector<int> rimSheet(sheet);
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> faces;
    for (const TopoDS_Shape& f : edgeFaces(e)) faces.push_back(cad.faces.FindIndex(f) - 1);
    for (int a : faces)
      for (int b : faces)
        if (sides.faces[a].side == Side::Lateral && sheet[b] > 0 && bendSheet[a] < 0) rimSheet[a] = sheet[b];
  }
  for (std::size_t a = 0; a < bendSheet.size(); ++a)
    if (bendSheet[a] >= 0) rimSheet[a] = bendSheet[a];
  return rimSheet;
}

// What the feet are found from, worked out once for every standing sheet.
struct Junctions {
  const CadSolid& cad;
  const WallSides& sides;
  const std::vector<Sheet>& sheets;
  std::vector<int> bendSheet;                           // bendSheetOfFaces
  std::vector<int> sheetOf;                             // sheetOfFaces
  std::vector<FacePairEdge> concave;                    // footEdges
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;  // facesOfEdges
};

// Whether p lies on the surface within `tolerance`. [in] surface, p, tolerance.
bool liesOn(const Handle(Geom_Surface) & surface, const gp_Pnt& p, double tolerance) {
  ShapeAnalysis_Surface on(surface);
  on.ValueOfUV(p, tolerance);
  return on.Gap() <= tolerance;
}

// Whether the edge lies on the surface: its ends and middle within `tolerance` of it. [in] edge, surface, tolerance.
bool edgeLiesOn(const TopoDS_Edge& edge, const Handle(Geom_Surface) & surface, double tolerance) {
  const BRepAdaptor_Curve curve(edge);
  const double a = curve.FirstParameter(), b = curve.LastParameter();
  return liesOn(surface, curve.Value(a), tolerance) && liesOn(surface, curve.Value(0.5 * (a + b)), tolerance) &&
         liesOn(surface, curve.Value(b), tolerance);
}

// The edges of standing sheet s's wall faces with rim faces that lie on base wall face `base`'s surface: where a
// wall stands flush with the base's rim (a box's lower end wall butting on its side walls, its outer face on the
// side walls' ends), its foot runs to that rim along them (an edge of two such faces twice). [in] j, s, base.
std::vector<TopoDS_Edge> flushFootEdges(const Junctions& j, int s, int base) {
  if (j.sheets[s].column) return {};  // no walls: its foot is its concave edges
  const double tolerance = kJoin * j.cad.diagonal;
  const TopoDS_Face& face = TopoDS::Face(j.cad.faces(base + 1));
  const std::optional<gp_Pln> plane = planeOf(face, tolerance);  // a plane written as a B-spline ends at the face
  const Handle(Geom_Surface) surface = plane ? new Geom_Plane(*plane) : BRep_Tool::Surface(face);
  std::vector<TopoDS_Edge> out;
  for (int f : j.sheets[s].faces)
    for (TopExp_Explorer it(j.cad.faces(f + 1), TopAbs_EDGE); it.More(); it.Next()) {
      const TopoDS_Edge edge = TopoDS::Edge(it.Current());
      const TopTools_ListOfShape& faces = j.edgeFaces.FindFromKey(edge);
      const bool byRim = std::any_of(faces.cbegin(), faces.cend(), [&](const TopoDS_Shape& g) {
        return j.sides.faces[j.cad.faces.FindIndex(g) - 1].side == Side::Lateral;
      });
      if (byRim && edgeLiesOn(edge, surface, tolerance)) out.push_back(edge);
    }
  return out;
}

// Per base wall face, the concave edges between it and the faces of standing sheet s. A sheet stands on the earlier
// (larger) sheets it meets in concave edges: the first sheet, or a wall standing on it (a rib's end on another rib,
// a partition's on a wall), so that the sheets stand on each other in a tree.
std::map<int, std::vector<TopoDS_Edge>> footEdges(const Junctions& j, int s) {
  std::map<int, std::vector<TopoDS_Edge>> edges;
  for (const FacePairEdge& c : j.concave)
    for (const auto& [base, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (j.sheetOf[base] >= 0 && j.sheetOf[base] < s &&
          (j.sides.faces[base].side != Side::Lateral || j.bendSheet[base] >= 0) && j.sheetOf[other] == s)
        edges[base].push_back(TopoDS::Edge(j.cad.edges(c.edge + 1)));
  for (auto& [base, on] : edges) {
    const std::vector<TopoDS_Edge> flush = flushFootEdges(j, s, base);
    on.insert(on.end(), flush.begin(), flush.end());
  }
  return edges;
}

gp_Pnt endPoint(const TopoDS_Wire& wire, bool first) {
  TopoDS_Vertex a, b;
  TopExp::Vertices(wire, a, b);
  return BRep_Tool::Pnt(first ? a : b);
}

// The direction in which the edge leaves through its end `at`: its tangent there, pointing away from it; none if `at`
// is no end of it. [in] edge, at, tolerance.
std::optional<gp_Vec> leaving(const TopoDS_Edge& edge, const gp_Pnt& at, double tolerance) {
  const BRepAdaptor_Curve curve(edge);
  for (const double t : {curve.FirstParameter(), curve.LastParameter()}) {
    gp_Pnt p;
    gp_Vec d;
    curve.D1(t, p, d);
    if (p.Distance(at) <= tolerance && d.Magnitude() > 0)
      return t == curve.FirstParameter() ? -d.Normalized() : d.Normalized();
  }
  return std::nullopt;
}

// The direction a wire leaves through its end `at`: the tangent of its edge there, pointing away from the edge.
gp_Vec outward(const TopoDS_Wire& wire, const gp_Pnt& at, double tolerance) {
  for (TopExp_Explorer it(wire, TopAbs_EDGE); it.More(); it.Next())
    if (const std::optional<gp_Vec> d = leaving(TopoDS::Edge(it.Current()), at, tolerance)) return *d;
  return gp_Vec(0, 0, 0);
}

// The edge from a to b on the base wall's surface: a straight segment on a plane, a segment of the surface's
// parameter plane on any other (a rib's foot closed along a shell's ruling or its rim).
TopoDS_Edge edgeOnSurface(const Handle(Geom_Surface) & surface, const gp_Pnt& a, const gp_Pnt& b, double tolerance) {
  if (GeomAdaptor_Surface(surface).GetType() == GeomAbs_Plane) return BRepBuilderAPI_MakeEdge(a, b).Edge();
  ShapeAnalysis_Surface uv(surface);
  const gp_Pnt2d ua = uv.ValueOfUV(a, tolerance);
  gp_Pnt2d ub = uv.ValueOfUV(b, tolerance);
  // on a periodic surface (a boss's cylinder), the short way round: b's (u, v) within half a period of a's
  if (surface->IsUPeriodic()) ub.SetX(ub.X() + surface->UPeriod() * std::round((ua.X() - ub.X()) / surface->UPeriod()));
  if (surface->IsVPeriodic()) ub.SetY(ub.Y() + surface->VPeriod() * std::round((ua.Y() - ub.Y()) / surface->VPeriod()));
  if (ua.Distance(ub) <= gp::Resolution()) return BRepBuilderAPI_MakeEdge(a, b).Edge();
  TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(GCE2d_MakeSegment(ua, ub).Value(), surface).Edge();
  BRepLib::BuildCurves3d(edge);
  return edge;
}

// What a foot chain's gaps are closed on: the base wall's surface, the sheet's feet on other base surfaces and the
// curved walls of the sheet and of those it stands on.
struct ClosingSurfaces {
  Handle(Geom_Surface) base;
  std::vector<Handle(Geom_Surface)> feet;   // the sheet's other feet's surfaces
  std::vector<Handle(Geom_Surface)> along;  // the curved walls
};

// The edge from a to b along `other` if a and b lie on it and the edge's middle lies on `base` too, else none.
std::optional<TopoDS_Edge> edgeOnBoth(const Handle(Geom_Surface) & base, const Handle(Geom_Surface) & other,
                                      const gp_Pnt& a, const gp_Pnt& b, double tolerance) {
  if (!liesOn(other, a, tolerance) || !liesOn(other, b, tolerance)) return std::nullopt;
  const TopoDS_Edge edge = edgeOnSurface(other, a, b, tolerance);
  const BRepAdaptor_Curve curve(edge);
  if (!liesOn(base, curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter())), kOnBoth * tolerance))
    return std::nullopt;
  return edge;
}

// The point where three planes meet, none if two are parallel or nearly.
std::optional<gp_Pnt> planesMeet(const gp_Pln& p, const gp_Pln& q, const gp_Pln& r) {
  const gp_XYZ n1 = p.Axis().Direction().XYZ(), n2 = q.Axis().Direction().XYZ(), n3 = r.Axis().Direction().XYZ();
  const double det = n1.Dot(n2.Crossed(n3));
  if (std::abs(det) < kPlanesMeet) return std::nullopt;
  const double d1 = n1.Dot(p.Location().XYZ()), d2 = n2.Dot(q.Location().XYZ()), d3 = n3.Dot(r.Location().XYZ());
  return gp_Pnt((d1 * n2.Crossed(n3) + d2 * n3.Crossed(n1) + d3 * n1.Crossed(n2)) / det);
}

// The edges closing a foot chain's gap from a to b on the base wall's surface, where the feet meet on one curve:
// along another foot of the sheet if a and b both lie on it (a boss merged into a box's wall: its foot on the floor
// closed along its foot on the wall, not round its own cylinder inside the wall); on planes, round the corner where
// two other feet's planes, one through a and one through b, meet the base's (a boss filling a box's corner: its foot
// on the floor runs along both walls' feet to the corner); along a curved wall if a and b lie on it (a rib's foot on a
// plate ending on a boss's foot circle, not on its chord); else edgeOnSurface on the base's. [in] on; [in] a, b.
std::vector<TopoDS_Edge> closingEdges(const ClosingSurfaces& on, const gp_Pnt& a, const gp_Pnt& b, double tolerance) {
  for (const Handle(Geom_Surface) & other : on.feet)
    if (const std::optional<TopoDS_Edge> edge = edgeOnBoth(on.base, other, a, b, tolerance)) return {*edge};
  const Handle(Geom_Plane) base = Handle(Geom_Plane)::DownCast(on.base);
  for (const Handle(Geom_Surface) & p : on.feet)
    for (const Handle(Geom_Surface) & q : on.feet) {
      const Handle(Geom_Plane) pa = Handle(Geom_Plane)::DownCast(p), qb = Handle(Geom_Plane)::DownCast(q);
      if (base.IsNull() || pa.IsNull() || qb.IsNull() || p == q || !liesOn(p, a, tolerance) || !liesOn(q, b, tolerance))
        continue;
      if (const std::optional<gp_Pnt> corner = planesMeet(base->Pln(), pa->Pln(), qb->Pln());
          corner && corner->Distance(a) > tolerance && corner->Distance(b) > tolerance)
        return {BRepBuilderAPI_MakeEdge(a, *corner).Edge(), BRepBuilderAPI_MakeEdge(*corner, b).Edge()};
    }
  for (const Handle(Geom_Surface) & other : on.along)
    if (const std::optional<TopoDS_Edge> edge = edgeOnBoth(on.base, other, a, b, tolerance)) return {*edge};
  return {edgeOnSurface(on.base, a, b, tolerance)};
}

// The direction in which the sheet's rim runs on past p: the tangent at p of the rim edge (`rims`) ending there,
// pointing away from it; none if p is no end of one. [in] rims, p, tolerance.
std::optional<gp_Vec> rimRunsOn(const std::vector<TopoDS_Edge>& rims, const gp_Pnt& p, double tolerance) {
  for (const TopoDS_Edge& edge : rims)
    if (const std::optional<gp_Vec> d = leaving(edge, p, tolerance)) return d;
  return std::nullopt;
}

// The way from a to b round a corner of the base's rim that a standing piece covers (a post at a plate's corner, its
// sides flush with the plate's: its foot's two ends lie on the two sides): straight on from a along the rim there to
// where the rim from b, run on, meets it, then to b. None unless rims run on from both a and b and their lines meet
// ahead of both (within `tolerance`); the ends are then joined straight. [in] rims: the base face's edges with the
// sheet's rim faces (convex); [in] a, b, tolerance.
std::optional<std::array<TopoDS_Edge, 2>> roundRimCorner(const std::vector<TopoDS_Edge>& rims, const gp_Pnt& a,
                                                         const gp_Pnt& b, double tolerance) {
  const std::optional<gp_Vec> da = rimRunsOn(rims, a, tolerance), db = rimRunsOn(rims, b, tolerance);
  if (!da || !db) return std::nullopt;
  const gp_Vec ab(a, b), n = da->Crossed(*db);
  if (n.Magnitude() < kRimTurn) return std::nullopt;  // parallel: the straight line is the rim's
  // a + s da = b + t db: s and t from the cross products with n (the lines lie in one plane)
  const double s = ab.Crossed(*db).Dot(n) / n.SquareMagnitude(), t = ab.Crossed(*da).Dot(n) / n.SquareMagnitude();
  const gp_Pnt corner = a.Translated(s * *da);
  if (!(s > tolerance && t > tolerance) || corner.Distance(b.Translated(t * *db)) > tolerance) return std::nullopt;
  return std::array<TopoDS_Edge, 2>{BRepBuilderAPI_MakeEdge(a, corner).Edge(),
                                    BRepBuilderAPI_MakeEdge(corner, b).Edge()};
}

// The foot edges joined into closed wires. Open chains are closed by segments on the base wall's surface between
// their free ends: first an end and the end it runs on to (a rib's foot continued under a rib crossing it), then
// the nearest free ends (a foot running to the wall's edge, a partition's two edges between walls), round the corner
// of the base's rim where the foot covers one (roundRimCorner, on a plane base; rims: the base face's rim edges). A
// chain's two ends are joined to each other only where no other end is left to join, if the segment turns back along
// it (a wall standing across a narrow face of the base, a bend's chamfer or round: its two sides' edges on it are
// lines or arcs shorter than the wall is thick, each closed on itself a sliver).
std::vector<TopoDS_Wire> closedWires(const std::vector<TopoDS_Edge>& edges, const ClosingSurfaces& on,
                                     const std::vector<TopoDS_Edge>& rims, double tolerance) {
  Handle(TopTools_HSequenceOfShape) in = new TopTools_HSequenceOfShape, wires;
  for (const TopoDS_Edge& e : edges) in->Append(e);
  ShapeAnalysis_FreeBounds::ConnectEdgesToWires(in, tolerance, false, wires);
  std::vector<gp_Pnt> ends;
  std::vector<gp_Vec> out;
  std::vector<int> chain;  // per end: its wire
  for (int i = 1; i <= wires->Length(); ++i) {
    const TopoDS_Wire w = TopoDS::Wire(wires->Value(i));
    if (BRep_Tool::IsClosed(w) || endPoint(w, true).Distance(endPoint(w, false)) <= tolerance) continue;
    for (const bool first : {true, false})
      ends.push_back(endPoint(w, first)), out.push_back(outward(w, endPoint(w, first), tolerance)), chain.push_back(i);
  }
  std::vector<char> used(ends.size(), 0);
  auto runsOn = [&](std::size_t i, std::size_t j) {  // the segment from end i to end j continues both
    const gp_Vec d(ends[i], ends[j]);
    return d.Magnitude() > tolerance && out[i].Dot(d.Normalized()) > kRunsOn && out[j].Dot(-d.Normalized()) > kRunsOn;
  };
  auto turnsBack = [&](std::size_t i, std::size_t j) {  // the segment from end i to end j closes a chain back on itself
    const gp_Vec d(ends[i], ends[j]);
    return chain[i] == chain[j] && d.Magnitude() > tolerance &&
           (out[i].Dot(d.Normalized()) < kTurnsBack || out[j].Dot(-d.Normalized()) < kTurnsBack);
  };
  enum class Pass { Continuing, NotBack, Any };
  const bool plane = GeomAdaptor_Surface(on.base).GetType() == GeomAbs_Plane;
  for (const Pass pass : {Pass::Continuing, Pass::NotBack, Pass::Any})
    for (;;) {  // nearest pairs first
      const bool continuing = pass == Pass::Continuing;
      std::size_t bi = 0, bj = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < ends.size(); ++i)
        for (std::size_t j = i + 1; j < ends.size(); ++j)
          if (!used[i] && !used[j] && (!continuing || runsOn(i, j)) && (pass != Pass::NotBack || !turnsBack(i, j)) &&
              ends[i].Distance(ends[j]) < best)
            best = ends[i].Distance(ends[j]), bi = i, bj = j;
      if (!std::isfinite(best)) break;
      used[bi] = used[bj] = 1;
      if (const auto round = continuing || !plane ? std::nullopt : roundRimCorner(rims, ends[bi], ends[bj], tolerance))
        in->Append((*round)[0]), in->Append((*round)[1]);
      else
        for (const TopoDS_Edge& e : closingEdges(on, ends[bi], ends[bj], tolerance)) in->Append(e);
    }
  Handle(TopTools_HSequenceOfShape) closed;
  ShapeAnalysis_FreeBounds::ConnectEdgesToWires(in, tolerance, false, closed);
  std::vector<TopoDS_Wire> result;
  for (int i = 1; i <= closed->Length(); ++i) result.push_back(TopoDS::Wire(closed->Value(i)));
  return result;
}

// The foot edges of standing sheet s grouped by the surface of the base wall they lie on: one plane (a rib running
// across a plate splits its top into two faces), or one curved face's surface.
struct SurfaceEdges {
  Handle(Geom_Surface) surface;
  std::optional<gp_Pln> plane;  // if the surface is planar
  int face;                     // the first base face on it
  int base;                     // its sheet
  std::vector<TopoDS_Edge> edges;
};

// Whether the face lies on `surface` (a rib's foot splits a shell's wall into faces of one cylinder, each its own
// surface in the file): a 3 x 3 grid of points over the face's parameter box lies on it.
bool sameSurface(const Handle(Geom_Surface) & surface, const TopoDS_Face& face, double tolerance) {
  ShapeAnalysis_Surface on(surface);
  const BRepAdaptor_Surface other(face);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  for (int i = 0; i <= 2; ++i)
    for (int k = 0; k <= 2; ++k) {
      on.ValueOfUV(other.Value(u0 + 0.5 * i * (u1 - u0), v0 + 0.5 * k * (v1 - v0)), tolerance);
      if (on.Gap() > tolerance) return false;
    }
  return true;
}

// The surface of a curved wall face that a foot lies on or runs along: the cylinder a B-spline or Bézier face is (a
// boss written as a B-spline is trimmed to its face: where a rib covers the boss there is no surface, the cylinder
// goes on round), else the face's own surface. [in] face, tolerance.
Handle(Geom_Surface) curvedSurface(const TopoDS_Shape& face, double tolerance) {
  const Handle(Geom_Surface)& own = BRep_Tool::Surface(TopoDS::Face(face));
  if (!Handle(Geom_ElementarySurface)::DownCast(own).IsNull()) return own;
  if (const std::optional<gp_Cylinder> cylinder = cylinderOf(face, tolerance))
    return new Geom_CylindricalSurface(*cylinder);
  return own;
}

// A B-spline or Bézier surface extended by `length` past each of its four boundaries (a shell's wall written as
// B-splines, one patch per face, ends where the wall standing on it begins: its foot lies beyond); any other
// surface as it is (planes, cylinders and their trimmed pieces reach on).
Handle(Geom_Surface) extendedSurface(const Handle(Geom_Surface) & surface, double length) {
  if (surface->DynamicType() != STANDARD_TYPE(Geom_BSplineSurface) &&
      surface->DynamicType() != STANDARD_TYPE(Geom_BezierSurface))
    return surface;
  Handle(Geom_BoundedSurface) extended = Handle(Geom_BoundedSurface)::DownCast(surface->Copy());
  for (const bool inU : {true, false})  // not round a periodic direction (a boss's cylinder in metres): it has no end
    if (!(inU ? surface->IsUPeriodic() : surface->IsVPeriodic()))
      for (const bool after : {true, false}) GeomLib::ExtendSurfByLength(extended, length, 1, inU, after);
  return extended;
}

// A periodic surface with its seam moved into the middle of the widest gap between the edges' points, where a foot
// face across the seam would not cut the solid: an elementary one (a boss's cylinder or cone) turned about its axis,
// a periodic B-spline (the same in metres) with its u origin at the knot nearest to there. Any other surface as it
// is. [in] surface; [in] edges: the foot edges on it.
Handle(Geom_Surface)
    seamAwayFrom(const Handle(Geom_Surface) & surface, const std::vector<TopoDS_Edge>& edges, double tolerance) {
  const Handle(Geom_ElementarySurface) elementary = Handle(Geom_ElementarySurface)::DownCast(surface);
  const Handle(Geom_BSplineSurface) spline = Handle(Geom_BSplineSurface)::DownCast(surface);
  if ((elementary.IsNull() && spline.IsNull()) || !surface->IsUPeriodic()) return surface;
  const double period = surface->UPeriod(), first = spline.IsNull() ? 0 : spline->UKnot(1);
  auto wrapped = [&](double u) { return first + std::fmod(std::fmod(u - first, period) + period, period); };
  ShapeAnalysis_Surface uv(surface);
  std::vector<double> u;
  for (const TopoDS_Edge& e : edges) {
    const BRepAdaptor_Curve curve(e);
    for (int k = 0; k <= kSeamSamples; ++k) {
      const double t = curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * k / kSeamSamples;
      u.push_back(wrapped(uv.ValueOfUV(curve.Value(t), tolerance).X()));
    }
  }
  if (u.empty()) return surface;
  std::sort(u.begin(), u.end());
  double gap = u.front() + period - u.back(), middle = wrapped(u.back() + 0.5 * gap);  // the gap across the seam first
  for (std::size_t i = 0; i + 1 < u.size(); ++i)
    if (u[i + 1] - u[i] > gap) gap = u[i + 1] - u[i], middle = u[i] + 0.5 * gap;
  if (!elementary.IsNull())
    return Handle(Geom_Surface)::DownCast(surface->Rotated(elementary->Position().Axis(), middle - first));
  Handle(Geom_BSplineSurface) moved = Handle(Geom_BSplineSurface)::DownCast(spline->Copy());
  int nearest = 1;
  for (int k = 1; k <= moved->NbUKnots(); ++k)
    if (std::abs(moved->UKnot(k) - middle) < std::abs(moved->UKnot(nearest) - middle)) nearest = k;
  moved->SetUOrigin(nearest);
  return moved;
}

std::vector<SurfaceEdges> footEdgesBySurface(const Junctions& j, int s) {
  const double tolerance = kJoin * j.cad.diagonal;
  std::vector<SurfaceEdges> surfaces;
  const std::map<int, std::vector<TopoDS_Edge>> edgesOn = footEdges(j, s);
  Bnd_Box box;  // round every foot edge
  for (const auto& [base, edges] : edgesOn)
    for (const TopoDS_Edge& e : edges) BRepBndLib::Add(e, box);
  const double reach = box.IsVoid() ? 0 : std::sqrt(box.SquareExtent());
  for (const auto& [base, edges] : edgesOn) {
    const TopoDS_Face& face = TopoDS::Face(j.cad.faces(base + 1));
    const std::optional<gp_Pln> plane = planeOf(face, tolerance);
    const Handle(Geom_Surface) surface =
        plane ? new Geom_Plane(*plane) : extendedSurface(curvedSurface(face, tolerance), reach);
    const int sheet = j.sheetOf[base];
    auto same = [&](const SurfaceEdges& p) {
      if (p.base != sheet) return false;
      if (!plane || !p.plane) return !plane && !p.plane && sameSurface(p.surface, face, tolerance);
      return samePlane(*p.plane, *plane, tolerance);
    };
    auto at = std::find_if(surfaces.begin(), surfaces.end(), same);
    if (at == surfaces.end()) at = surfaces.insert(surfaces.end(), SurfaceEdges{surface, plane, base, sheet, {}});
    for (const TopoDS_Edge& e : edges)  // a flush foot edge comes once per face of the plane and of the wall
      if (std::none_of(at->edges.begin(), at->edges.end(), [&](const TopoDS_Edge& f) { return f.IsSame(e); }))
        at->edges.push_back(e);
  }
  for (SurfaceEdges& on : surfaces)
    if (!on.plane) on.surface = seamAwayFrom(on.surface, on.edges, tolerance);
  return surfaces;
}

// The face on the surface bounded by `wire`, its missing curves on the surface added, its wire turned to bound
// the finite side; none if it cannot be made.
std::optional<TopoDS_Face> faceOn(const SurfaceEdges& on, const TopoDS_Wire& wire, double tolerance) {
  if (on.plane) {
    BRepBuilderAPI_MakeFace face(*on.plane, wire, true);
    if (!face.IsDone()) return std::nullopt;
    return face.Face();
  }
  for (const TopoDS_Wire& w : {wire, TopoDS::Wire(wire.Reversed())}) {
    BRepBuilderAPI_MakeFace face(on.surface, w, true);
    if (!face.IsDone()) continue;
    ShapeFix_Face fix(face.Face());
    fix.SetPrecision(tolerance);
    fix.FixPeriodicDegeneratedMode() = 0;  // OpenCASCADE 7.6's crashes on a cone's face cut round (a drafted boss)
    fix.Perform();
    if (areaOf(fix.Face()) > 0 && BRepCheck_Analyzer(fix.Face()).IsValid()) return fix.Face();
  }
  return std::nullopt;
}

// Whether sheet s meets rim (lateral) faces in concave edges (a post standing on the edge of a wall) but no wall.
bool standsOnRimFace(const Junctions& j, int s) {
  return std::any_of(j.concave.begin(), j.concave.end(), [&](const FacePairEdge& c) {
    const bool aIn = std::count(j.sheets[s].faces.begin(), j.sheets[s].faces.end(), c.a) > 0;
    const bool bIn = std::count(j.sheets[s].faces.begin(), j.sheets[s].faces.end(), c.b) > 0;
    const int other = aIn ? c.b : c.a;
    return aIn != bIn && j.sides.faces[other].side == Side::Lateral;
  });
}

// A note naming a thickness step where sheet s goes on from a thicker wall past a step in its faces that the sweep's
// hexes do not take (thicknessSteps at any width of the step's side), else "". [in] j, s.
std::string stepNote(const Junctions& j, int s) {
  const std::vector<int>& own = j.sheets[s].faces;
  for (const auto& [a, b] : thicknessSteps(j.cad, j.sides, std::numeric_limits<double>::infinity()))
    if ((std::count(own.begin(), own.end(), a) > 0) != (std::count(own.begin(), own.end(), b) > 0))
      return " (a thinner wall going on from a thicker one's rim: a thickness step is meshed where the step's side "
             "runs all along the rim and is no wider than the thinner wall)";
  return "";
}

// The edges of base face `face` with the sheet's rim faces: its edges with lateral faces that are not concave.
// [in] j, face.
std::vector<TopoDS_Edge> rimEdges(const Junctions& j, int face) {
  std::set<int> concave;
  for (const FacePairEdge& c : j.concave) concave.insert(c.edge);
  std::vector<TopoDS_Edge> rims;
  for (TopExp_Explorer e(j.cad.faces(face + 1), TopAbs_EDGE); e.More(); e.Next()) {
    const TopTools_ListOfShape& faces = j.edgeFaces.FindFromKey(e.Current());
    const bool byRim = std::any_of(faces.cbegin(), faces.cend(), [&](const TopoDS_Shape& g) {
      return j.sides.faces[j.cad.faces.FindIndex(g) - 1].side == Side::Lateral;
    });
    if (byRim && !concave.count(j.cad.edges.FindIndex(e.Current()) - 1)) rims.push_back(TopoDS::Edge(e.Current()));
  }
  return rims;
}

// The feet of standing sheet s: faces on the surfaces of the base's walls under it, bounded by its foot edges.
std::vector<Foot> footFaces(const Junctions& j, int s) {
  std::vector<Foot> feet;
  const double tolerance = kJoin * j.cad.diagonal;
  const std::vector<SurfaceEdges> surfaces = footEdgesBySurface(j, s);
  std::vector<Handle(Geom_Surface)> along;  // the curved walls of the sheet and of those it stands on
  for (int f : j.sheets[s].faces)
    if (!planeOf(j.cad.faces(f + 1), tolerance)) along.push_back(curvedSurface(j.cad.faces(f + 1), tolerance));
  for (const SurfaceEdges& on : surfaces)
    if (!on.plane) along.push_back(on.surface);
  for (const SurfaceEdges& on : surfaces) {
    ClosingSurfaces closing{on.surface, {}, along};
    for (const SurfaceEdges& other : surfaces)
      if (&other != &on) closing.feet.push_back(other.surface);
    for (const TopoDS_Wire& wire : closedWires(on.edges, closing, rimEdges(j, on.face), tolerance))
      if (const std::optional<TopoDS_Face> face = faceOn(on, wire, tolerance))
        if (const double area = areaOf(*face); area > tolerance * tolerance)  // not edges there and back (no area)
          feet.push_back({s, on.base, on.face, *face, area});
  }
  if (feet.empty() && standsOnRimFace(j, s))
    throw geometryError("T-junction: the sheet at " + sheetPlace(j.cad, j.sheets[s]) +
                        " stands on the edge (a rim face) of another sheet, not on its wall" + stepNote(j, s) +
                        ", which is not meshed yet");
  if (feet.empty())
    throw geometryError("T-junction: no foot found for the sheet at " + sheetPlace(j.cad, j.sheets[s]) +
                        " on the sheet it stands on");
  return feet;
}

// The images of `face` in the split result: itself if the split left it whole, else its pieces.
std::vector<TopoDS_Shape> imagesOf(BRepAlgoAPI_Splitter& split, const TopoDS_Shape& face) {
  const TopTools_ListOfShape& modified = split.Modified(face);
  if (modified.IsEmpty()) return {face};
  return std::vector<TopoDS_Shape>(modified.cbegin(), modified.cend());
}

// Per piece, per face of it, the face of `cad` it is or is a piece of (-1: a foot).
std::vector<std::vector<int>> faceOrigins(const CadSolid& cad, BRepAlgoAPI_Splitter& split,
                                          const std::vector<TopoDS_Solid>& pieces) {
  std::vector<std::vector<int>> origin;
  for (const TopoDS_Solid& piece : pieces) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(piece, TopAbs_FACE, faces);
    origin.emplace_back(faces.Extent(), -1);
    for (int f = 1; f <= cad.faces.Extent(); ++f)
      for (const TopoDS_Shape& image : imagesOf(split, cad.faces(f)))
        if (const int at = faces.FindIndex(image); at > 0) origin.back()[at - 1] = f - 1;
  }
  return origin;
}

// A sheet's wall planes (unit normal with its first non-zero coordinate positive, offset), or none if a wall is
// not planar.
std::vector<std::pair<Vec3, double>> wallPlanes(const CadSolid& cad, const Sheet& sheet) {
  std::vector<std::pair<Vec3, double>> planes;
  const double tolerance = kJoin * cad.diagonal;
  for (int f : sheet.faces) {
    const std::optional<gp_Pln> plane = planeOf(cad.faces(f + 1), tolerance);
    if (!plane) return {};
    const gp_XYZ d = plane->Axis().Direction().XYZ(), o = plane->Location().XYZ();
    Vec3 n(d.X(), d.Y(), d.Z());
    const int first = std::abs(n.x()) > 1e-9 ? 0 : std::abs(n.y()) > 1e-9 ? 1 : 2;
    if (n[first] < 0) n = -n;
    const double offset = n.dot(Vec3(o.X(), o.Y(), o.Z()));
    const bool known = std::any_of(planes.begin(), planes.end(), [&](const auto& p) {
      return p.first.dot(n) > 1 - 1e-9 && std::abs(p.second - offset) <= tolerance;
    });
    if (!known) planes.emplace_back(n, offset);
  }
  return planes;
}

bool samePlanes(const std::vector<std::pair<Vec3, double>>& a, const std::vector<std::pair<Vec3, double>>& b,
                double tolerance) {
  if (a.empty() || a.size() != b.size()) return false;
  for (const auto& p : a)
    if (std::none_of(b.begin(), b.end(), [&](const auto& q) {
          return p.first.dot(q.first) > 1 - 1e-9 && std::abs(p.second - q.second) <= tolerance;
        }))
      return false;
  return true;
}

// Whether two of the sheets `crossers` have their walls on the same planes: the other rib is in segments too, cut by
// the two sheets' rib (ribs of one height crossing). A lower rib leaves the higher one whole, its walls' faces round
// its feet: the lower rib's segments then stand on both sides of it, each a T.
bool crossedInSegments(const std::set<int>& crossers, const std::vector<std::vector<std::pair<Vec3, double>>>& planes,
                       double tolerance) {
  for (auto x = crossers.begin(); x != crossers.end(); ++x)
    for (auto y = std::next(x); y != crossers.end(); ++y)
      if (samePlanes(planes[*x], planes[*y], tolerance)) return true;
  return false;
}

// Whether sheet s meets sheet b's walls in concave edges with both of its own walls (two of its faces there face
// opposite ways): s's thickness ends on b's wall, so s stands on b (a rib's end on another rib's side), whichever
// is larger. [in] normals: per (s, b), the outward normals of s's wall faces at its concave edges with b's walls.
bool bothWallsOn(const std::map<std::pair<int, int>, std::vector<Vec3>>& normals, int s, int b) {
  const auto at = normals.find({s, b});
  if (at == normals.end()) return false;
  const std::vector<Vec3>& n = at->second;
  for (std::size_t x = 0; x < n.size(); ++x)
    for (std::size_t y = x + 1; y < n.size(); ++y)
      if (n[x].dot(n[y]) < -kOppositeWalls) return true;
  return false;
}

// The sheets reordered so that each standing sheet comes after the standing sheets it stands on (bothWallsOn one
// way only), else in the order given: the first sheet stays first. [in] cad, sides; [in] concave: footEdges(cad,
// sides); [in] sheets: by decreasing area.
std::vector<Sheet> standingOrder(const CadSolid& cad, const WallSides& sides, const std::vector<FacePairEdge>& concave,
                                 std::vector<Sheet> sheets) {
  const std::vector<int> sheetOf = sheetOfFaces(cad, sides, sheets, bendSheetOfFaces(cad, sides, sheets, concave));
  std::map<std::pair<int, int>, std::vector<Vec3>> normals;  // (own sheet, other sheet) -> own walls' normals there
  for (const FacePairEdge& c : concave)
    for (const auto& [own, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (sheetOf[own] > 0 && sheetOf[other] > 0 && sheetOf[own] != sheetOf[other] &&
          sides.faces[own].side != Side::Lateral && sides.faces[other].side != Side::Lateral)
        normals[{sheetOf[own], sheetOf[other]}].push_back(
            normalAtEdge(TopoDS::Face(cad.faces(own + 1)), TopoDS::Edge(cad.edges(c.edge + 1))));
  const int n = static_cast<int>(sheets.size());
  std::vector<std::set<int>> under(n);  // the standing sheets each stands on
  for (const auto& [pair, unused] : normals)
    if (const auto [s, b] = pair; bothWallsOn(normals, s, b) && !bothWallsOn(normals, b, s)) under[s].insert(b);
  std::vector<int> order;
  std::vector<char> placed(n, 0);
  while (static_cast<int>(order.size()) < n) {  // the first sheet whose bases are all placed, again and again
    int next = -1;
    for (int s = 0; s < n && next < 0; ++s)
      if (!placed[s] && std::all_of(under[s].begin(), under[s].end(), [&](int b) { return placed[b] != 0; })) next = s;
    for (int s = 0; s < n && next < 0; ++s)  // sheets standing on each other in a ring: the rest as given
      if (!placed[s]) next = s;
    placed[next] = 1, order.push_back(next);
  }
  std::vector<Sheet> ordered;
  for (int s : order) ordered.push_back(std::move(sheets[s]));
  return ordered;
}

// The edges where a standing wall's foot may be: the concave ones, and the folded joins that are no knife edge (a
// crevice: a boss merged 0.2-0.3 into a wall, or drafted, meets its face in an air wedge of 20-28 degrees, an edge
// BRepOffset_Analyse takes for convex; sheet_edges.hpp SheetJoin::folded). [in] cad, sides. Returns them, concave
// set.
std::vector<FacePairEdge> footEdges(const CadSolid& cad, const WallSides& sides) {
  std::vector<FacePairEdge> feet = concaveEdges(cad);
  for (const SheetJoin& j : sides.sheetJoins)
    if (j.folded && sides.faces[j.a].opposite != j.b && sides.faces[j.b].opposite != j.a)
      feet.push_back({j.edge, j.a, j.b, true});
  return feet;
}

}  // namespace

std::vector<Sheet> mergeCrossingRibs(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets) {
  const int n = static_cast<int>(sheets.size());
  const std::vector<FacePairEdge> concave = footEdges(cad, sides);
  const std::vector<int> faceSheet = sheetOfFaces(cad, sides, sheets, bendSheetOfFaces(cad, sides, sheets, concave));
  std::vector<std::set<int>> meets(n);  // the standing sheets each meets in a concave edge
  for (const FacePairEdge& c : concave)
    if (const int a = faceSheet[c.a], b = faceSheet[c.b]; a > 0 && b > 0 && a != b)
      meets[a].insert(b), meets[b].insert(a);
  std::vector<std::vector<std::pair<Vec3, double>>> planes(n);  // none for a column: it crosses nothing
  for (int s = 1; s < n; ++s)
    if (!sheets[s].column) planes[s] = wallPlanes(cad, sheets[s]);
  struct Crossing {
    int a, b;
    std::set<int> crossers;  // the other rib's segments both meet
    double area;
  };
  std::vector<Crossing> crossings;
  for (int a = 1; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (!samePlanes(planes[a], planes[b], kJoin * cad.diagonal)) continue;
      Crossing c{a, b, {}, sheets[a].area + sheets[b].area};
      std::set_intersection(meets[a].begin(), meets[a].end(), meets[b].begin(), meets[b].end(),
                            std::inserter(c.crossers, c.crossers.end()));
      if (crossedInSegments(c.crossers, planes, kJoin * cad.diagonal)) crossings.push_back(std::move(c));
    }
  std::stable_sort(crossings.begin(), crossings.end(),
                   [](const Crossing& x, const Crossing& y) { return x.area > y.area; });
  UnionFind uf(n);
  std::set<int> through, crossed;  // segments of ribs run through, of ribs crossed
  for (const Crossing& c : crossings) {
    if (crossed.count(c.a) || crossed.count(c.b) ||
        std::any_of(c.crossers.begin(), c.crossers.end(), [&](int x) { return through.count(x) > 0; }))
      continue;
    uf.unite(c.a, c.b), through.insert({c.a, c.b}), crossed.insert(c.crossers.begin(), c.crossers.end());
  }
  std::map<int, std::vector<int>> group;  // root -> sheets
  for (int s = 0; s < n; ++s) group[uf.find(s)].push_back(s);
  std::vector<Sheet> merged;
  for (const auto& [root, ribs] : group) {
    if (ribs.size() == 1) {  // as found (a column keeps its flag and volume)
      merged.push_back(sheets[root]);
      continue;
    }
    std::vector<int> f;
    for (int s : ribs) f.insert(f.end(), sheets[s].faces.begin(), sheets[s].faces.end());
    std::sort(f.begin(), f.end());
    merged.push_back(sheetOf(cad, sides, f));
  }
  std::stable_sort(merged.begin(), merged.end(), [](const Sheet& x, const Sheet& y) { return x.area > y.area; });
  return standingOrder(cad, sides, concave, std::move(merged));
}

// Each sheet's pieces among the solids of the cut: the solid holding most of (the images of) its wall faces' area is
// its piece, cut.pieces[s] (not the one holding its first face: a face's place in the CAD's list is the exporter's, and
// a blind bore's bottom, a wall face of the base, may go with the boss's piece); a solid holding no earlier sheet's
// piece but an image of one of s's wall faces is a further piece of s (appended). Throws geometryError if a solid is no
// sheet's or a sheet has no solid. [in] cad, sheets, split, solids; [out] cut: pieces, sheetOf.
void piecesOfSheets(const CadSolid& cad, const std::vector<Sheet>& sheets, BRepAlgoAPI_Splitter& split,
                    const std::vector<TopoDS_Solid>& solids, JunctionCut& cut) {
  std::vector<TopTools_IndexedMapOfShape> faces(solids.size());
  for (std::size_t k = 0; k < solids.size(); ++k) TopExp::MapShapes(solids[k], TopAbs_FACE, faces[k]);
  auto holding = [&](const TopoDS_Shape& face) {
    for (std::size_t k = 0; k < solids.size(); ++k)
      if (faces[k].Contains(face)) return static_cast<int>(k);
    return -1;
  };
  std::vector<int> owner(solids.size(), -1);
  for (std::size_t s = 0; s < sheets.size(); ++s) {
    std::vector<double> held(solids.size(), 0.0);  // the sheet's wall area each solid holds
    for (int f : sheets[s].faces)
      for (const TopoDS_Shape& image : imagesOf(split, cad.faces(f + 1)))
        if (const int k = holding(image); k >= 0) held[k] += areaOf(image);
    const auto most = std::max_element(held.begin(), held.end());
    const int piece = most == held.end() || *most <= 0 ? -1 : static_cast<int>(most - held.begin());
    if (piece < 0 || owner[piece] >= 0)
      throw geometryError("T-junction: no piece holds the sheet at " + sheetPlace(cad, sheets[s]) + " after the cut");
    owner[piece] = static_cast<int>(s);
    cut.pieces.push_back(solids[piece]), cut.sheetOf.push_back(static_cast<int>(s));
  }
  for (std::size_t s = 1; s < sheets.size(); ++s)
    for (int f : sheets[s].faces)
      for (const TopoDS_Shape& image : imagesOf(split, cad.faces(f + 1)))
        if (const int k = holding(image); k >= 0 && owner[k] < 0) {
          owner[k] = static_cast<int>(s);
          cut.pieces.push_back(solids[k]), cut.sheetOf.push_back(static_cast<int>(s));
        }
  if (cut.pieces.size() != solids.size())
    throw geometryError("T-junction: cutting the sheets off the one they stand on gave " +
                        std::to_string(solids.size()) + " pieces for " + std::to_string(sheets.size()) + " sheets, " +
                        std::to_string(solids.size() - cut.pieces.size()) + " of them no sheet's");
}

JunctionCut cutAtJunctions(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets) {
  if (sheets.size() < 2) {  // one piece: the solid, each face its own origin
    std::vector<int> same(cad.faces.Extent());
    std::iota(same.begin(), same.end(), 0);
    return {{cad.solid}, {0}, {}, {same}};
  }
  const std::vector<FacePairEdge> concave = footEdges(cad, sides);
  std::vector<int> bendSheet = bendSheetOfFaces(cad, sides, sheets, concave);
  std::vector<int> sheetOf = sheetOfFaces(cad, sides, sheets, bendSheet);
  const Junctions junctions{cad, sides, sheets, std::move(bendSheet), std::move(sheetOf), concave, facesOfEdges(cad)};
  JunctionCut cut;
  TopTools_ListOfShape arguments, tools;
  arguments.Append(cad.solid);
  std::vector<Foot> cutters;
  for (int s = 1; s < static_cast<int>(sheets.size()); ++s)
    for (Foot& f : footFaces(junctions, s)) tools.Append(f.face), cutters.push_back(std::move(f));
  BRepAlgoAPI_Splitter split;
  split.SetArguments(arguments);
  split.SetTools(tools);
  split.SetFuzzyValue(kJoin * cad.diagonal);
  split.Build();
  std::vector<TopoDS_Solid> solids;
  for (TopExp_Explorer it(split.Shape(), TopAbs_SOLID); it.More(); it.Next())
    solids.push_back(TopoDS::Solid(it.Current()));
  piecesOfSheets(cad, sheets, split, solids, cut);
  // The feet as they are in the pieces: the pieces of each cutting face that the base's piece shares with a piece of
  // its sheet (a foot across a bore keeps the ring round it).
  std::vector<TopTools_IndexedMapOfShape> pieceFaces(cut.pieces.size());
  for (std::size_t p = 0; p < cut.pieces.size(); ++p) TopExp::MapShapes(cut.pieces[p], TopAbs_FACE, pieceFaces[p]);
  for (const Foot& f : cutters) {
    for (const TopoDS_Shape& image : imagesOf(split, f.face))
      for (std::size_t p = 0; p < cut.pieces.size(); ++p)
        if (cut.sheetOf[p] == f.sheet && pieceFaces[f.base].Contains(image) && pieceFaces[p].Contains(image))
          cut.feet.push_back({static_cast<int>(p), f.base, f.baseFace, TopoDS::Face(image), areaOf(image)});
  }
  for (int s = 1; s < static_cast<int>(sheets.size()); ++s)  // a cutter may leave none (one on a face), a sheet not
    if (std::none_of(cut.feet.begin(), cut.feet.end(), [&](const Foot& f) { return cut.sheetOf[f.sheet] == s; }))
      throw geometryError("T-junction: the foot of the sheet at " + sheetPlace(cad, sheets[s]) +
                          " is not a face of both pieces after the cut");
  cut.faceOrigin = faceOrigins(cad, split, cut.pieces);
  return cut;
}

}  // namespace hexlayer
