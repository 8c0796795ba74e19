#include "sweep/rim_projection.hpp"

#include <deque>
#include <optional>
#include <vector>

#include "core/groups.hpp"
#include "core/threads.hpp"
#include "geometry/wall_rays.hpp"
#include "quality/quality.hpp"

namespace hexlayer {
namespace {

constexpr double kSpoiled = 0.2;  // a hex below this scaled Jacobian that got worse is spoiled
constexpr double kMaxAlongRim = 0.5;  // share of a rim node's move that may run along the rim ...
constexpr double kFreeMove = 0.1;     // ... unless the move is shorter than this share of the reach

// Per node, the sum of the outward normals (scaled by area) of the mesh's boundary side faces around it:
// at a rim node, the direction in which the rim faces outward.
std::vector<Vec3> sideFaceNormals(const HexMesh& mesh) {
  std::vector<Vec3> normal(mesh.nodes.size(), Vec3::Zero());
  for (const BoundaryFace& f : boundaryFaces(mesh)) {
    if (f.localFace < 2) continue;  // the bottom and top faces of the hexes lie on the walls
    const auto& x = mesh.nodes;
    const Vec3 n = 0.5 * (x[f.nodes[2]] - x[f.nodes[0]]).cross(x[f.nodes[3]] - x[f.nodes[1]]);
    for (int v : f.nodes) normal[v] += n;
  }
  return normal;
}

// The rim's directions at a column: outward (from the mesh's side faces) and along the rim (tangent).
struct RimFrame {
  Vec3 outward, tangent;
};

RimFrame rimFrame(const HexMesh& mesh, const std::vector<int>& column, const std::vector<Vec3>& sideNormals) {
  RimFrame frame{Vec3::Zero(), Vec3::Zero()};
  for (int v : column) frame.outward += sideNormals[v];
  const Vec3 sweep = mesh.nodes[column.back()] - mesh.nodes[column.front()];
  frame.outward -= frame.outward.dot(sweep) / std::max(sweep.squaredNorm(), 1e-300) * sweep;  // across the sweep line
  if (frame.outward.norm() > 0) frame.outward.normalize();
  frame.tangent = sweep.cross(frame.outward);
  if (frame.tangent.norm() > 0) frame.tangent.normalize();
  return frame;
}

// A move of a rim node to `to` within reach stays in the rim's cross-section: it may go outward and up or
// down the rim's profile, but not far along the rim (to the side faces of a part whose rim has no lateral
// face); a short move may go anywhere (onto a rim that twists, into a corner).
bool acrossRim(const RimFrame& frame, const Vec3& from, const std::optional<FacePoint>& to, double reach) {
  if (!to) return false;
  const Vec3 move = to->point - from;
  if (move.norm() > reach) return false;
  return move.norm() <= kFreeMove * reach || std::abs(move.dot(frame.tangent)) <= kMaxAlongRim * move.norm();
}

// The point of the lateral faces for p: along the rim's outward line through p if it meets one within
// reach, else the nearest one within reach if that lies across the rim.
std::optional<FacePoint> ontoRim(WallRays& rays, const WallProjector& walls, const Vec3& p, const RimFrame& frame, double reach) {
  if (frame.outward.squaredNorm() > 0)
    if (std::optional<FacePoint> hit = rays.nearestOnLine(Side::Lateral, p, frame.outward, reach)) return hit;
  std::optional<FacePoint> nearest = walls.project(Side::Lateral, p);
  if (acrossRim(frame, p, nearest, reach)) return nearest;
  return std::nullopt;
}

// The point of the `side` wall's edges on the lateral faces nearest to p, if within reach and across the
// rim, else ontoRim's.
std::optional<FacePoint> ontoWallEdge(Side side, WallRays& rays, const WallProjector& walls, const Vec3& p,
                                      const RimFrame& frame, double reach) {
  std::optional<FacePoint> edge = walls.projectOntoRimEdges(side, p);
  if (acrossRim(frame, p, edge, reach)) return edge;
  return ontoRim(rays, walls, p, frame, reach);
}

// Where the nodes of one rim column go (nullopt: where they are): the ends onto the edges where the walls
// meet the lateral faces, the nodes between them evenly spaced on the line joining the moved ends, then
// along the rim's outward line onto the lateral faces.
std::vector<std::optional<FacePoint>> layColumn(const HexMesh& mesh, const std::vector<int>& column, const RimFrame& frame,
                                                WallRays& rays, const WallProjector& walls, double reach) {
  const std::size_t m = column.size() - 1;
  std::vector<std::optional<FacePoint>> to(column.size());
  to[0] = ontoWallEdge(Side::Bottom, rays, walls, mesh.nodes[column[0]], frame, reach);
  to[m] = ontoWallEdge(Side::Top, rays, walls, mesh.nodes[column[m]], frame, reach);
  const Vec3 bottom = to[0] ? to[0]->point : mesh.nodes[column[0]], top = to[m] ? to[m]->point : mesh.nodes[column[m]];
  for (std::size_t k = 1; k < m; ++k)
    to[k] = ontoRim(rays, walls, bottom + (static_cast<double>(k) / m) * (top - bottom), frame, reach);
  return to;
}

// The hexes that have a rim node, each once, and per rim column the hexes around its nodes.
struct RimHexes {
  std::vector<std::size_t> hexes;
  std::vector<std::vector<std::size_t>> ofColumn;
};

RimHexes rimHexes(const HexMesh& mesh, const std::vector<std::vector<int>>& columns) {
  const Groups<std::size_t> at = groupByKey<std::size_t>(mesh.nodes.size(), [&](auto emit) {
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
      for (int v : mesh.hexes[h])
        if (mesh.nodeOnRim[v]) emit(v, h);
  });
  RimHexes r;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (int v : mesh.hexes[h])
      if (mesh.nodeOnRim[v]) {
        r.hexes.push_back(h);
        break;
      }
  for (const std::vector<int>& column : columns) {
    std::vector<std::size_t> around;
    for (int v : column) around.insert(around.end(), at.items.begin() + at.start[v], at.items.begin() + at.start[v + 1]);
    r.ofColumn.push_back(std::move(around));
  }
  return r;
}

}  // namespace

std::vector<std::vector<int>> rimColumns(const HexMesh& mesh) {
  std::vector<int> above(mesh.nodes.size(), -1);
  for (const auto& h : mesh.hexes)
    for (int k = 0; k < 4; ++k) above[h[k]] = h[k + 4];
  std::vector<std::vector<int>> columns;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (mesh.nodeOnRim[i] && mesh.nodeLayer[i] == 0) {
      std::vector<int> column{static_cast<int>(i)};
      while (above[column.back()] >= 0) column.push_back(above[column.back()]);
      columns.push_back(std::move(column));
    }
  return columns;
}

RimProjectionStats projectRim(HexMesh& mesh, const CadSolid& cad, const WallSides& sides, const WallProjector& walls,
                              double reach) {
  const std::vector<std::vector<int>> columns = rimColumns(mesh);
  const std::vector<Vec3> normal = sideFaceNormals(mesh);
  // The new places first, in parallel (one ray caster per thread: OpenCASCADE's keeps state); a column's
  // depend only on where the sweep put it.
  std::vector<std::vector<std::optional<FacePoint>>> to(columns.size());
  std::deque<WallRays> rays;
  for (int t = 0; t < threadCount(); ++t) rays.emplace_back(cad, sides);
  #pragma omp parallel for schedule(dynamic, 8)
  for (long c = 0; c < static_cast<long>(columns.size()); ++c) {
    to[c] = layColumn(mesh, columns[c], rimFrame(mesh, columns[c], normal), rays[threadIndex()], walls, reach);
  }
  // Then all columns at once, and back where the sweep put them those that spoil a hex (below a scaled
  // Jacobian of 0.2 and worse than before), until none does: the result does not depend on the order.
  RimProjectionStats stats;
  const RimHexes around = rimHexes(mesh, columns);
  std::vector<double> before(mesh.hexes.size(), 1.0);
  for (std::size_t h : around.hexes) before[h] = hexScaledJacobian(hexCorners(mesh, h));
  const std::vector<Vec3> swept = mesh.nodes;
  std::vector<char> moved(columns.size(), 0);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    stats.rimNodes += columns[c].size();
    for (std::size_t k = 0; k < columns[c].size(); ++k)
      if (to[c][k]) mesh.nodes[columns[c][k]] = to[c][k]->point, moved[c] = 1;
  }
  auto spoiled = [&](std::size_t c) {
    for (std::size_t h : around.ofColumn[c]) {
      const double sj = hexScaledJacobian(hexCorners(mesh, h));
      if (sj < kSpoiled && sj < before[h]) return true;
    }
    return false;
  };
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::size_t> back;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (moved[c] && spoiled(c)) back.push_back(c);
    for (std::size_t c : back) {
      for (int v : columns[c]) mesh.nodes[v] = swept[v];
      moved[c] = 0, changed = true, ++stats.columnsKept;
    }
  }
  // The columns put back get their nodes moved one at a time where that spoils no hex.
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (std::size_t k = 0; k < columns[c].size(); ++k) {
      const int v = columns[c][k];
      if (!to[c][k]) continue;
      if (!moved[c]) {
        mesh.nodes[v] = to[c][k]->point;
        if (spoiled(c)) {
          mesh.nodes[v] = swept[v];
          continue;
        }
      }
      mesh.nodeFace[v] = to[c][k]->face, ++stats.onLateralFaces;
    }
  return stats;
}

}  // namespace hexlayer
