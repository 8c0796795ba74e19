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

// The height of p over the foot's plane, along the axis.
double heightOf(const ColumnPiece& column, const Vec3& p) { return (p - column.origin).dot(column.axis); }

// Per foot quad, the tier its hexes end in: that of the ledge the line up the axis from its middle meets first, else
// the last. [in,out] rays; [in] q, column, tiers; [in] reach: how far the lines are followed.
std::vector<int> quadTiers(RayCaster& rays, const QuadMesh& q, const ColumnPiece& column, const ColumnTiers& tiers,
                           double reach) {
  const int last = static_cast<int>(tiers.top.size()) - 1;
  std::vector<int> tier(q.quads.size(), last);
  for (std::size_t k = 0; k < q.quads.size(); ++k) {
    Vec3 middle = Vec3::Zero();
    for (int n : q.quads[k]) middle += 0.25 * q.nodes[n];
    const std::optional<FacePoint> cap = capAbove(rays, column, middle, reach);
    for (const ColumnLedge& ledge : column.ledges)
      if (cap && cap->face == ledge.face)  // the tier whose top is nearest the ledge's (ledges as high are one tier)
        for (int i = 0; i < last; ++i)
          if (std::abs(tiers.top[i] - ledge.height) < std::abs(tiers.top[tier[k]] - ledge.height)) tier[k] = i;
  }
  return tier;
}

// Where the columns end on the caps (those of the column's top: the caps that end it) of the nodes of `loops` and of
// the nodes flagged `inner`: a loop node's on the caps' rim edges (its place raised to the column's height), an
// inner node's where its place raised by the loops' ends (mean value coordinates) projects, or up the axis where that
// lies sideways (a dome). [in] cad, foot, column, walls; [in] loops: about the inner nodes (the foot's outline, and in
// a column with ledges the steps' loops about its top); [in] inner: per node. Returns per node its top (the others'
// left empty).
std::vector<FacePoint> capTops(const CadSolid& cad, const ColumnFoot& foot, const ColumnPiece& column,
                               const WallProjector& walls, const std::vector<std::vector<int>>& loops,
                               const std::vector<char>& inner) {
  const QuadMesh& q = foot.quads;
  std::vector<std::vector<Eigen::Vector2d>> polygon;
  std::vector<int> loopNodes;
  for (const std::vector<int>& loop : loops) {
    polygon.emplace_back();
    for (int n : loop) loopNodes.push_back(n), polygon.back().push_back(onFootPlane(foot, column, q.nodes[n]));
  }
  std::vector<FacePoint> top(q.nodes.size());
  std::optional<RayCaster> rays;  // made at the first inner node whose cap point is off its axis line
  for (int n : loopNodes) {
    const Vec3 raised = q.nodes[n] + column.height * column.axis;
    const std::optional<FacePoint> rim = walls.projectOntoRimEdges(Side::Top, raised);
    top[n] = rim ? *rim : onSide(walls, Side::Top, raised);
  }
  for (int n = 0; n < static_cast<int>(q.nodes.size()); ++n) {
    if (!inner[n]) continue;
    const std::vector<double> w = meanValueWeights(polygon, onFootPlane(foot, column, q.nodes[n]));
    Vec3 raised = q.nodes[n];
    for (std::size_t j = 0; j < loopNodes.size(); ++j)
      raised += w[j] * (top[loopNodes[j]].point - q.nodes[loopNodes[j]]);
    top[n] = onSide(walls, Side::Top, raised);
    const Vec3 moved = top[n].point - raised, rise = (raised - q.nodes[n]).dot(column.axis) * column.axis;
    if ((moved - moved.dot(column.axis) * column.axis).norm() > kOffAxis * rise.norm()) {  // sideways: a dome
      if (!rays) rays.emplace(cad, 1e-7 * cad.diagonal);
      if (const std::optional<FacePoint> up = capAbove(*rays, column, raised - rise, 2 * cad.diagonal)) top[n] = *up;
    }
  }
  return top;
}

