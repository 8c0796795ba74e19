#include "geometry/sheet_edges.hpp"

#include <BRepOffset_Analyse.hxx>
#include <BRepOffset_Interval.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include <algorithm>

namespace hexlayer {
namespace {

constexpr double kTangentAngle = 0.5;  // radians: a bend's tangent edges, not a junction

// Whether some piece of the edge is of this kind.
bool hasKind(const BRepOffset_Analyse& edges, const TopoDS_Edge& edge, ChFiDS_TypeOfConcavity kind) {
  for (const BRepOffset_Interval& piece : edges.Type(edge))
    if (piece.Type() == kind) return true;
  return false;
}

}  // namespace

std::vector<SheetJoin> sheetJoins(const CadSolid& cad) {
  const BRepOffset_Analyse edgeTypes(cad.solid, kTangentAngle);
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  std::vector<SheetJoin> joins;
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> faces;
    for (const TopoDS_Shape& f : edgeFaces(e))
      if (const int i = cad.faces.FindIndex(f) - 1; std::find(faces.begin(), faces.end(), i) == faces.end())
        faces.push_back(i);
    const TopoDS_Edge edge = TopoDS::Edge(edgeFaces.FindKey(e));
    if (faces.size() != 2 || hasKind(edgeTypes, edge, ChFiDS_Concave)) continue;
    const auto [a, b] = std::minmax(faces[0], faces[1]);
    joins.push_back({a, b, !hasKind(edgeTypes, edge, ChFiDS_Convex)});
  }
  return joins;
}

}  // namespace hexlayer
