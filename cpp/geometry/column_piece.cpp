#include "geometry/column_piece.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexlayer {
namespace {

constexpr double kPlanarFoot = 1e-7;  // times the part's diagonal: a foot this near a plane is one
// 1 - cosine: a plane foot tilted less from square to the axis is square to it
constexpr double kSquareFoot = 1e-9;
// The column's axis is its sides' direction where that is more than kSameAxis (radians) off the foot's normal (a pin
// drawn straight on a sloping or curved wall); its sides lean at most kMaxSideLean from square to the foot's normal;
// the foot's normals are within kMaxFootTilt of the axis.
constexpr double kSameAxis = 1.0 * M_PI / 180, kMaxSideLean = M_PI / 6, kMaxFootTilt = M_PI / 4;
// Of the greatest eigenvalue: a second least eigenvalue of the sides' normals' n n^T this small leaves the axis free.
constexpr double kFreeAxis = 1e-3;
// Of the face's greatest |du x dv| at its triangulation's nodes: a node whose is no greater lies at a pole.
constexpr double kPole = 1e-6;

// The range of n . axis over the face's outward normals at the nodes of its triangulation (BRepMesh's, at their
// (u, v): a B-spline face's triangles can lean far from its surface), and its farthest point along the axis; nullopt
// for a face without a triangulation.
struct FaceReach {
  double lowest = std::numeric_limits<double>::infinity(), highest = -std::numeric_limits<double>::infinity();
  double top = -std::numeric_limits<double>::infinity();
};
std::optional<FaceReach> faceReach(const TopoDS_Face& face, const Vec3& axis) {
  TopLoc_Location at;
  const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, at);
  if (t.IsNull() || !t->HasUVNodes() || t->NbNodes() == 0) return std::nullopt;
  FaceReach r;
  std::vector<Vec3> normal(t->NbNodes());
  std::vector<double> length(t->NbNodes());
  for (int i = 1; i <= t->NbNodes(); ++i) {
    const gp_Pnt p = t->Node(i).Transformed(at.Transformation());
    r.top = std::max(r.top, Vec3(p.X(), p.Y(), p.Z()).dot(axis));
    normal[i - 1] = outwardNormal(face, t->UVNode(i).X(), t->UVNode(i).Y(), &length[i - 1]);
  }
  const double pole = kPole * *std::max_element(length.begin(), length.end());
  for (int i = 0; i < t->NbNodes(); ++i)
    if (length[i] > pole)  // not at a pole (a cone's apex): no normal there, or one turned over just past it
      r.lowest = std::min(r.lowest, normal[i].dot(axis)), r.highest = std::max(r.highest, normal[i].dot(axis));
  if (r.lowest > r.highest) return std::nullopt;
  return r;
}

// The sum of n n^T over the normals (at their triangulation's nodes) of the faces but the foot whose normals all lie
// within `lean` (radians) of square to the foot's normal. [in] cad, foot, footNormal, lean.
Eigen::Matrix3d sideNormals(const CadSolid& cad, int foot, const Vec3& footNormal, double leanAngle) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  const double lean = std::sin(leanAngle);
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    if (f == foot) continue;
    const TopoDS_Face& face = TopoDS::Face(cad.faces(f + 1));
    const std::optional<FaceReach> r = faceReach(face, footNormal);
    if (!r || r->lowest < -lean || r->highest > lean) continue;
    TopLoc_Location at;
    const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, at);
    for (int i = 1; i <= t->NbNodes(); ++i) {
      const Vec3 n = outwardNormal(face, t->UVNode(i).X(), t->UVNode(i).Y());
      sum += n * n.transpose();
    }
  }
  return sum;
}

// The direction most square to the normals whose sum of n n^T is `sum`: its least eigenvector; nullopt if there are
// none, or if they leave it free to turn (the two least eigenvalues both about 0: the normals of two parallel faces).
std::optional<Vec3> leastDirection(const Eigen::Matrix3d& sum) {
  if (sum.isZero()) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(sum);  // eigenvalues ascending
  if (eigen.eigenvalues()(1) <= kFreeAxis * eigen.eigenvalues()(2)) return std::nullopt;
  return Vec3(eigen.eigenvectors().col(0).normalized());
}

