#include "pipeline/junction_mesh.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include "core/error.hpp"

namespace hexlayer {
namespace {

constexpr double kParallel = 1e-7;  // sine of the angle below which two planes are parallel
constexpr double kBox = 1e-6;       // relative volume difference of a box and its extent
constexpr double kOnFoot = 1e-3;    // of a layer: a node this near the foot's plane lies on it

Vec3 toVec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

// The unit normal of a planar face (as its surface has it, not oriented); throws if the face is not planar.
Vec3 planeNormal(const TopoDS_Shape& face, const char* what) {
  const BRepAdaptor_Surface surface(TopoDS::Face(face));
  if (surface.GetType() != GeomAbs_Plane) throw geometryError(std::string("T-junction: ") + what + " is not planar");
  return toVec(surface.Plane().Axis().Direction().XYZ());
}

bool parallel(const Vec3& a, const Vec3& b) { return a.cross(b).norm() <= kParallel; }

// The rib's wall normal: all its walls planar and parallel, across the plate's normal n.
Vec3 ribNormal(const CadSolid& cad, const Sheet& rib, const Vec3& n) {
  const Vec3 normal = planeNormal(cad.faces(rib.faces.front() + 1), "a wall of the standing sheet");
  for (int f : rib.faces)
    if (!parallel(planeNormal(cad.faces(f + 1), "a wall of the standing sheet"), normal))
      throw geometryError("T-junction: the rib's walls are not parallel planes");
  if (std::abs(normal.dot(n)) > kParallel) throw geometryError("T-junction: the rib does not stand across the plate");
  return normal;
}

struct Extent {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
};

// The plate piece's vertices' extent in the frame (u, v, w); throws unless the piece is that box.
Extent boxExtent(const TopoDS_Solid& piece, const Vec3& u, const Vec3& v, const Vec3& w) {
  TopTools_IndexedMapOfShape faces, vertices;
  TopExp::MapShapes(piece, TopAbs_FACE, faces);
  for (int f = 1; f <= faces.Extent(); ++f) planeNormal(faces(f), "a face of the plate");
  TopExp::MapShapes(piece, TopAbs_VERTEX, vertices);
  Extent e;
  for (int k = 1; k <= vertices.Extent(); ++k) {
    const Vec3 p = toVec(BRep_Tool::Pnt(TopoDS::Vertex(vertices(k))).XYZ());
    const Vec3 local(p.dot(u), p.dot(v), p.dot(w));
    e.lo = e.lo.cwiseMin(local), e.hi = e.hi.cwiseMax(local);
  }
  GProp_GProps props;
  BRepGProp::VolumeProperties(piece, props);
  const double box = (e.hi - e.lo).prod();
  if (!(std::abs(props.Mass() - box) <= kBox * box))
    throw geometryError(
        "T-junction: the plate under the rib is not a rectangle (junction meshing does not cut "
        "other plates yet)");
  return e;
}

// The foot's plane's normal, pointing out of the plate piece (towards the rib).
Vec3 footNormal(const JunctionCut& cut) {
  Vec3 n = planeNormal(cut.feet.front().face, "the rib's foot");
  GProp_GProps face, plate;
  BRepGProp::SurfaceProperties(cut.feet.front().face, face);
  BRepGProp::VolumeProperties(cut.pieces.front(), plate);
  return (toVec(face.CentreOfMass().XYZ()) - toVec(plate.CentreOfMass().XYZ())).dot(n) > 0 ? n : Vec3(-n);
}

// 20-node hexes: the plate's mid-edge node of every edge whose corners are both rib nodes is the rib's mid-edge node
// of that edge. [in] plate, rib; [in,out] shared: footNodesShared's corners, the mid-edge nodes added.
void shareMidEdgeNodes(const HexMesh& plate, const HexMesh& rib, std::vector<int>& shared) {
  if (!plate.quadratic()) return;
  std::map<std::pair<int, int>, int> ribEdges;  // the rib's edges on the foot: their corners -> mid-edge node
  std::vector<char> onFoot(rib.nodes.size(), 0);
  for (int n : shared)
    if (n >= 0) onFoot[n] = 1;
  for (std::size_t h = 0; h < rib.hexes.size(); ++h)
    for (std::size_t e = 0; e < kHexEdges.size(); ++e) {
      const int a = rib.hexes[h][kHexEdges[e][0]], b = rib.hexes[h][kHexEdges[e][1]];
      if (onFoot[a] && onFoot[b]) ribEdges[std::minmax(a, b)] = rib.midEdges[h][e];
    }
  for (std::size_t h = 0; h < plate.hexes.size(); ++h)
    for (std::size_t e = 0; e < kHexEdges.size(); ++e) {
      const int a = shared[plate.hexes[h][kHexEdges[e][0]]], b = shared[plate.hexes[h][kHexEdges[e][1]]];
      if (a < 0 || b < 0) continue;
      const auto at = ribEdges.find(std::minmax(a, b));
      if (at == ribEdges.end())
        throw geometryError("T-junction: a plate's edge on the rib's foot is none of the rib's");
      shared[plate.midEdges[h][e]] = at->second;
    }
}

}  // namespace

TJunctionFrame tJunctionFrame(const CadSolid& cad, const std::vector<Sheet>& sheets, const JunctionCut& cut) {
  if (sheets.size() != 2 || cut.pieces.size() != 2 || cut.feet.size() != 1)
    throw geometryError("T-junction: junction meshing takes one rib with one foot on a plate");
  TJunctionFrame t;
  t.w = footNormal(cut);
  const Vec3 ribWall = ribNormal(cad, sheets[1], t.w);
  t.plate.u = ribWall.cross(t.w).normalized();
  t.plate.v = t.w.cross(t.plate.u);
  const Extent e = boxExtent(cut.pieces.front(), t.plate.u, t.plate.v, t.w);
  t.plate.uMin = e.lo.x(), t.plate.uMax = e.hi.x(), t.plate.vMin = e.lo.y(), t.plate.vMax = e.hi.y();
  t.plate.origin = 0.5 * (e.lo.z() + e.hi.z()) * t.w;
  t.footW = e.hi.z();
  t.thickness = e.hi.z() - e.lo.z();
  return t;
}

FootGrid footGrid(const HexMesh& rib, const QuadMesh& quads, const TJunctionFrame& frame) {
  const int m = rib.layers, stride = m + 1;
  const double tolerance = kOnFoot * frame.thickness / std::max(m, 1);
  auto onFoot = [&](int q) {
    for (int k = 0; k <= m; ++k)
      if (!(std::abs(rib.nodes[q * stride + k].dot(frame.w) - frame.footW) <= tolerance)) return false;
    return true;
  };
  auto u = [&](int q) { return rib.nodes[q * stride].dot(frame.plate.u); };
  std::vector<int> columns;
  for (int q = 0; q < static_cast<int>(quads.nodes.size()) && (q + 1) * stride <= static_cast<int>(rib.nodes.size());
       ++q)
    if (onFoot(q)) columns.push_back(q);
  std::stable_sort(columns.begin(), columns.end(), [&](int a, int b) { return u(a) < u(b); });
  std::set<std::pair<int, int>> edges;
  for (const auto& quad : quads.quads)
    for (int c = 0; c < 4; ++c) edges.insert(std::minmax(quad[c], quad[(c + 1) % 4]));
  for (std::size_t j = 0; j + 1 < columns.size(); ++j)
    if (!edges.count(std::minmax(columns[j], columns[j + 1])))
      throw geometryError("T-junction: the rib's nodes on its foot are not one row of quads");
  if (columns.size() < 2) throw geometryError("T-junction: the rib has no quads along its foot");
  FootGrid g;
  g.nodes.assign(stride, std::vector<int>(columns.size()));
  g.rows.assign(stride, 0), g.columns.assign(columns.size(), 0);
  g.at.assign(stride, std::vector<Eigen::Vector2d>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) {
    const int q = columns[j];
    const bool up = rib.nodes[q * stride].dot(frame.plate.v) < rib.nodes[q * stride + m].dot(frame.plate.v);
    for (int i = 0; i < stride; ++i) {
      const int n = q * stride + (up ? i : m - i);
      g.nodes[i][j] = n;
      g.at[i][j] = {rib.nodes[n].dot(frame.plate.u), rib.nodes[n].dot(frame.plate.v)};
      g.rows[i] += rib.nodes[n].dot(frame.plate.v) / columns.size();
      g.columns[j] += rib.nodes[n].dot(frame.plate.u) / stride;
    }
  }
  return g;
}

Footprint footprintOf(const TJunctionFrame& frame, const FootGrid& foot, double unit) {
  Footprint f = frame.plate;
  f.origin *= unit;
  f.uMin *= unit, f.uMax *= unit, f.vMin *= unit, f.vMax *= unit;
  for (double c : foot.columns) f.columns.push_back(c * unit);
  for (double r : foot.rows) f.rows.push_back(r * unit);
  for (const auto& row : foot.at) {
    f.feet.emplace_back();
    for (const Eigen::Vector2d& p : row) f.feet.back().push_back(p * unit);
  }
  f.size = (f.columns.back() - f.columns.front()) / (f.columns.size() - 1);
  return f;
}

std::vector<int> footNodesShared(const HexMesh& plate, const std::vector<std::vector<int>>& strip, const HexMesh& rib,
                                 const FootGrid& foot, double tolerance) {
  const int m = plate.layers, stride = m + 1;
  std::vector<int> shared(plate.nodes.size(), -1);
  for (std::size_t i = 0; i < strip.size(); ++i)
    for (std::size_t j = 0; j < strip[i].size(); ++j) {
      const Vec3& p = rib.nodes[foot.nodes[i][j]];
      const int a = strip[i][j] * stride, b = a + m;
      const int end = (plate.nodes[a] - p).norm() < (plate.nodes[b] - p).norm() ? a : b;
      if (const double d = (plate.nodes[end] - p).norm(); !(d <= tolerance)) {
        std::ostringstream msg;
        msg << "T-junction: the plate's node under the rib's foot node (" << p.x() << ", " << p.y() << ", " << p.z()
            << ") is " << d << " from it";
        throw geometryError(msg.str());
      }
      shared[end] = foot.nodes[i][j];
    }
  shareMidEdgeNodes(plate, rib, shared);
  return shared;
}

JunctionHexes junctionHexes(const HexMesh& mesh, const std::vector<double>& scaledJacobian,
                            const std::vector<int>& footNodes) {
  std::vector<char> onFoot(mesh.nodes.size(), 0);
  for (int n : footNodes) onFoot[n] = 1;
  JunctionHexes j;
  j.minScaledJacobian = std::numeric_limits<double>::infinity();
  double sum = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    if (std::none_of(mesh.hexes[h].begin(), mesh.hexes[h].end(), [&](int n) { return onFoot[n] != 0; })) continue;
    ++j.hexes, sum += scaledJacobian[h];
    j.minScaledJacobian = std::min(j.minScaledJacobian, scaledJacobian[h]);
  }
  if (j.hexes == 0) j.minScaledJacobian = 0;
  j.meanScaledJacobian = j.hexes ? sum / j.hexes : 0;
  return j;
}

}  // namespace hexlayer
