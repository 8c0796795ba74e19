#include "sweep/smoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/groups.hpp"
#include "core/sweep_halves.hpp"
#include "quality/quality.hpp"

namespace hexlayer {
namespace {

constexpr double kPoorHex = 0.6;               // the nodes of hexes below this scaled Jacobian are smoothed
constexpr int kMaxRounds = 20;                 // rounds over those nodes, fewer if a round moves none
constexpr double kSteps[] = {1.0, 0.5, 0.25};  // shares of the way to the neighbours' mean tried, longest first
constexpr double kMinGain = 1e-6;              // a move must raise the node's worst hex by at least this
constexpr double kBadHex = 0.2;                // then the nodes of hexes still below this are pattern-searched
constexpr double kSearchGoal = 0.3;            // they lower the shortfall of their hexes below this
constexpr double kShortEdge = 0.2;  // nor shorten an edge of theirs below this share of their mean edge length
constexpr double kSearchSteps[] = {0.3, 0.1, 0.03};  // their steps, in mean edge lengths, longest first

// How a node may move: not at all, freely (inside the part), on the faces of one side, or along the edges where
// one side's wall meets the rim.
struct Freedom {
  bool moves = false;
  std::optional<Side> on;      // the side whose faces (or rim edges) it stays on; none: free
  bool alongRimEdges = false;  // on the rim edges of `on`
  std::optional<Side> orOn;    // the other side whose faces it may go onto, the nearer
};

// [in] rimEdges: whether the nodes on the CAD edges where the walls meet the rim may slide along them.
Freedom freedomOf(const HexMesh& mesh, const WallSides& sides, int v, bool rimEdges) {
  const bool wallLayer = mesh.nodeLayer[v] == 0 || mesh.nodeLayer[v] == mesh.layers;
  if (mesh.nodeOnRim[v] == kRimSwept && wallLayer && rimEdges)
    return {true, mesh.nodeLayer[v] == 0 ? Side::Bottom : Side::Top, true};
  if (mesh.nodeOnRim[v] == kRimCap || (mesh.nodeOnRim[v] == kRimSwept && wallLayer))
    return {};  // on a CAD edge or a cap
  if (mesh.nodeFace[v] >= 0 && wallLayer && !mesh.nodeOnRim[v] && sides.faces[mesh.nodeFace[v]].side == Side::Lateral)
    // A wall's node on a rim face, off the rim: the middle of the rounds of a step where the wall's thickness
    // changes faces along the wall. It may go back onto the wall's faces.
    return {true, mesh.nodeLayer[v] == 0 ? Side::Bottom : Side::Top, false, Side::Lateral};
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

// Where node v goes when sent to `to`: there if it is free, else the nearest point of its side's faces.
// [in] walls, f: v's freedom, to.
std::optional<FacePoint> placeAt(const WallProjector& walls, const Freedom& f, const Vec3& to) {
  if (!f.on) return FacePoint{to, -1};
  if (f.alongRimEdges) return walls.projectOntoRimEdges(*f.on, to);
  std::optional<FacePoint> at = walls.project(*f.on, to);
  if (!f.orOn) return at;
  std::optional<FacePoint> other = walls.project(*f.orOn, to);
  if (!at || (other && (other->point - to).norm() < (at->point - to).norm())) return other;
  return at;
}

// measure(v) were node v at `at` (it stays where it is). [in,out] mesh: v moved and back.
template <class Measure>
auto measureIfAt(HexMesh& mesh, int v, const Vec3& at, const Measure& measure) {
  const Vec3 from = mesh.nodes[v];
  mesh.nodes[v] = at;
  const auto value = measure(v);
  mesh.nodes[v] = from;
  return value;
}

void moveTo(HexMesh& mesh, const Freedom& f, int v, const FacePoint& at) {
  mesh.nodes[v] = at.point;
  if (f.on) mesh.nodeFace[v] = at.face;
}

// One Laplacian move of node v: the longest step of kSteps towards its neighbours' mean that raises its worst hex
// by kMinGain. [in,out] mesh; [in] walls, f: v's freedom, around: its neighbours. Returns whether it moved.
template <class Worst>
bool laplacianMove(HexMesh& mesh, const WallProjector& walls, const Freedom& f, int v, const std::vector<int>& around,
                   const Worst& worstAround) {
  Vec3 mean = Vec3::Zero();
  for (int n : around) mean += mesh.nodes[n];
  mean /= static_cast<double>(around.size());
  const Vec3 from = mesh.nodes[v];
  const double before = worstAround(v);
  for (double step : kSteps) {
    const std::optional<FacePoint> at = placeAt(walls, f, from + step * (mean - from));
    if (!at) return false;
    if (measureIfAt(mesh, v, at->point, worstAround) > before + kMinGain) return moveTo(mesh, f, v, *at), true;
  }
  return false;
}

// The shortest of the edges from p to the nodes `around`. [in] mesh, p, around.
double shortestEdge(const HexMesh& mesh, const Vec3& p, const std::vector<int>& around) {
  double shortest = std::numeric_limits<double>::infinity();
  for (int n : around) shortest = std::min(shortest, (mesh.nodes[n] - p).norm());
  return shortest;
}

// The worst hex around a node and the sum of the squares of its hexes' shortfall below kSearchGoal.
struct HexesAround {
  double worst = 1, shortfall = 0;
};

// One pattern-search move of node v: of the steps towards and away from each neighbour (kSearchSteps of its mean
// edge length: the directions turn and scale with the mesh), the one that lowers its hexes' shortfall most,
// longest steps first, keeping its worst hex no worse and its edges no shorter than kShortEdge of that mean (the
// scaled Jacobian does not see an edge shrink: two nodes drawn together would leave a collapsed hex). Reaches
// what the Laplacian move cannot: a node that must move away from its neighbours' mean to untangle a hex.
// [in,out] mesh; [in] walls, f, around; hexesAround(v): v's HexesAround. Returns whether it moved.
template <class Measure>
bool searchMove(HexMesh& mesh, const WallProjector& walls, const Freedom& f, int v, const std::vector<int>& around,
                const Measure& hexesAround) {
  const Vec3 from = mesh.nodes[v];
  double length = 0;
  for (int n : around) length += (mesh.nodes[n] - from).norm();
  length /= static_cast<double>(around.size());
  const HexesAround before = hexesAround(v);
  for (double step : kSearchSteps) {
    std::optional<FacePoint> best;
    double bestShortfall = before.shortfall - kMinGain;
    for (int n : around)
      for (double sign : {1.0, -1.0}) {
        const Vec3 to = from + sign * step * length * (mesh.nodes[n] - from).normalized();
        const std::optional<FacePoint> at = placeAt(walls, f, to);
        if (!at) return false;
        if (shortestEdge(mesh, at->point, around) < kShortEdge * length) continue;
        const HexesAround after = measureIfAt(mesh, v, at->point, hexesAround);
        if (after.worst >= before.worst && after.shortfall < bestShortfall) best = at, bestShortfall = after.shortfall;
      }
    if (best) return moveTo(mesh, f, v, *best), true;
  }
  return false;
}

// Gauss-Seidel rounds over the candidate nodes, each moved by `move` (the same moves for the same mesh), until a
// round moves none or kMaxRounds: in index order, or on a mesh large enough in two halves side by side and their seam
// after them (sweep_halves.hpp: a move reads only the nodes of the hexes around its node), a node whose hexes did not
// change since its last visit passed by (MoveClock). Returns the moves kept.
template <class Move>
std::size_t smoothRounds(HexMesh& mesh, const WallSides& sides, const std::vector<char>& candidate,
                         const Groups<std::size_t>& hexesAt, const std::vector<std::vector<int>>& neighbours,
                         bool rimEdges, const Move& move) {
  const SweepHalves order = sweepHalves(
      mesh.nodes, [&](int v) { return candidate[v] != 0; }, hexesAt, [&](std::size_t h) { return mesh.hexes[h]; });
  std::size_t total = 0;
  MoveClock clock(mesh.nodes.size());  // a node whose hexes' nodes did not move since its last visit is passed by
  const long n = static_cast<long>(mesh.nodes.size());
  for (int round = 0; round < kMaxRounds; ++round) {
    std::array<std::size_t, 3> moved{0, 0, 0};  // per part of the sweep
    sweepInHalves(order, [&](int v, int part) {
      if (!candidate[v] || clock.unchanged(
                               hexesAt, [&](std::size_t h) { return mesh.hexes[h]; }, v))
        return;
      const long t = round * n + order.position[v];
      clock.visit(v, t);
      const Freedom f = freedomOf(mesh, sides, v, rimEdges);
      if (f.moves && !neighbours[v].empty() && move(f, v)) ++moved[part], clock.moved(v, t);
    });
    const std::size_t inRound = moved[0] + moved[1] + moved[2];
    total += inRound;
    if (inRound == 0) break;
  }
  return total;
}

// The scaled Jacobian of every hex. [in] mesh.
std::vector<double> scaledJacobians(const HexMesh& mesh) {
  std::vector<double> sj(mesh.hexes.size());
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) sj[h] = hexScaledJacobian(hexCorners(mesh, h));
  return sj;
}

// The nodes of the hexes whose scaled Jacobian (sj) is below `below`. [in] mesh, sj, below.
std::vector<char> nodesOfHexesBelow(const HexMesh& mesh, const std::vector<double>& sj, double below) {
  std::vector<char> candidate(mesh.nodes.size(), 0);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    if (sj[h] < below)
      for (int v : mesh.hexes[h]) candidate[v] = 1;
  return candidate;
}

// The nodes `nodes` and those of every hex with one of them. [in] mesh, nodes: one flag per node.
std::vector<char> withHexesAround(const HexMesh& mesh, const std::vector<char>& nodes) {
  std::vector<char> out = nodes;
  for (const auto& hex : mesh.hexes)
    if (std::any_of(hex.begin(), hex.end(), [&](int v) { return nodes[v] != 0; }))
      for (int v : hex) out[v] = 1;
  return out;
}

// The candidates but the pinned nodes. [in] candidate, pinned: one flag per node (pinned empty: none).
std::vector<char> unpinned(std::vector<char> candidate, const std::vector<char>& pinned) {
  for (std::size_t v = 0; v < pinned.size() && v < candidate.size(); ++v)
    if (pinned[v]) candidate[v] = 0;
  return candidate;
}

}  // namespace

SmoothingStats smoothPoorHexes(HexMesh& mesh, const WallProjector& walls, const WallSides& sides,
                               const std::vector<char>& pinned) {
  SmoothingStats stats;
  const std::vector<double> sj = scaledJacobians(mesh);
  for (const double q : sj) {
    stats.worstBefore = std::min(stats.worstBefore, q);
    stats.poorHexes += q < kPoorHex;
  }
  stats.worstAfter = stats.worstBefore;
  if (stats.poorHexes == 0) return stats;
  const Groups<std::size_t> hexesAt = groupByKey<std::size_t>(mesh.nodes.size(), [&](auto emit) {
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
      for (int v : mesh.hexes[h]) emit(static_cast<std::size_t>(v), h);
  });
  const std::vector<std::vector<int>> neighbours = edgeNeighbours(mesh);
  auto hexesAround = [&](int v) {
    HexesAround a;
    for (std::size_t i = hexesAt.start[v]; i < hexesAt.start[v + 1]; ++i) {
      const double q = hexScaledJacobian(hexCorners(mesh, hexesAt.items[i]));
      a.worst = std::min(a.worst, q);
      a.shortfall += std::pow(std::max(0.0, kSearchGoal - q), 2);
    }
    return a;
  };
  auto worstAround = [&](int v) { return hexesAround(v).worst; };
  stats.nodesMoved = smoothRounds(
      mesh, sides, unpinned(nodesOfHexesBelow(mesh, sj, kPoorHex), pinned), hexesAt, neighbours, false,
      [&](const Freedom& f, int v) { return laplacianMove(mesh, walls, f, v, neighbours[v], worstAround); });
  stats.searchMoves = smoothRounds(
      mesh, sides, unpinned(withHexesAround(mesh, nodesOfHexesBelow(mesh, scaledJacobians(mesh), kBadHex)), pinned),
      hexesAt, neighbours, true,
      [&](const Freedom& f, int v) { return searchMove(mesh, walls, f, v, neighbours[v], hexesAround); });
  const std::vector<double> after = scaledJacobians(mesh);
  stats.worstAfter = *std::min_element(after.begin(), after.end());
  return stats;
}

}  // namespace hexlayer