// One node's column: its end on each tier's top it reaches (on a side, or a ledge, or the caps).
struct NodeColumn {
  int low = 0, high = 0;           // the lowest and highest tier its quads' hexes end in
  std::vector<FacePoint> tierTop;  // per tier up to `high`, where it crosses that tier's top (the last: its end)
};

// The node columns of a column with ledges. [in] cad, foot, column, walls, tiers, outline; [in] quadTier: per quad;
// [in,out] rays: the column's.
std::vector<NodeColumn> steppedColumns(const CadSolid& cad, const ColumnFoot& foot, const ColumnPiece& column,
                                       const WallProjector& walls, const ColumnTiers& tiers,
                                       const std::vector<char>& outline, const std::vector<int>& quadTier,
                                       RayCaster& rays) {
  const QuadMesh& q = foot.quads;
  const int last = static_cast<int>(tiers.top.size()) - 1;
  std::vector<NodeColumn> c(q.nodes.size(), NodeColumn{last, 0, {}});
  for (std::size_t k = 0; k < q.quads.size(); ++k)
    for (int n : q.quads[k]) c[n].low = std::min(c[n].low, quadTier[k]), c[n].high = std::max(c[n].high, quadTier[k]);
  // the top's: loops all of whose nodes reach it (the outline's, the steps'), their inner nodes interpolated from them
  std::vector<std::vector<int>> topLoops;
  std::vector<char> onLoop(q.nodes.size(), 0), inner(q.nodes.size(), 0);
  std::vector<std::vector<Eigen::Vector2d>> flat;  // the top's loops counter-clockwise
  for (const auto* loops : {&foot.loops, &foot.steps})
    for (const std::vector<int>& loop : *loops) {
      for (int n : loop) onLoop[n] = 1;
      if (std::any_of(loop.begin(), loop.end(), [&](int n) { return c[n].high != last; })) continue;
      topLoops.push_back(loop), flat.emplace_back();
      for (int n : loop) flat.back().push_back(onFootPlane(foot, column, q.nodes[n]));
      if (polygonArea(flat.back()) < 0)
        std::reverse(topLoops.back().begin(), topLoops.back().end()),
            std::reverse(flat.back().begin(), flat.back().end());
    }
  for (std::size_t l = 0; l < topLoops.size(); ++l) {  // a hole (inside an odd number of the others) turned round
    int round = 0;
    for (std::size_t o = 0; o < topLoops.size(); ++o) round += o != l && insidePolygon(flat[o], flat[l].front());
    if (round % 2 != 0) std::reverse(topLoops[l].begin(), topLoops[l].end());
  }
  for (std::size_t n = 0; n < q.nodes.size(); ++n) inner[n] = !onLoop[n] && c[n].low == last;
  const std::vector<FacePoint> top = capTops(cad, foot, column, walls, topLoops, inner);
  for (std::size_t n = 0; n < q.nodes.size(); ++n) {
    const Vec3& from = q.nodes[n];
    auto raised = [&](int tier) { return Vec3(from + (tiers.top[tier] - heightOf(column, from)) * column.axis); };
    for (int i = 0; i < c[n].high; ++i)  // a tier's top passed: on a side above the node's lowest ledge, on its edge
      c[n].tierTop.push_back(outline[n] || i > c[n].low ? onSide(walls, Side::Lateral, raised(i))
                             : i == c[n].low            ? onSide(walls, Side::Top, raised(i))
                                                        : FacePoint{raised(i), -1});
    const Vec3 end = raised(c[n].high);
    std::optional<FacePoint> at;
    if (inner[n] || (c[n].high == last && top[n].face >= 0))
      at = top[n];
    else if (onLoop[n])
      at = walls.projectOntoRimEdges(Side::Top, end);  // a side's top edge
    else                                               // inside a ledge (a drill point's cone, or flat): up the axis
      at = capAbove(rays, column, from, 2 * cad.diagonal);
    c[n].tierTop.push_back(at ? *at : onSide(walls, Side::Top, end));
  }
  return c;
}

}  // namespace

