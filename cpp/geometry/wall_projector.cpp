#include "geometry/wall_projector.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <limits>

namespace hexlayer {

namespace {

int sideIndex(Side side) { return static_cast<int>(side) + 1; }

}  // namespace

WallProjector::WallProjector(const CadSolid& cad, const WallSides& sides) {
  auto piece = [](const TopoDS_Shape& shape, int face, int lateral = -1) {
    Piece w{shape, face, lateral, {}};
    BRepBndLib::AddOptimal(shape, w.box, false, false);  // exact geometry, not the triangulation
    return w;
  };
  for (int f = 0; f < cad.faces.Extent(); ++f)
    faces_[sideIndex(sides.faces[f].side)].push_back(piece(cad.faces(f + 1), f));
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    int wall = -1, lateral = -1;
    for (const TopoDS_Shape& face : edgeFaces(e)) {
      const int f = cad.faces.FindIndex(face) - 1;
      if (sides.faces[f].side == Side::Lateral)
        lateral = f;
      else if (wall < 0)
        wall = f;
    }
    if (lateral >= 0 && wall >= 0)
      rimEdges_[sideIndex(sides.faces[wall].side)].push_back(piece(edgeFaces.FindKey(e), wall, lateral));
  }
}

std::optional<FacePoint> WallProjector::project(Side side, const Vec3& p) const {
  return nearest(faces_[sideIndex(side)], p);
}

std::optional<FacePoint> WallProjector::projectOntoFace(int face, const Vec3& p) const {
  for (const std::vector<Piece>& side : faces_)
    for (const Piece& piece : side)
      if (piece.face == face) return nearest({piece}, p);
  return std::nullopt;
}

std::optional<FacePoint> WallProjector::projectOntoRimEdges(Side side, const Vec3& p) const {
  return nearest(rimEdges_[sideIndex(side)], p);
}

std::optional<FacePoint> WallProjector::projectOntoRimEdgesOf(Side side, int lateral, const Vec3& p) const {
  std::vector<Piece> of;
  for (const Piece& edge : rimEdges_[sideIndex(side)])
    if (edge.lateral == lateral) of.push_back(edge);
  return nearest(of, p);
}

std::optional<Vec3> WallProjector::rimMiddle(const Vec3& p) const {
  const std::optional<FacePoint> rim = project(Side::Lateral, p);
  if (!rim) return std::nullopt;
  std::optional<FacePoint> top = projectOntoRimEdgesOf(Side::Top, rim->face, p);
  std::optional<FacePoint> bottom = projectOntoRimEdgesOf(Side::Bottom, rim->face, p);
  if (!top) top = projectOntoRimEdges(Side::Top, p);
  if (!bottom) bottom = projectOntoRimEdges(Side::Bottom, p);
  if (!top || !bottom) return std::nullopt;
  return Vec3(0.5 * (top->point + bottom->point));
}

// Pieces nearest first by their boxes; a piece whose box is farther than the best point so far is skipped.
std::optional<FacePoint> WallProjector::nearest(const std::vector<Piece>& faces, const Vec3& p) {
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
    BRepExtrema_DistShapeShape distance(vertex, faces[i].shape);
    if (!distance.IsDone() || distance.NbSolution() == 0 || distance.Value() >= bestDistance) continue;
    bestDistance = distance.Value();
    const gp_Pnt q = distance.PointOnShape2(1);
    best = FacePoint{Vec3(q.X(), q.Y(), q.Z()), faces[i].face};
  }
  return best;
}

}  // namespace hexlayer
