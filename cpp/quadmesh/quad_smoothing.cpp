#include "quadmesh/quad_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hexlayer {

double quadScaledJacobian(const std::array<Vec3, 4>& p) {
  Vec3 n = (p[2] - p[0]).cross(p[3] - p[1]);
  if (n.norm() == 0) return -1;
  n.normalize();
  double sj = 1;
  for (int k = 0; k < 4; ++k) {
    const Vec3 e1 = p[(k + 1) % 4] - p[k], e2 = p[(k + 3) % 4] - p[k];
    const double len = e1.norm() * e2.norm();
    sj = std::min(sj, len > 0 ? n.dot(e1.cross(e2)) / len : -1.0);
  }
  return sj;
}

namespace {

constexpr double kGoodQuad = 0.97;  // quads below this scaled Jacobian get their nodes optimized

struct NodeQuads {
  std::vector<int> start, quads;  // quads around node i: quads[start[i] .. start[i+1])
};

NodeQuads quadsAroundNodes(const QuadMesh& q) {
  NodeQuads nq;
  nq.start.assign(q.nodes.size() + 1, 0);
  for (const auto& quad : q.quads)
    for (int v : quad) ++nq.start[v + 1];
  for (size_t i = 0; i < q.nodes.size(); ++i) nq.start[i + 1] += nq.start[i];
  nq.quads.resize(nq.start.back());
  std::vector<int> fill(nq.start.begin(), nq.start.end() - 1);
  for (size_t e = 0; e < q.quads.size(); ++e)
    for (int v : q.quads[e]) nq.quads[fill[v]++] = static_cast<int>(e);
  return nq;
}

std::vector<char> rimNodes(const QuadMesh& q) {
  std::unordered_map<std::uint64_t, int> use;
  auto key = [](int a, int b) { return (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b)); };
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k) ++use[key(quad[k], quad[(k + 1) % 4])];
  std::vector<char> rim(q.nodes.size(), 0);
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k)
      if (use[key(quad[k], quad[(k + 1) % 4])] == 1) rim[quad[k]] = rim[quad[(k + 1) % 4]] = 1;
  return rim;
}

std::array<Vec3, 4> corners(const QuadMesh& q, int e, int moved, const Vec3& at) {
  std::array<Vec3, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = q.quads[e][k] == moved ? at : q.nodes[q.quads[e][k]];
  return p;
}

// Worst quad around `node` if it stood at `at`.
double worstAround(const QuadMesh& q, const NodeQuads& nq, int node, const Vec3& at) {
  double worst = 1;
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k)
    worst = std::min(worst, quadScaledJacobian(corners(q, nq.quads[k], node, at)));
  return worst;
}

// Area-weighted mean of the centroids of the quads around the node.
Vec3 centroidTarget(const QuadMesh& q, const NodeQuads& nq, int node) {
  Vec3 sum = Vec3::Zero();
  double area = 0;
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k) {
    const auto p = corners(q, nq.quads[k], -1, Vec3::Zero());
    const double a = 0.5 * (p[2] - p[0]).cross(p[3] - p[1]).norm();
    sum += a * 0.25 * (p[0] + p[1] + p[2] + p[3]);
    area += a;
  }
  return area > 0 ? Vec3(sum / area) : q.nodes[node];
}

// Pattern search in the tangent plane: tries steps in eight directions, keeps the one that raises
// the worst quad around the node most, halves the step when none does; the result is projected
// back onto the chordal surface and kept if the worst quad is still better than before.
void improveWorst(QuadMesh& q, const NodeQuads& nq, const ChordalLocator& chordal, int node) {
  const double before = worstAround(q, nq, node, q.nodes[node]);
  double best = before, step = 0;
  Vec3 n = Vec3::Zero();
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k) {
    const auto p = corners(q, nq.quads[k], -1, Vec3::Zero());
    n += (p[2] - p[0]).cross(p[3] - p[1]);
    for (const Vec3& c : p) step = std::max(step, (c - q.nodes[node]).norm());
  }
  if (n.norm() == 0) return;
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.normalized().cross(t1);
  Vec3 at = q.nodes[node];
  for (step *= 0.2; step > 1e-3 * (q.nodes[node] - at).norm() + 1e-12 && step > 0;) {
    Vec3 bestAt = at;
    for (int d = 0; d < 8; ++d) {
      const double a = d * M_PI / 4;
      const Vec3 trial = at + step * (std::cos(a) * t1 + std::sin(a) * t2);
      const double w = worstAround(q, nq, node, trial);
      if (w > best + 1e-9) best = w, bestAt = trial;
    }
    if (bestAt == at) step *= 0.5;
    if (step < 1e-3 * std::sqrt(n.norm())) break;
    at = bestAt;
  }
  const Vec3 onSurface = chordal.locate(at).point;
  if (worstAround(q, nq, node, onSurface) > before) q.nodes[node] = onSurface;
}

}  // namespace

void smoothQuadMesh(QuadMesh& q, const ChordalLocator& chordal, int iterations) {
  const NodeQuads nq = quadsAroundNodes(q);
  const std::vector<char> rim = rimNodes(q);
  for (int it = 0; it < iterations; ++it)
    for (size_t i = 0; i < q.nodes.size(); ++i) {
      if (rim[i]) continue;
      const int node = static_cast<int>(i);
      const double before = worstAround(q, nq, node, q.nodes[i]);
      const Vec3 target = chordal.locate(centroidTarget(q, nq, node)).point;
      if (worstAround(q, nq, node, target) >= std::min(before, 0.999)) q.nodes[i] = target;
    }
  // Then the nodes of the worst quads are optimized for the worst quad around them.
  for (int it = 0; it < iterations; ++it)
    for (size_t i = 0; i < q.nodes.size(); ++i)
      if (!rim[i] && worstAround(q, nq, static_cast<int>(i), q.nodes[i]) < kGoodQuad) improveWorst(q, nq, chordal, static_cast<int>(i));
}

}  // namespace hexlayer
