#include "sweep/sweep.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "quality/quality.hpp"

namespace hexlayer {
namespace {

const double kTurned = std::cos(1e-5);   // a first line this far from the chordal normal was turned (aimed)
constexpr double kUntangleTarget = 0.2;  // columns below this scaled Jacobian get their directions smoothed

// Places the m + 1 hex nodes of quad node i on its sweep line along `normal` (§7.2); returns the line.
SweepLine placeSweepLine(HexMesh& mesh, const Vec3& q, int i, const Vec3& normal, double radius,
                         const std::vector<double>& offsets, const WallMap& walls) {
  const SweepLine line = walls(q, normal, radius);
  const int stride = static_cast<int>(offsets.size());
  for (int k = 0; k < stride; ++k) mesh.nodes[i * stride + k] = layerNode(q, line, offsets[k]);
  mesh.nodes[i * stride] = line.bottom, mesh.nodes[i * stride + stride - 1] = line.top;  // exactly on the walls
  mesh.nodeFace[i * stride] = line.bottomFace, mesh.nodeFace[i * stride + stride - 1] = line.topFace;
  return line;
}

double columnQuality(const HexMesh& mesh, int quad) {
  double worst = 1;
  for (int k = 0; k < mesh.layers; ++k)
    worst = std::min(worst, hexScaledJacobian(hexCorners(mesh, static_cast<size_t>(quad) * mesh.layers + k)));
  return worst;
}

}  // namespace

HexMesh layeredHexes(const QuadMesh& q, const std::vector<Vec3>& up, int m) {
  const std::vector<std::vector<int>> rim = rimEdgeNeighbours(q);  // the chordal surface's rim
  HexMesh mesh;
  mesh.layers = m;
  const int stride = m + 1;
  mesh.nodes.assign(q.nodes.size() * stride, Vec3::Zero());
  mesh.nodeLayer.resize(mesh.nodes.size());
  mesh.nodeOnRim.resize(mesh.nodes.size());
  mesh.nodeFace.assign(mesh.nodes.size(), -1);
  for (size_t i = 0; i < q.nodes.size(); ++i)
    for (int k = 0; k <= m; ++k) {
      mesh.nodeLayer[i * stride + k] = k;
      mesh.nodeOnRim[i * stride + k] = !rim[i].empty();
    }
  mesh.hexes.reserve(q.quads.size() * m);
  for (std::array<int, 4> quad : q.quads) {
    const Vec3 n = (q.nodes[quad[2]] - q.nodes[quad[0]]).cross(q.nodes[quad[3]] - q.nodes[quad[1]]);
    const Vec3 sweepDir = up[quad[0]] + up[quad[1]] + up[quad[2]] + up[quad[3]];
    if (n.dot(sweepDir) < 0) std::swap(quad[1], quad[3]);  // counter-clockwise seen from the top
    for (int k = 0; k < m; ++k) {                          // the quad's nodes in layers k and k + 1
      std::array<int, 8> hex;
      for (int c = 0; c < 4; ++c) hex[c] = quad[c] * stride + k, hex[c + 4] = quad[c] * stride + k + 1;
      mesh.hexes.push_back(hex);
    }
  }
  return mesh;
}

SweepDirection interpolateSweep(const ChordalSurface& chordal, const ChordalPoint& at) {
  const auto& f = chordal.facets[at.facet];
  SweepDirection d{normalAt(chordal, at), 0};
  for (int k = 0; k < (f[3] < 0 ? 3 : 4); ++k)
    d.radius += at.weights[k] * chordal.radius[f[k]];  // Eq. 6 (Eq. 5 on an edge)
  d.normal.normalize();  // the weighted sum of unit normals is shorter than 1: sweep along a unit vector
  return d;
}

std::vector<double> layerOffsets(int m) {
  std::vector<double> offsets(m + 1);
  const double s = 2.0 / m;  // s = 2r / m, in units of r
  for (int k = 0; k <= m; ++k) offsets[k] = s * (k - 0.5 * m);
  return offsets;
}

SweepLine radiusSweepLine(const Vec3& q, const Vec3& n, double r) { return {q - r * n, q + r * n, -1, -1}; }

Vec3 layerNode(const Vec3& q, const SweepLine& line, double t) {
  return t >= 0 ? Vec3(q + t * (line.top - q)) : Vec3(q - t * (line.bottom - q));
}

SweepResult sweepQuads(const QuadMesh& q, const ChordalLocator& chordal, int m, const WallMap& walls,
                       const WallMap& aimed) {
  if (m < 1) throw usageError("the number of layers must be at least 1");
  const std::vector<double> offsets = layerOffsets(m);
  std::vector<SweepDirection> dir(q.nodes.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(q.nodes.size()); ++i)
    dir[i] = interpolateSweep(chordal.surface(), chordal.locate(q.nodes[i]));

  std::vector<Vec3> normal(dir.size());
  for (size_t i = 0; i < dir.size(); ++i) normal[i] = dir[i].normal;
  SweepResult result{layeredHexes(q, normal, m), {}};
  auto place = [&](int i) { placeSweepLine(result.mesh, q.nodes[i], i, normal[i], dir[i].radius, offsets, walls); };
  const WallMap& first = aimed ? aimed : walls;
  ParallelErrors errors;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < static_cast<int>(q.nodes.size()); ++i)
    errors.run([&] {
      const SweepLine line = placeSweepLine(result.mesh, q.nodes[i], i, normal[i], dir[i].radius, offsets, first);
      if (const Vec3 d = (line.top - line.bottom).normalized(); aimed && d.dot(normal[i]) < kTurned) normal[i] = d;
    });
  errors.rethrow();
  result.untangled =
      untangleSweep(q, normal, kUntangleTarget, place, [&](int j) { return columnQuality(result.mesh, j); });
  return result;
}

std::vector<std::vector<int>> columnsByBottom(const HexMesh& mesh) {
  std::vector<int> above(mesh.nodes.size(), -1);
  for (const auto& h : mesh.hexes)
    for (int k = 0; k < 4; ++k) above[h[k]] = h[k + 4];
  std::vector<std::vector<int>> columns(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (mesh.nodeLayer[i] == 0)
      for (int v = static_cast<int>(i); v >= 0; v = above[v]) columns[i].push_back(v);
  return columns;
}

std::vector<char> placeFootEnds(HexMesh& mesh, const QuadMesh& quads, const std::vector<FootEnd>& feet, double near) {
  if (feet.empty()) return {};
  const std::vector<double> offsets = layerOffsets(mesh.layers);
  const std::size_t stride = offsets.size();
  std::vector<char> placed(mesh.nodes.size(), 0);
  for (const FootEnd& foot : feet) {
    if (foot.quadNode < 0 || (foot.quadNode + 1) * stride > mesh.nodes.size()) continue;
    const std::size_t first = foot.quadNode * stride, last = first + mesh.layers;
    const bool top = (mesh.nodes[last] - foot.at).norm() < (mesh.nodes[first] - foot.at).norm();
    placed[top ? last : first] = 1;
    if (!foot.lap && (mesh.nodes[top ? last : first] - foot.at).norm() <= near) continue;
    const Vec3& q = quads.nodes[foot.quadNode];
    for (std::size_t k = 0; k < stride; ++k)  // layerNode's half line: q + |t| (end - q) on the end's side
      if (top ? offsets[k] > 0 : offsets[k] < 0) mesh.nodes[first + k] = q + std::abs(offsets[k]) * (foot.at - q);
  }
  return placed;
}

}  // namespace hexlayer
