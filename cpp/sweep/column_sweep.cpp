#include "sweep/column_sweep.hpp"

#include <algorithm>
#include <optional>

#include "core/error.hpp"
#include "core/polygon.hpp"
#include "geometry/ray_caster.hpp"
#include "sweep/sweep.hpp"

namespace hexlayer {
namespace {

// Of the height: an inner node's raised place whose nearest cap point lies this far sideways from it is put on the cap
// along the axis instead (a dome's nearest point lies out towards its rim).
constexpr double kOffAxis = 1e-3;

// [in] walls; [in] side; [in] p. Returns the nearest point of the `side` faces, or throws naming what was sought.
FacePoint onSide(const WallProjector& walls, Side side, const Vec3& p) {
  if (std::optional<FacePoint> q = walls.project(side, p)) return *q;
  throw geometryError(side == Side::Top ? "column: no cap above a node of its foot" : "column: no side beside its rim");
}

// Where the line up the axis from `from` first meets a cap of the column; none if it meets none. [in,out] rays; [in]
// column, from, reach: how far the line is followed.
std::optional<FacePoint> capAbove(RayCaster& rays, const ColumnPiece& column, const Vec3& from, double reach) {
  for (const RayHit& hit : rays.all(from, column.axis, 0, reach))
    if (std::find(column.caps.begin(), column.caps.end(), hit.face) != column.caps.end())
      return FacePoint{hit.point, hit.face};
  return std::nullopt;
}

}  // namespace

HexMesh sweepColumn(const CadSolid& cad, const ColumnFoot& foot, const ColumnPiece& column, const WallProjector& walls,
                    int layers) {
  const QuadMesh& q = foot.quads;
  const int m = layers, stride = m + 1;
  HexMesh mesh = layeredHexes(q, std::vector<Vec3>(q.nodes.size(), column.axis), m);
  // the outline's ends on the caps' rim edges, raised to the column's height first
  std::vector<char> outline(q.nodes.size(), 0);
  std::vector<std::vector<Eigen::Vector2d>> polygon;
  std::vector<int> outlineNodes;
  for (const std::vector<int>& loop : foot.loops) {
    polygon.emplace_back();
    for (int n : loop) {
      outline[n] = 1, outlineNodes.push_back(n);
      polygon.back().push_back(onFootPlane(foot, column, q.nodes[n]));
    }
  }
  std::vector<FacePoint> top(q.nodes.size());
  std::optional<RayCaster> rays;  // made at the first inner node whose cap point is off its axis line
  for (int n : outlineNodes) {
    const Vec3 raised = q.nodes[n] + column.height * column.axis;
    const std::optional<FacePoint> rim = walls.projectOntoRimEdges(Side::Top, raised);
    top[n] = rim ? *rim : onSide(walls, Side::Top, raised);
  }
  for (int n = 0; n < static_cast<int>(q.nodes.size()); ++n) {
    if (outline[n]) continue;
    const std::vector<double> w = meanValueWeights(polygon, onFootPlane(foot, column, q.nodes[n]));
    Vec3 raised = q.nodes[n];
    for (std::size_t j = 0; j < outlineNodes.size(); ++j)
      raised += w[j] * (top[outlineNodes[j]].point - q.nodes[outlineNodes[j]]);
    top[n] = onSide(walls, Side::Top, raised);
    const Vec3 moved = top[n].point - raised, rise = (raised - q.nodes[n]).dot(column.axis) * column.axis;
    if ((moved - moved.dot(column.axis) * column.axis).norm() > kOffAxis * rise.norm()) {  // sideways: a dome
      if (!rays) rays.emplace(cad, 1e-7 * cad.diagonal);
      if (const std::optional<FacePoint> up = capAbove(*rays, column, raised - rise, 2 * cad.diagonal)) top[n] = *up;
    }
  }
  for (int n = 0; n < static_cast<int>(q.nodes.size()); ++n) {
    const Vec3& from = q.nodes[n];
    const Vec3 to = top[n].point;
    for (int k = 0; k <= m; ++k) {
      const int id = n * stride + k;
      Vec3 p = from + (to - from) * (static_cast<double>(k) / m);
      int face = -1;
      if (k == 0) {
        p = from, face = column.foot;
      } else if (k == m) {
        p = to, face = top[n].face;
      } else if (outline[n]) {
        const FacePoint s = onSide(walls, Side::Lateral, p);
        p = s.point, face = s.face;
      }
      mesh.nodes[id] = p, mesh.nodeFace[id] = face;
    }
  }
  return mesh;
}

}  // namespace hexlayer