// The direction the column's sides run in: of the faces whose normals all lie within kMaxSideLean of square to the
// foot's normal (or, if none do or they leave it free, within kMaxFootTilt: a pin or post upright on a wall sloping 30
// to 45 degrees), the direction most square to all their normals (leastDirection: a cylinder's or a prism's axis),
// turned towards the foot's normal; the foot's normal itself if that is within kSameAxis of it, or none is found.
// [in] cad, foot; [in] footNormal.
Vec3 sidesAxis(const CadSolid& cad, int foot, const Vec3& footNormal) {
  std::optional<Vec3> axis = leastDirection(sideNormals(cad, foot, footNormal, kMaxSideLean));
  if (!axis) axis = leastDirection(sideNormals(cad, foot, footNormal, kMaxFootTilt));
  if (!axis) return footNormal;
  if (axis->dot(footNormal) < 0) *axis = -*axis;
  return axis->dot(footNormal) >= std::cos(kSameAxis) ? footNormal : *axis;
}

// The heights over the foot's plane of the edge's ends and middle: their least and greatest. [in] c, edge.
std::pair<double, double> edgeHeights(const ColumnPiece& c, const TopoDS_Shape& edge) {
  const BRepAdaptor_Curve curve(TopoDS::Edge(edge));
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const double t : {0.0, 0.5, 1.0}) {
    const double h =
        (toVec(curve.Value((1 - t) * curve.FirstParameter() + t * curve.LastParameter())) - c.origin).dot(c.axis);
    low = std::min(low, h), high = std::max(high, h);
  }
  return {low, high};
}

// The column's ledges (ColumnPiece::ledges), lowest first. [in] cad; [in] c: its foot, axis, origin, sides, caps and
// height found; [in] top: per face, its farthest point along the axis over the foot's plane.
std::vector<ColumnLedge> findLedges(const CadSolid& cad, const ColumnPiece& c, const std::vector<double>& top) {
  TopTools_IndexedDataMapOfShapeListOfShape faceOfEdge;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, faceOfEdge);
  const double drop = kLedgeDrop * c.height;
  auto rises = [&](int f, const TopoDS_Shape& edge, double height) {  // a side beside it reaches higher
    for (const TopoDS_Shape& other : faceOfEdge.FindFromKey(edge))
      if (const int o = cad.faces.FindIndex(other) - 1;
          o != f && std::find(c.sides.begin(), c.sides.end(), o) != c.sides.end() && top[o] > height + drop)
        return true;
    return false;
  };
  auto isSeam = [&](int f, const TopoDS_Shape& edge) {  // the face's own seam: no other face beside it
    const TopTools_ListOfShape& faces = faceOfEdge.FindFromKey(edge);
    return std::all_of(faces.begin(), faces.end(),
                       [&](const TopoDS_Shape& other) { return cad.faces.FindIndex(other) - 1 == f; });
  };
  std::vector<ColumnLedge> ledges;
  for (int f : c.caps) {
    const TopoDS_Face& face = TopoDS::Face(cad.faces(f + 1));
    ColumnLedge ledge{f, -std::numeric_limits<double>::infinity(), {}, false};
    double low = std::numeric_limits<double>::infinity();  // the steps' edges' least height
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
      int edges = 0, rising = 0;
      double wireLow = std::numeric_limits<double>::infinity(), wireHigh = -wireLow;
      for (TopExp_Explorer e(w.Current(), TopAbs_EDGE); e.More(); e.Next()) {
        if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current())) || isSeam(f, e.Current())) continue;  // a cone's apex
        const auto [a, b] = edgeHeights(c, e.Current());
        ++edges, rising += rises(f, e.Current(), b), wireLow = std::min(wireLow, a), wireHigh = std::max(wireHigh, b);
      }
      if (rising == edges && wireHigh - wireLow <= drop)  // a step round a level outline
        ledge.steps.push_back(TopoDS::Wire(w.Current())), low = std::min(low, wireLow),
                                                          ledge.height = std::max(ledge.height, wireHigh);
      else
        ledge.partial |= rising > 0;
    }
    // a ledge's steps at one height, no higher than its top's lowest edge (it stays under its tier's top)
    if (ledge.steps.empty() && !ledge.partial) continue;
    if (!ledge.steps.empty() && (ledge.height - low > drop || top[f] > ledge.height + drop)) ledge.partial = true;
    if (ledge.steps.empty()) ledge.height = top[f];
    ledges.push_back(std::move(ledge));
  }
  std::sort(ledges.begin(), ledges.end(), [](const ColumnLedge& a, const ColumnLedge& b) {
    return a.height < b.height || (a.height == b.height && a.face < b.face);
  });
  return ledges;
}

}  // namespace

