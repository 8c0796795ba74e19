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

// The columns of rim nodes, bottom (layer 0) to top: nodes above one another in the hexes (corners k, k + 4).
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

// The point of the lateral faces for p: along the rim's outward line through p if it meets one within
// reach, else the nearest one within reach.
std::optional<FacePoint> ontoRim(WallRays& rays, const WallProjector& walls, const Vec3& p, const Vec3& outward, double reach) {
  if (outward.squaredNorm() > 0)
    if (std::optional<FacePoint> hit = rays.nearestOnLine(Side::Lateral, p, outward, reach)) return hit;
  std::optional<FacePoint> nearest = walls.project(Side::Lateral, p);
  if (nearest && (nearest->point - p).norm() <= reach) return nearest;
  return std::nullopt;
}

// Where the nodes of one rim column go (nullopt: where they are): the ends onto the lateral faces, the
// nodes between them evenly spaced on the line joining the moved ends, then onto the lateral faces.
std::vector<std::optional<FacePoint>> layColumn(const HexMesh& mesh, const std::vector<int>& column, const Vec3& outward,
                                                WallRays& rays, const WallProjector& walls, double reach) {
  const std::size_t m = column.size() - 1;
  std::vector<std::optional<FacePoint>> to(column.size());
  to[0] = ontoRim(rays, walls, mesh.nodes[column[0]], outward, reach);
  to[m] = ontoRim(rays, walls, mesh.nodes[column[m]], outward, reach);
  const Vec3 bottom = to[0] ? to[0]->point : mesh.nodes[column[0]], top = to[m] ? to[m]->point : mesh.nodes[column[m]];
  for (std::size_t k = 1; k < m; ++k)
    to[k] = ontoRim(rays, walls, bottom + (static_cast<double>(k) / m) * (top - bottom), outward, reach);
  return to;
}

// Scaled Jacobians of the hexes around the given nodes (a hex once per node it has among them).
class HexesAround {
 public:
  explicit HexesAround(const HexMesh& mesh) : mesh_(mesh) {
    at_ = groupByKey<std::size_t>(mesh.nodes.size(), [&](auto emit) {
      for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (int v : mesh.hexes[h])
          if (mesh.nodeOnRim[v]) emit(v, h);
    });
  }
  std::vector<double> scaledJacobians(const std::vector<int>& nodes) const {
    std::vector<double> sj;
    for (int v : nodes)
      for (std::size_t k = at_.start[v]; k < at_.start[v + 1]; ++k) sj.push_back(hexScaledJacobian(hexCorners(mesh_, at_.items[k])));
    return sj;
  }

 private:
  const HexMesh& mesh_;
  Groups<std::size_t> at_;
};

bool spoils(const std::vector<double>& before, const std::vector<double>& after) {
  for (std::size_t k = 0; k < after.size(); ++k)
    if (after[k] < kSpoiled && after[k] < before[k]) return true;
  return false;
}

// Moves the nodes to their new places if no hex around them is spoiled; returns whether it did.
bool moveUnlessSpoiled(HexMesh& mesh, const HexesAround& around, const std::vector<int>& nodes,
                       const std::vector<FacePoint>& to) {
  const std::vector<double> before = around.scaledJacobians(nodes);
  std::vector<Vec3> was;
  for (std::size_t k = 0; k < nodes.size(); ++k) was.push_back(mesh.nodes[nodes[k]]), mesh.nodes[nodes[k]] = to[k].point;
  if (!spoils(before, around.scaledJacobians(nodes))) {
    for (std::size_t k = 0; k < nodes.size(); ++k) mesh.nodeFace[nodes[k]] = to[k].face;
    return true;
  }
  for (std::size_t k = 0; k < nodes.size(); ++k) mesh.nodes[nodes[k]] = was[k];
  return false;
}

}  // namespace

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
    Vec3 outward = Vec3::Zero();
    for (int v : columns[c]) outward += normal[v];
    if (outward.norm() > 0) outward.normalize();
    to[c] = layColumn(mesh, columns[c], outward, rays[threadIndex()], walls, reach);
  }
  // Then one column at a time, as a column's hexes share nodes with its neighbours'.
  RimProjectionStats stats;
  const HexesAround around(mesh);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    stats.rimNodes += columns[c].size();
    std::vector<int> nodes;
    std::vector<FacePoint> places;
    for (std::size_t k = 0; k < columns[c].size(); ++k)
      if (to[c][k]) nodes.push_back(columns[c][k]), places.push_back(*to[c][k]);
    if (nodes.empty()) continue;
    if (moveUnlessSpoiled(mesh, around, nodes, places)) {
      stats.onLateralFaces += nodes.size();
      continue;
    }
    ++stats.columnsKept;
    for (std::size_t k = 0; k < nodes.size(); ++k) stats.onLateralFaces += moveUnlessSpoiled(mesh, around, {nodes[k]}, {places[k]});
  }
  return stats;
}

}  // namespace hexlayer
