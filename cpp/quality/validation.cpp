#include "quality/validation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hexlayer {
namespace {

// Relative to the mesh's extent: nodes this close are one node written twice.
constexpr double kCoincidentTolerance = 1e-7;

std::string where(const Vec3& p) {
  std::ostringstream s;
  s << std::setprecision(6) << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

ValidationFailure failure(const std::string& check, std::size_t count, const Vec3& at, const std::string& what) {
  std::ostringstream s;
  s << check << ": " << count << " " << what << " at " << where(at);
  return {check, count, at, s.str()};
}

// A hex whose 8 corners are not 8 distinct nodes of the mesh.
bool degenerate(std::array<int, 8> hex, std::size_t nodes) {
  std::sort(hex.begin(), hex.end());
  return std::adjacent_find(hex.begin(), hex.end()) != hex.end() || hex.front() < 0 ||
         static_cast<std::size_t>(hex.back()) >= nodes;
}

std::optional<ValidationFailure> checkHexes(const HexMesh& mesh) {
  std::size_t bad = 0, first = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    if (degenerate(mesh.hexes[h], mesh.nodes.size()) && bad++ == 0) first = h;
  if (bad == 0) return std::nullopt;
  Vec3 at = Vec3::Zero();
  for (int v : mesh.hexes[first])
    if (v >= 0 && static_cast<std::size_t>(v) < mesh.nodes.size()) at += mesh.nodes[v] / 8;
  return failure("hexes", bad, at, "elements without 8 distinct corner nodes, the first");
}

std::optional<ValidationFailure> checkConformal(const HexMesh& mesh) {
  if (mesh.nodes.empty()) return std::nullopt;
  const CoincidentNodes c = findCoincidentNodes(mesh, kCoincidentTolerance * boxDiagonal(mesh.nodes));
  if (c.pairs == 0) return std::nullopt;
  return failure("conformal", c.pairs, mesh.nodes[c.firstNode],
                 "pairs of duplicate nodes (the hexes there are not joined), the first");
}

std::optional<ValidationFailure> checkWatertight(const HexMesh& mesh, const BoundaryCheck& b) {
  const std::size_t bad = b.openEdges + b.nonManifoldEdges + b.inconsistentlyOrientedEdges;
  if (bad == 0) return std::nullopt;
  std::ostringstream what;
  what << "boundary edges not shared by exactly two boundary faces in opposite directions (" << b.openEdges << " open, "
       << b.nonManifoldEdges << " non-manifold, " << b.inconsistentlyOrientedEdges << " flipped), the first";
  const Vec3 at = 0.5 * (mesh.nodes[b.firstBadEdge[0]] + mesh.nodes[b.firstBadEdge[1]]);
  return failure("watertight", bad, at, what.str());
}

std::optional<ValidationFailure> checkVolume(const QualityReport& q, double cadVolume) {
  const double error = (q.volume - cadVolume) / cadVolume;
  if (std::abs(error) <= kMaxVolumeError) return std::nullopt;
  std::ostringstream s;
  s << std::setprecision(6) << "volume: the mesh's " << q.volume << " differs from the CAD's " << cadVolume << " by "
    << std::showpos << 100 * error << std::noshowpos << " % (at most " << 100 * kMaxVolumeError << " %)";
  return ValidationFailure{"volume", 1, std::nullopt, s.str()};
}

// Only on a watertight boundary: an open one's Euler characteristic says nothing of its holes.
std::optional<ValidationFailure> checkTopology(const BoundaryCheck& b, std::optional<long> cadEuler) {
  const long apart = cadEuler ? *cadEuler - b.eulerCharacteristic : 0;  // chi = 2 - 2 genus per closed shell
  if (apart <= 0 || !b.watertight()) return std::nullopt;
  const std::size_t holes = static_cast<std::size_t>((apart + 1) / 2);
  std::ostringstream s;
  s << "topology: the mesh has " << holes << " hole(s) the part does not have (its boundary's Euler characteristic "
    << b.eulerCharacteristic << ", the part's " << *cadEuler << ")";
  return ValidationFailure{"topology", holes, std::nullopt, s.str()};
}

}  // namespace

std::vector<ValidationFailure> validateMesh(const HexMesh& mesh, const QualityReport& q, const BoundaryCheck& b,
                                            double cadVolume, std::optional<long> cadEuler) {
  std::vector<ValidationFailure> failures;
  if (mesh.hexes.empty()) return {{"hexes", 0, std::nullopt, "hexes: the mesh has no hex"}};
  for (auto f : {checkHexes(mesh),
                 q.inverted == 0 ? std::nullopt
                                 : std::optional(failure("inverted", q.inverted, q.worstAt,
                                                         "inverted hexes (scaled Jacobian <= 0), the worst")),
                 checkConformal(mesh), checkWatertight(mesh, b), checkVolume(q, cadVolume), checkTopology(b, cadEuler)})
    if (f) failures.push_back(*f);
  return failures;
}

}  // namespace hexlayer