ColumnTiers columnTiers(const ColumnPiece& column, double size) {
  ColumnTiers t;
  for (const ColumnLedge& ledge : column.ledges)
    if (t.top.empty() || ledge.height > t.top.back() + kLedgeDrop * column.height) t.top.push_back(ledge.height);
  t.top.push_back(column.height);
  double below = 0;
  for (double top : t.top)
    t.layers.push_back(std::max(1, static_cast<int>(std::lround((top - below) / size)))), below = top;
  return t;
}

HexMesh sweepColumn(const CadSolid& cad, const ColumnFoot& foot, const ColumnPiece& column, const WallProjector& walls,
                    const ColumnTiers& tiers) {
  const QuadMesh& q = foot.quads;
  const int tierCount = static_cast<int>(tiers.top.size());
  std::vector<int> first{0};  // per tier, its first layer (and after the last, the layers in all)
  for (int layers : tiers.layers) first.push_back(first.back() + layers);
  std::vector<char> outline(q.nodes.size(), 0);
  for (const std::vector<int>& loop : foot.loops)
    for (int n : loop) outline[n] = 1;
  std::vector<int> quadTier(q.quads.size(), tierCount - 1);
  std::vector<NodeColumn> columns;
  if (tierCount == 1) {
    std::vector<char> inner(q.nodes.size());
    for (std::size_t n = 0; n < q.nodes.size(); ++n) inner[n] = !outline[n];
    for (const FacePoint& t : capTops(cad, foot, column, walls, foot.loops, inner)) columns.push_back({0, 0, {t}});
  } else {
    RayCaster rays(cad, 1e-7 * cad.diagonal);
    quadTier = quadTiers(rays, q, column, tiers, 2 * cad.diagonal);
    columns = steppedColumns(cad, foot, column, walls, tiers, outline, quadTier, rays);
  }
  HexMesh mesh;
  mesh.layers = first.back();
  std::vector<int> base;  // per quad node, its column's first hex node
  for (std::size_t n = 0; n < q.nodes.size(); ++n) {
    const NodeColumn& c = columns[n];
    base.push_back(static_cast<int>(mesh.nodes.size()));
    Vec3 below = q.nodes[n];
    mesh.nodes.push_back(below), mesh.nodeFace.push_back(column.foot), mesh.nodeLayer.push_back(0);
    mesh.nodeOnRim.push_back(outline[n] ? kRimSwept : 0);
    for (int i = 0; i <= c.high; ++i) {
      const bool sideNode = outline[n] || i > c.low;  // a side's: the outline's, or a step's above its ledge
      for (int k = first[i] + 1; k <= first[i + 1]; ++k) {
        FacePoint p{below + (c.tierTop[i].point - below) * (static_cast<double>(k - first[i]) / tiers.layers[i]), -1};
        if (k == first[i + 1])
          p = c.tierTop[i];
        else if (sideNode)
          p = onSide(walls, Side::Lateral, p.point);
        mesh.nodes.push_back(p.point), mesh.nodeFace.push_back(p.face), mesh.nodeLayer.push_back(k);
        mesh.nodeOnRim.push_back(sideNode || (k == first[i + 1] && i == c.low && c.low < c.high) ? kRimSwept : 0);
      }
      below = c.tierTop[i].point;
    }
  }
  for (std::size_t k = 0; k < q.quads.size(); ++k) {
    std::array<int, 4> quad = q.quads[k];
    const Vec3 n = (q.nodes[quad[2]] - q.nodes[quad[0]]).cross(q.nodes[quad[3]] - q.nodes[quad[1]]);
    if (n.dot(column.axis) < 0) std::swap(quad[1], quad[3]);  // counter-clockwise seen from up the axis
    for (int layer = 0; layer < first[quadTier[k] + 1]; ++layer) {
      std::array<int, 8> hex;
      for (int c = 0; c < 4; ++c) hex[c] = base[quad[c]] + layer, hex[c + 4] = base[quad[c]] + layer + 1;
      mesh.hexes.push_back(hex);
    }
  }
  return mesh;
}

}  // namespace hexlayer
