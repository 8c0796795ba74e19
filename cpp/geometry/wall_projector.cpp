#include "geometry/wall_projector.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <limits>

namespace hexlayer {

WallProjector::WallProjector(const CadSolid& cad, const WallSides& sides) {
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    WallFace w{TopoDS::Face(cad.faces(f + 1)), f, {}};
    BRepBndLib::AddOptimal(w.face, w.box, false, false);  // exact geometry, not the triangulation
    faces_[static_cast<int>(sides.faces[f].side) + 1].push_back(w);
  }
}

// Faces nearest first by their boxes; a face whose box is farther than the best point so far is skipped.
std::optional<FacePoint> WallProjector::project(Side side, const Vec3& p) const {
  const std::vector<WallFace>& faces = faces_[static_cast<int>(side) + 1];
  const gp_Pnt point(p.x(), p.y(), p.z());
  Bnd_Box at;
  at.Add(point);
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < faces.size(); ++i) order.emplace_back(faces[i].box.Distance(at), i);
  std::sort(order.begin(), order.end());
  const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(point);
  std::optional<FacePoint> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const auto& [boxDistance, i] : order) {
    if (boxDistance > bestDistance) break;
    BRepExtrema_DistShapeShape nearest(vertex, faces[i].face);
    if (!nearest.IsDone() || nearest.NbSolution() == 0 || nearest.Value() >= bestDistance) continue;
    bestDistance = nearest.Value();
    const gp_Pnt q = nearest.PointOnShape2(1);
    best = FacePoint{Vec3(q.X(), q.Y(), q.Z()), faces[i].index};
  }
  return best;
}

}  // namespace hexlayer
