#include "geometry/wall_projector.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/box_tree.hpp"
#include "core/threads.hpp"
#include "geometry/bnd_box.hpp"
#include "geometry/cad_faces.hpp"

namespace hexlayer {

namespace {

int sideIndex(Side side) { return static_cast<int>(side) + 1; }

}  // namespace

WallProjector::WallProjector(const CadSolid& cad, const WallSides& sides, FaceBoxes* boxes)
    : pieceOfFace_(cad.faces.Extent(), -1),
      tools_(threadCount()),
      cadFaces_(std::make_unique<CadFaces>(cad, boxes)),
      probes_(threadCount()) {
  auto edgePiece = [](const TopoDS_Shape& edge, int face, int lateral) {
    Piece w{edge, face, lateral, {}};
    BRepBndLib::AddOptimal(edge, w.box, false, false);  // exact geometry, not the triangulation
    return w;
  };
  auto facePiece = [&](int f) {  // its box measured once, by CadFaces
    return Piece{cad.faces(f + 1), f, -1, cadFaces_->face(f).exactBox};
  };
  std::array<std::vector<int>, 3> faces, rimEdges;
  std::array<std::map<int, std::vector<int>>, 3> rimEdgesOf;
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    pieceOfFace_[f] = static_cast<int>(pieces_.size());
    faces[sideIndex(sides.faces[f].side)].push_back(pieceOfFace_[f]);
    pieces_.push_back(facePiece(f));
  }
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
    if (lateral < 0 || wall < 0) continue;
    const int side = sideIndex(sides.faces[wall].side), id = static_cast<int>(pieces_.size());
    rimEdges[side].push_back(id), rimEdgesOf[side][lateral].push_back(id);
    pieces_.push_back(edgePiece(edgeFaces.FindKey(e), wall, lateral));
  }
  for (int s = 0; s < 3; ++s) {
    faces_[s] = pieceSet(pieces_, faces[s]);
    rimEdges_[s] = pieceSet(pieces_, rimEdges[s]);
    for (auto& [lateral, ids] : rimEdgesOf[s]) rimEdgesOf_[s][lateral].pieces = std::move(ids);
  }
  for (std::vector<Distance>& perThread : tools_) perThread.resize(pieces_.size());
}

WallProjector::~WallProjector() = default;

// [in] all: the pieces; [in] ids: the set's, ascending. Returns the set with its box tree.
WallProjector::PieceSet WallProjector::pieceSet(const std::vector<Piece>& all, std::vector<int> ids) {
  std::vector<Box> boxes;
  for (int i : ids) {
    if (all[i].box.IsVoid()) return {std::move(ids), nullptr};
    boxes.push_back(boxOf(all[i].box));
  }
  return {std::move(ids), std::make_unique<BoxTree>(boxes)};
}

std::optional<FacePoint> WallProjector::project(Side side, const Vec3& p) const {
  return nearest(faces_[sideIndex(side)], p);
}

bool WallProjector::reaches(Side side, const Vec3& p, double reach, const std::vector<char>& leftOut) const {
  const PieceSet& set = faces_[sideIndex(side)];
  CadFaceProbe* own = probe();
  std::unique_ptr<CadFaceProbe> local;  // off the counted threads: one for this query
  if (!own) local = std::make_unique<CadFaceProbe>(*cadFaces_), own = local.get();
  auto near = [&](int i) {
    const int f = pieces_[i].face;
    return !(f < static_cast<int>(leftOut.size()) && leftOut[f]) && mayBeWithin(p, boxOf(pieces_[i].box), reach) &&
           own->distance(f, p) <= reach;
  };
  if (!set.tree) return std::any_of(set.pieces.begin(), set.pieces.end(), near);
  bool found = false;
  set.tree->traverse([&](const Box& b) { return mayBeWithin(p, b, reach); },
                     [&](int k) { return found = near(set.pieces[k]); });
  return found;
}

std::optional<FacePoint> WallProjector::projectOntoFace(int face, const Vec3& p) const {
  const int piece = face >= 0 && face < static_cast<int>(pieceOfFace_.size()) ? pieceOfFace_[face] : -1;
  if (piece < 0) return std::nullopt;
  const std::optional<Hit> hit = distance(piece, BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z())).Vertex());
  return hit ? std::optional<FacePoint>(hit->at) : std::nullopt;
}

std::optional<FacePoint> WallProjector::projectOntoRimEdges(Side side, const Vec3& p) const {
  return nearest(rimEdges_[sideIndex(side)], p);
}

