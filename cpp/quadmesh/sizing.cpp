#include "quadmesh/sizing.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/point_grid.hpp"

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

// Quads across a gap of the chordal surface between two stretches of its rim facing each other (a ligament between
// holes, a hole near the rim, a slot): fewer, and a quad spans the gap, its nodes on both rims.
constexpr double kQuadsAcrossGap = 2;
// Two rim points face each other across the surface where the chord between them leaves each within this angle of
// the direction into the surface there (cos 25 degrees): not two points beside each other on a rim, nor across the
// air between two sheets (the chord leaves the surface).
constexpr double kFacing = 0.9;
// Two points of one rim loop face each other only if the loop between them is this many times their chord at least:
// not round a convex corner (1.41 at a right angle) nor across the tip of a gusset (2.6 at 45 degrees; refined, its
// triangle grid's nodes left the gusset's faces), but across a slot deeper than it is wide.
constexpr double kAcrossArc = 3;

// Where each rim vertex lies along its rim loop: the length of the loop's edges walked from its first vertex; 0 off
// the rim. A vertex the rim passes twice gets the first pass's. [in] s; [in] edges: its facetEdgeUses. Returns one
// per vertex.
std::vector<double> arcAlongRim(const ChordalSurface& s,
                                const std::vector<std::pair<std::pair<int, int>, int>>& edges) {
  std::vector<std::vector<int>> next(s.vertices.size());
  for (const auto& [edge, uses] : edges)
    if (uses == 1) next[edge.first].push_back(edge.second), next[edge.second].push_back(edge.first);
  std::vector<double> arc(s.vertices.size(), 0);
  std::vector<char> walked(s.vertices.size(), 0);
  for (std::size_t start = 0; start < next.size(); ++start) {
    if (next[start].empty() || walked[start]) continue;
    walked[start] = 1;
    for (int at = static_cast<int>(start), to = next[start].front(); to >= 0 && !walked[to];) {
      arc[to] = arc[at] + (s.vertices[to] - s.vertices[at]).norm(), walked[to] = 1;
      const auto ahead = std::find_if(next[to].begin(), next[to].end(), [&](int v) { return !walked[v]; });
      at = to, to = ahead == next[to].end() ? -1 : *ahead;
    }
  }
  return arc;
}

// The unit direction into the surface at each rim vertex, in the plane of its rim facets: the mean of its rim edges'
// directions, each across its edge towards its facet's centre; zero off the rim. [in] s; [in] edges: its
// facetEdgeUses. Returns one per vertex.
std::vector<Vec3> intoSurface(const ChordalSurface& s, const std::vector<std::pair<std::pair<int, int>, int>>& edges) {
  std::map<std::pair<int, int>, int> rimEdges;
  for (const auto& [edge, uses] : edges)
    if (uses == 1) rimEdges.emplace(edge, 0);
  std::vector<Vec3> into(s.vertices.size(), Vec3::Zero());
  for (const auto& f : s.facets) {
    const int corners = f[3] < 0 ? 3 : 4;
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < corners; ++k) centre += s.vertices[f[k]] / corners;
    for (int k = 0; k < corners; ++k) {
      const int a = f[k], b = f[(k + 1) % corners];
      if (!rimEdges.count({std::min(a, b), std::max(a, b)})) continue;
      const Vec3 along = (s.vertices[b] - s.vertices[a]).normalized();
      Vec3 across = centre - 0.5 * (s.vertices[a] + s.vertices[b]);
      across -= across.dot(along) * along;
      if (across.norm() > 0) into[a] += across.normalized(), into[b] += across.normalized();
    }
  }
  for (Vec3& v : into)
    if (v.norm() > 0) v.normalize();
  return into;
}

// The gap across the surface at each rim vertex (the nearest rim vertex facing it: kFacing, kAcrossArc) if under
// reach[i]; infinity elsewhere. [in] s; [in] loops: its rim loops; [in] reach: per vertex, the farthest gap that
// matters. Returns one per vertex.
std::vector<double> gapsAcross(const ChordalSurface& s, const RimLoops& loops, const std::vector<double>& reach) {
  const auto edges = facetEdgeUses(s);  // sorted once for both
  const std::vector<Vec3> into = intoSurface(s, edges);
  const std::vector<double> arc = arcAlongRim(s, edges);
  auto alongLoop = [&](int i, int j) {  // the shorter way round the loop
    const double apart = std::abs(arc[i] - arc[j]);
    return std::min(apart, loops.length[loops.loopOf[i]] - apart);
  };
  std::vector<double> gap(s.vertices.size(), INFINITY);
  double cell = 0;
  for (std::size_t i = 0; i < into.size(); ++i)
    if (into[i].norm() > 0) cell = std::max(cell, reach[i]);
  PointGrid rim(cell);
  for (std::size_t i = 0; i < into.size(); ++i)
    if (into[i].norm() > 0) rim.insert(static_cast<int>(i), s.vertices[i]);
  for (std::size_t i = 0; i < into.size(); ++i) {
    if (into[i].norm() == 0) continue;
    rim.forEachNear(s.vertices[i], reach[i], [&](int j, const Vec3& q) {
      const Vec3 chord = q - s.vertices[i];
      const double length = chord.norm();
      const bool apart = loops.loopOf[j] != loops.loopOf[static_cast<int>(i)] ||
                         alongLoop(static_cast<int>(i), j) >= kAcrossArc * length;
      if (length > 0 && apart && into[i].dot(chord) > kFacing * length && -into[j].dot(chord) > kFacing * length)
        gap[i] = std::min(gap[i], length);
    });
  }
  return gap;
}

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
  std::vector<double> reach(h.size());  // a gap wider than kQuadsAcrossGap quads needs nothing
  for (size_t i = 0; i < h.size(); ++i) reach[i] = kQuadsAcrossGap * h[i];
  const std::vector<double> gap = gapsAcross(s, loops, reach);
  for (size_t i = 0; i < h.size(); ++i)
    if (std::isfinite(gap[i])) h[i] = std::min(h[i], std::max(lo, gap[i] / kQuadsAcrossGap));
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