std::optional<ColumnPiece> columnPiece(const CadSolid& cad) {
  ColumnPiece c;
  for (int f = 0; f < cad.faces.Extent(); ++f)
    if (isCutFace(cad, f)) {
      if (c.foot >= 0) return std::nullopt;  // feet on two faces
      c.foot = f;
    }
  if (c.foot < 0) return std::nullopt;
  const TopoDS_Face& foot = TopoDS::Face(cad.faces(c.foot + 1));
  double u0, u1, v0, v1;
  BRepTools::UVBounds(foot, u0, u1, v0, v1);
  const Vec3 footNormal = -outwardNormal(foot, 0.5 * (u0 + u1), 0.5 * (v0 + v1));  // outward is into the sheet
  c.axis = sidesAxis(cad, c.foot, footNormal);
  // a plane square to the axis (or a B-spline lying on one: a part scaled to metres, a CAD system's export); else a
  // foot whose normals stay within kMaxFootTilt of the axis (a pin on a shell, or drawn along its sides' direction
  // on a sloping wall): its plane the one square to the axis through its middle, its nodes put on it along the axis
  const std::optional<gp_Pln> plane = planeOf(foot, kPlanarFoot * cad.diagonal);
  const std::optional<FaceReach> tilt = faceReach(foot, -c.axis);
  if (!tilt || tilt->lowest < std::cos(kMaxFootTilt)) return std::nullopt;
  c.footOffPlane = !plane || tilt->lowest < 1 - kSquareFoot;
  c.origin = plane && !c.footOffPlane ? toVec(plane->Location())
                                      : toVec(BRepAdaptor_Surface(foot).Value(0.5 * (u0 + u1), 0.5 * (v0 + v1)));
  const double square = std::sin(kMaxColumnDraft), base = c.origin.dot(c.axis);
  std::vector<double> top(cad.faces.Extent(), 0);  // per face, its farthest point over the foot's plane
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    if (f == c.foot) continue;
    const std::optional<FaceReach> r = faceReach(TopoDS::Face(cad.faces(f + 1)), c.axis);
    if (!r || r->lowest < -square) return std::nullopt;  // it looks back at the foot: an overhang
    (r->highest <= square ? c.sides : c.caps).push_back(f);
    top[f] = r->top - base, c.height = std::max(c.height, top[f]);
  }
  if (c.caps.empty() || c.sides.empty() || !(c.height > 0)) return std::nullopt;
  c.ledges = findLedges(cad, c, top);
  return c;
}

WallSides columnSides(const CadSolid& cad, const ColumnPiece& column) {
  WallSides sides;
  sides.faces.resize(cad.faces.Extent());
  sides.faces[column.foot].side = Side::Bottom;
  for (int f : column.caps) sides.faces[f].side = Side::Top;
  sides.thickness = faceWidth(cad.faces(column.foot + 1));
  return sides;
}

}  // namespace hexlayer
