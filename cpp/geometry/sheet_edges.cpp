#include "geometry/sheet_edges.hpp"

#include <BRepOffset_Analyse.hxx>
#include <BRepOffset_Interval.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>

namespace hexlayer {
namespace {

constexpr double kTangentAngle = 0.5;  // radians: a bend's tangent edges, not a junction

bool isConcave(const BRepOffset_Analyse& edges, const TopoDS_Edge& edge) {
  for (const BRepOffset_Interval& piece : edges.Type(edge))
    if (piece.Type() == ChFiDS_Concave) return true;
  return false;
}

}  // namespace

std::vector<std::pair<int, int>> sheetJoins(const CadSolid& cad) {
  const BRepOffset_Analyse edgeTypes(cad.solid, kTangentAngle);
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  std::vector<std::pair<int, int>> joins;
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> faces;
    for (const TopoDS_Shape& f : edgeFaces(e))
      if (const int i = cad.faces.FindIndex(f) - 1; std::find(faces.begin(), faces.end(), i) == faces.end()) faces.push_back(i);
    if (faces.size() == 2 && !isConcave(edgeTypes, TopoDS::Edge(edgeFaces.FindKey(e))))
      joins.push_back(std::minmax(faces[0], faces[1]));
  }
  return joins;
}

}  // namespace hexlayer
