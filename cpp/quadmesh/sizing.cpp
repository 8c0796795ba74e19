#include "quadmesh/sizing.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hexlayer {
namespace {

std::vector<std::pair<int, int>> facetEdges(const ChordalSurface& s) {
  std::vector<std::pair<int, int>> out;
  for (const auto& [edge, uses] : facetEdgeUses(s)) out.push_back(edge);
  return out;
}

// h_i = min(h_i, h_j + g |x_i - x_j|) over the edges until nothing changes (a discrete Lipschitz bound).
void limitGradation(const ChordalSurface& s, const std::vector<std::pair<int, int>>& edges, double g,
                    std::vector<double>& h) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b] : edges) {
      const double d = g * (s.vertices[a] - s.vertices[b]).norm();
      if (h[a] > h[b] + d + 1e-12) h[a] = h[b] + d, changed = true;
      if (h[b] > h[a] + d + 1e-12) h[b] = h[a] + d, changed = true;
    }
  }
}

// Whether the chordal surface turns there more tightly than a bend of its wall can: a radius of curvature below the
// wall's thickness 2r (the sharp inside corner of a bent sheet, the fold where walls meet). The facets' fold there
// only gets sharper as they get smaller, and a quad as wide as the wall spans it anyway: the curvature term does
// not refine it. [in] curvature (chordalCurvature), radius: at a vertex.
bool isCrease(double curvature, double radius) { return curvature * 2 * radius > 1; }

// Quad edges round a closed boundary loop of the chordal surface (a hole's rim): fewer, and a small hole's loop
// collapses in the quad mesh (the hole is filled); eight make an o-grid round it. A loop shorter than the smallest
// quad edge is a pinhole between facets, not a hole: it is left alone.
constexpr double kEdgesRoundLoop = 8;

}  // namespace

std::vector<double> chordalCurvature(const ChordalSurface& s) {
  std::vector<double> sum(s.vertices.size(), 0);
  std::vector<int> count(s.vertices.size(), 0);
  for (const auto& [a, b] : facetEdges(s)) {
    const double length = (s.vertices[a] - s.vertices[b]).norm();
    if (length <= 0) continue;
    const double angle = std::acos(std::clamp(s.normals[a].dot(s.normals[b]), -1.0, 1.0));
    sum[a] += angle / length, sum[b] += angle / length;
    ++count[a], ++count[b];
  }
  for (size_t i = 0; i < sum.size(); ++i) sum[i] /= std::max(count[i], 1);
  return sum;
}

std::vector<double> adaptiveSizes(const ChordalSurface& s, const SizingOptions& o) {
  const double lo = o.minSize > 0 ? o.minSize : 0.25 * o.size, hi = o.maxSize > 0 ? o.maxSize : 4 * o.size;
  const double medianRadius = median(s.radius);
  const std::vector<double> curvature = chordalCurvature(s);
  const RimLoops loops = rimLoops(s);
  std::vector<double> h(s.vertices.size());
  for (size_t i = 0; i < h.size(); ++i) {
    h[i] = medianRadius > 0 ? o.size * s.radius[i] / medianRadius : o.size;  // §6.1: radius function
    if (curvature[i] > 0 && !isCrease(curvature[i], s.radius[i]))
      h[i] = std::min(h[i], o.turnPerQuad / curvature[i]);  // §6.1: curvature
    h[i] = std::clamp(h[i], lo, hi);
    if (const int loop = loops.loopOf[i]; loop >= 0 && loops.length[loop] >= lo)  // a hole's rim
      h[i] = std::min(h[i], std::max(lo, loops.length[loop] / kEdgesRoundLoop));
  }
  limitGradation(s, facetEdges(s), o.gradation, h);
  return h;
}

ChordalSizeField::ChordalSizeField(const ChordalLocator& chordal, const std::vector<double>& vertexSize)
    : chordal_(&chordal),
      vertexSize_(&vertexSize),
      reachLo_(Vec3::Constant(INFINITY)),
      reachHi_(Vec3::Constant(-INFINITY)) {
  for (const Vec3& v : chordal.surface().vertices) reachLo_ = reachLo_.cwiseMin(v), reachHi_ = reachHi_.cwiseMax(v);
  const double grow = reachLo_.allFinite() ? (reachHi_ - reachLo_).norm() : 0.0;
  reachLo_ -= Vec3::Constant(grow), reachHi_ += Vec3::Constant(grow);
}

double ChordalSizeField::at(const Vec3& p, int& facet) const {
  const std::vector<double>& size = *vertexSize_;
  const bool near = p.allFinite() && (p.array() >= reachLo_.array()).all() && (p.array() <= reachHi_.array()).all();
  if (!near && facet < 0) return *std::max_element(size.begin(), size.end());
  const ChordalPoint found = near ? chordal_->locate(p, facet) : ChordalPoint{};  // far: the facet before, evenly
  if (near) facet = found.facet;
  const auto& f = chordal_->surface().facets[facet];
  const int corners = f[3] < 0 ? 3 : 4;
  double h = 0;
  for (int k = 0; k < corners; ++k) h += (near ? found.weights[k] : 1.0 / corners) * size[f[k]];  // sum w_k h_k
  return h;
}

}  // namespace hexlayer
