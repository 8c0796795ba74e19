#include "geometry/sheet_edges.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepOffset_Analyse.hxx>
#include <BRepOffset_Interval.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

namespace hexlayer {
namespace {

constexpr double kTangentAngle = 0.5;  // radians: a bend's tangent edges, not a junction

// Whether some piece of the edge is of this kind.
bool hasKind(const BRepOffset_Analyse& edges, const TopoDS_Edge& edge, ChFiDS_TypeOfConcavity kind) {
  for (const BRepOffset_Interval& piece : edges.Type(edge))
    if (piece.Type() == kind) return true;
  return false;
}

// Calls visit(edge, a, b, kinds) for every edge between two distinct faces a < b (0-based), with the edge's
// BRepOffset_Analyse kinds.
template <class Visit>
void forEachFacePairEdge(const CadSolid& cad, Visit&& visit) {
  const BRepOffset_Analyse edgeTypes(cad.solid, kTangentAngle);
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> faces;
    for (const TopoDS_Shape& f : edgeFaces(e))
      if (const int i = cad.faces.FindIndex(f) - 1; std::find(faces.begin(), faces.end(), i) == faces.end())
        faces.push_back(i);
    if (faces.size() != 2) continue;
    const TopoDS_Edge edge = TopoDS::Edge(edgeFaces.FindKey(e));
    const auto [a, b] = std::minmax(faces[0], faces[1]);
    visit(cad.edges.FindIndex(edge) - 1, a, b,
          [&](ChFiDS_TypeOfConcavity kind) { return hasKind(edgeTypes, edge, kind); });
  }
}

constexpr double kSameCurvature = 0.02;  // relative to the larger of the two; and 1e-6 / the part's diagonal

// The point of `face`'s parameter plane at parameter t of `edge` (its pcurve on the face); none without a pcurve.
std::optional<gp_Pnt2d> uvAt(const TopoDS_Face& face, const TopoDS_Edge& edge, double t) {
  double first, last;
  const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
  if (pcurve.IsNull()) return std::nullopt;
  return pcurve->Value(t);
}

// The mean curvature along the face's outward normal and the Gaussian curvature of `face` at parameter t of `edge`
// (its pcurve on the face); none where undefined. [in] face, edge, t.
std::optional<std::pair<double, double>> curvaturesAt(const TopoDS_Face& face, const TopoDS_Edge& edge, double t) {
  const std::optional<gp_Pnt2d> uv = uvAt(face, edge, t);
  if (!uv) return std::nullopt;
  const BRepAdaptor_Surface surface(face);
  BRepLProp_SLProps props(surface, uv->X(), uv->Y(), 2, Precision::Confusion());
  if (!props.IsCurvatureDefined()) return std::nullopt;
  const double outward = face.Orientation() == TopAbs_REVERSED ? -1 : 1;
  return std::make_pair(outward * props.MeanCurvature(), props.GaussianCurvature());
}

// The outward unit normal of `face` at parameter t of `edge` (its pcurve on the face); none where undefined.
std::optional<gp_Dir> normalAt(const TopoDS_Face& face, const TopoDS_Edge& edge, double t) {
  const std::optional<gp_Pnt2d> uv = uvAt(face, edge, t);
  if (!uv) return std::nullopt;
  const BRepAdaptor_Surface surface(face);
  BRepLProp_SLProps props(surface, uv->X(), uv->Y(), 1, Precision::Confusion());
  if (!props.IsNormalDefined()) return std::nullopt;
  return face.Orientation() == TopAbs_REVERSED ? props.Normal().Reversed() : props.Normal();
}

// Whether the normals of faces a and b at the middle of their edge are within kTangentAngle of opposite.
// [in] cad; [in] a, b, edge: 0-based.
bool foldedAt(const CadSolid& cad, int a, int b, int edge) {
  const TopoDS_Edge& e = TopoDS::Edge(cad.edges(edge + 1));
  double first, last;
  BRep_Tool::Range(e, first, last);
  const auto na = normalAt(TopoDS::Face(cad.faces(a + 1)), e, 0.5 * (first + last));
  const auto nb = normalAt(TopoDS::Face(cad.faces(b + 1)), e, 0.5 * (first + last));
  return na && nb && na->Angle(*nb) > M_PI - kTangentAngle;
}

}  // namespace

bool oneSurfaceAcross(const CadSolid& cad, const SheetJoin& j) {
  if (!j.smooth || j.edge < 0) return false;
  const TopoDS_Edge& edge = TopoDS::Edge(cad.edges(j.edge + 1));
  double first, last;
  BRep_Tool::Range(edge, first, last);
  const double t = 0.5 * (first + last);
  const auto a = curvaturesAt(TopoDS::Face(cad.faces(j.a + 1)), edge, t);
  const auto b = curvaturesAt(TopoDS::Face(cad.faces(j.b + 1)), edge, t);
  if (!a || !b) return false;
  const double floor = 1e-6 / cad.diagonal;
  auto same = [&](double x, double y, double least) {
    return std::abs(x - y) <= kSameCurvature * std::max(std::abs(x), std::abs(y)) + least;
  };
  return same(a->first, b->first, floor) && same(a->second, b->second, floor * floor);
}

std::vector<SheetJoin> sheetJoins(const CadSolid& cad) {
  std::vector<SheetJoin> joins;
  forEachFacePairEdge(cad, [&](int edge, int a, int b, auto has) {
    if (!has(ChFiDS_Concave)) {
      const bool smooth = !has(ChFiDS_Convex);
      joins.push_back({a, b, smooth, edge, !smooth && foldedAt(cad, a, b, edge)});
    }
  });
  return joins;
}

std::vector<FacePairEdge> concaveEdges(const CadSolid& cad) {
  std::vector<FacePairEdge> concave;
  forEachFacePairEdge(cad, [&](int edge, int a, int b, auto has) {
    if (has(ChFiDS_Concave)) concave.push_back({edge, a, b, true});
  });
  return concave;
}

std::vector<FacePairEdge> sharpEdges(const CadSolid& cad) {
  std::vector<FacePairEdge> sharp;
  forEachFacePairEdge(cad, [&](int edge, int a, int b, auto has) {
    if (has(ChFiDS_Concave) || has(ChFiDS_Convex)) sharp.push_back({edge, a, b, has(ChFiDS_Concave)});
  });
  return sharp;
}

std::vector<std::set<int>> faceNeighbours(const CadSolid& cad) {
  std::vector<std::set<int>> next(cad.faces.Extent());
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= edgeFaces.Extent(); ++e)
    for (const TopoDS_Shape& a : edgeFaces(e))
      for (const TopoDS_Shape& b : edgeFaces(e))
        if (const int i = cad.faces.FindIndex(a) - 1, j = cad.faces.FindIndex(b) - 1; i != j) next[i].insert(j);
  return next;
}

}  // namespace hexlayer
