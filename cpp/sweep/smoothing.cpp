#include "sweep/smoothing.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "core/groups.hpp"
#include "quality/quality.hpp"

namespace hexlayer {
namespace {

constexpr double kPoorHex = 0.6;               // the nodes of hexes below this scaled Jacobian are smoothed
constexpr int kMaxRounds = 20;                 // rounds over those nodes, fewer if a round moves none
constexpr double kSteps[] = {1.0, 0.5, 0.25};  // shares of the way to the neighbours' mean tried, longest first
constexpr double kMinGain = 1e-6;              // a move must raise the node's worst hex by at least this

// How a node may move: not at all, freely (inside the part), or on the faces of one side.
struct Freedom {
  bool moves = false;
  std::optional<Side> on;  // the side whose faces it stays on; none: free
};

Freedom freedomOf(const HexMesh& mesh, const WallSides& sides, int v) {
  const bool wallLayer = mesh.nodeLayer[v] == 0 || mesh.nodeLayer[v] == mesh.layers;
  if (mesh.nodeOnRim[v] == kRimCap || (mesh.nodeOnRim[v] == kRimSwept && wallLayer))
    return {};  // on a CAD edge or a cap
  if (mesh.nodeFace[v] >= 0) return {true, sides.faces[mesh.nodeFace[v]].side};
  if (!wallLayer && !mesh.nodeOnRim[v]) return {true, std::nullopt};
  return {};  // a boundary node not put on the CAD
}

// The nodes joined to each node by a hex edge, each once, in increasing order.
std::vector<std::vector<int>> edgeNeighbours(const HexMesh& mesh) {
  std::vector<std::vector<int>> around(mesh.nodes.size());
  for (const auto& hex : mesh.hexes)
    for (const auto& e : kHexEdges) around[hex[e[0]]].push_back(hex[e[1]]), around[hex[e[1]]].push_back(hex[e[0]]);
  for (auto& a : around) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  return around;
}

}  // namespace

SmoothingStats smoothPoorHexes(HexMesh& mesh, const WallProjector& walls, const WallSides& sides) {
  SmoothingStats stats;
  std::vector<double> sj(mesh.hexes.size());
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) sj[h] = hexScaledJacobian(hexCorners(mesh, h));
  const Groups<std::size_t> hexesAt = groupByKey<std::size_t>(mesh.nodes.size(), [&](auto emit) {
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
      for (int v : mesh.hexes[h]) emit(static_cast<std::size_t>(v), h);
  });
  std::vector<char> candidate(mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    stats.worstBefore = std::min(stats.worstBefore, sj[h]);
    if (sj[h] >= kPoorHex) continue;
    ++stats.poorHexes;
    for (int v : mesh.hexes[h]) candidate[v] = 1;
  }
  stats.worstAfter = stats.worstBefore;
  if (stats.poorHexes == 0) return stats;
  const std::vector<std::vector<int>> neighbours = edgeNeighbours(mesh);
  auto worstAround = [&](int v) {
    double worst = 1;
    for (std::size_t i = hexesAt.start[v]; i < hexesAt.start[v + 1]; ++i)
      worst = std::min(worst, hexScaledJacobian(hexCorners(mesh, hexesAt.items[i])));
    return worst;
  };
  // Gauss-Seidel rounds in node order: the same moves for the same mesh.
  for (int round = 0; round < kMaxRounds; ++round) {
    std::size_t moved = 0;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      const int v = static_cast<int>(i);
      const Freedom f = candidate[v] ? freedomOf(mesh, sides, v) : Freedom{};
      if (!f.moves || neighbours[v].empty()) continue;
      Vec3 mean = Vec3::Zero();
      for (int n : neighbours[v]) mean += mesh.nodes[n];
      mean /= static_cast<double>(neighbours[v].size());
      const Vec3 from = mesh.nodes[v];
      const double before = worstAround(v);
      for (double step : kSteps) {
        FacePoint to{from + step * (mean - from), -1};
        if (f.on) {
          const std::optional<FacePoint> onCad = walls.project(*f.on, to.point);
          if (!onCad) break;
          to = *onCad;
        }
        mesh.nodes[v] = to.point;
        if (worstAround(v) > before + kMinGain) {
          if (f.on) mesh.nodeFace[v] = to.face;
          ++moved;
          break;
        }
        mesh.nodes[v] = from;
      }
    }
    stats.nodesMoved += moved;
    if (moved == 0) break;
  }
  stats.worstAfter = 1;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    stats.worstAfter = std::min(stats.worstAfter, hexScaledJacobian(hexCorners(mesh, h)));
  return stats;
}

}  // namespace hexlayer