std::optional<FacePoint> WallProjector::projectOntoRimEdgesOf(Side side, int lateral, const Vec3& p) const {
  const std::map<int, PieceSet>& of = rimEdgesOf_[sideIndex(side)];
  const auto it = of.find(lateral);
  if (it == of.end()) return std::nullopt;
  return nearest(it->second, p);
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

// The set's pieces nearest first by their boxes (equal: by id); a piece whose box is farther than the best point so
// far is skipped. With a box tree only the pieces whose boxes are not farther than the first piece's point are
// sorted: a farther one comes after the best point and is skipped as well.
std::optional<FacePoint> WallProjector::nearest(const PieceSet& set, const Vec3& p) const {
  const gp_Pnt point(p.x(), p.y(), p.z());
  Bnd_Box at;
  at.Add(point);
  const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(point);
  std::vector<std::pair<double, int>> order;
  auto all = [&] {
    order.clear();
    for (int i : set.pieces) order.emplace_back(pieces_[i].box.Distance(at), i);
    std::sort(order.begin(), order.end());
    return nearestOf(order, vertex, std::nullopt);
  };
  if (!set.tree || set.pieces.empty()) return all();
  std::pair<double, int> first{std::numeric_limits<double>::infinity(), -1};
  set.tree->traverse([&](const Box& b) { return mayBeWithin(p, b, first.first); },
                     [&](int k) {
                       const std::pair<double, int> d(pieces_[set.pieces[k]].box.Distance(at), set.pieces[k]);
                       first = std::min(first, d);
                       return false;
                     });
  const std::optional<Hit> firstHit = first.second >= 0 ? distance(first.second, vertex) : std::nullopt;
  if (!firstHit) return all();  // no distance to the first piece: every piece, as it always was
  order.push_back(first);
  set.tree->traverse([&](const Box& b) { return mayBeWithin(p, b, firstHit->distance); },
                     [&](int k) {
                       const int i = set.pieces[k];
                       const double d = pieces_[i].box.Distance(at);
                       if (i != first.second && d <= firstHit->distance) order.emplace_back(d, i);
                       return false;
                     });
  std::sort(order.begin(), order.end());
  return nearestOf(order, vertex, std::make_pair(first.second, firstHit));
}

// The pieces of `order` (box distance, piece) in turn until one's box is farther than the best point so far: the
// nearest point. [in] known: a piece whose distance was already asked, and its answer.
std::optional<FacePoint> WallProjector::nearestOf(const std::vector<std::pair<double, int>>& order,
                                                  const TopoDS_Vertex& vertex, const Known& known) const {
  std::optional<FacePoint> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const auto& [boxDistance, i] : order) {
    if (boxDistance > bestDistance) break;
    const std::optional<Hit> hit = known && known->first == i ? known->second : distance(i, vertex);
    if (!hit || hit->distance >= bestDistance) continue;
    bestDistance = hit->distance;
    best = hit->at;
  }
  return best;
}

// BRepExtrema_DistShapeShape from the vertex to the piece, with the piece loaded once per thread (the same bits as
// one built for the query: Perform recomputes all but the piece's sub-shapes and their boxes).
std::optional<WallProjector::Hit> WallProjector::distance(int piece, const TopoDS_Vertex& vertex) const {
  const std::size_t thread = static_cast<std::size_t>(threadIndex());
  if (const std::optional<Hit> foot = faceFoot(piece, vertex, thread)) return foot;
  Distance own;
  Distance& tool = thread < tools_.size() ? tools_[thread][piece] : own;
  if (!tool) {
    tool = std::make_unique<BRepExtrema_DistShapeShape>();
    tool->LoadS2(pieces_[piece].shape);
  }
  tool->LoadS1(vertex);
  tool->Perform();
  if (!tool->IsDone() || tool->NbSolution() == 0) return std::nullopt;
  const gp_Pnt q = tool->PointOnShape2(1);
  return Hit{tool->Value(), FacePoint{Vec3(q.X(), q.Y(), q.Z()), pieces_[piece].face}};
}

// The same answer where it is p's foot point well inside the face, with the face's vertices and edges farther
// (CadFaceProbe::foot), without BRepExtrema; nullopt elsewhere, for an edge, or off the threads' probes.
std::optional<WallProjector::Hit> WallProjector::faceFoot(int piece, const TopoDS_Vertex& vertex,
                                                          std::size_t thread) const {
  const Piece& w = pieces_[piece];
  CadFaceProbe* own = w.shape.ShapeType() == TopAbs_FACE && thread < probes_.size() ? probe() : nullptr;
  if (!own) return std::nullopt;
  const std::optional<std::pair<double, gp_Pnt>> foot = own->foot(w.face, BRep_Tool::Pnt(vertex));
  if (!foot) return std::nullopt;
  const gp_Pnt& q = foot->second;
  return Hit{foot->first, FacePoint{Vec3(q.X(), q.Y(), q.Z()), w.face}};
}

CadFaceProbe* WallProjector::probe() const {
  const std::size_t thread = static_cast<std::size_t>(threadIndex());
  if (thread >= probes_.size()) return nullptr;
  if (!probes_[thread]) probes_[thread] = std::make_unique<CadFaceProbe>(*cadFaces_);
  return probes_[thread].get();
}

}  // namespace hexlayer
