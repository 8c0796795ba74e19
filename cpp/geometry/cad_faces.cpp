#include "geometry/cad_faces.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <limits>

namespace hexlayer {
namespace {

gp_Pnt point(const Vec3& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

// For every face, the faces that share a vertex with it (itself excluded), ascending.
std::vector<std::vector<int>> vertexNeighbours(const CadSolid& cad) {
  TopTools_IndexedDataMapOfShapeListOfShape facesOfVertex;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_VERTEX, TopAbs_FACE, facesOfVertex);
  std::vector<std::vector<int>> neighbours(cad.faces.Extent());
  for (int v = 1; v <= facesOfVertex.Extent(); ++v) {
    std::vector<int> around;
    for (const TopoDS_Shape& f : facesOfVertex(v)) around.push_back(cad.faces.FindIndex(f) - 1);
    for (int a : around)
      for (int b : around)
        if (a != b && a >= 0 && b >= 0) neighbours[a].push_back(b);
  }
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return neighbours;
}

}  // namespace

CadFaces::CadFaces(const CadSolid& cad) : neighbours_(vertexNeighbours(cad)) {
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    faces_.push_back(TopoDS::Face(cad.faces(f)));
    tolerance_.push_back(BRep_Tool::Tolerance(faces_.back()));
    Bnd_Box box;
    BRepBndLib::AddOptimal(faces_.back(), box, false, false);
    box.Enlarge(tolerance_.back());
    boxes_.push_back(box);
  }
}

double CadFaces::distance(int face, const Vec3& p) const {
  BRepExtrema_DistShapeShape nearest(BRepBuilderAPI_MakeVertex(point(p)).Vertex(), faces_[face]);
  if (!nearest.IsDone() || nearest.NbSolution() == 0) return std::numeric_limits<double>::infinity();
  return nearest.Value();
}

bool CadFaces::lies(int face, const Vec3& p) const {
  return !boxes_[face].IsOut(point(p)) && distance(face, p) < tolerance_[face];
}

FacesAtPoint CadFaces::facesAt(int face, const Vec3& p) const {
  FacesAtPoint at{{face}, distance(face, p)};
  for (int g : neighbours_[face])
    if (lies(g, p)) at.faces.push_back(g);
  return at;
}

}  // namespace hexlayer
