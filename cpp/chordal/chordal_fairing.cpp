#include "chordal/chordal_fairing.hpp"

#include <algorithm>

namespace hexlayer {
namespace {

constexpr double kLambda = 0.5, kMu = -0.53;  // Taubin's pass band: noise goes, the shape stays

struct EdgeGraph {
  std::vector<std::vector<int>> neighbours;  // vertices sharing a facet edge
  std::vector<char> onRim;                   // on an edge of one facet only
};

EdgeGraph edgeGraph(const ChordalSurface& s) {
  EdgeGraph g{std::vector<std::vector<int>>(s.vertices.size()), std::vector<char>(s.vertices.size(), 0)};
  for (const auto& [edge, count] : facetEdgeUses(s)) {
    g.neighbours[edge.first].push_back(edge.second);
    g.neighbours[edge.second].push_back(edge.first);
    if (count == 1) g.onRim[edge.first] = g.onRim[edge.second] = 1;
  }
  return g;
}

// One Laplacian step v += factor n (n · (mean of the neighbours - v)) on every vertex off the rim.
// Only the normal part moves: the zigzag goes, while the vertices do not slide along the surface
// (which could fold facets over the rim of a hole).
void laplacianStep(ChordalSurface& s, const EdgeGraph& g, double factor) {
  const std::vector<Vec3> normal = vertexNormals(s);
  std::vector<Vec3> next = s.vertices;
  for (size_t i = 0; i < next.size(); ++i) {
    if (g.onRim[i] || g.neighbours[i].empty()) continue;
    Vec3 mean = Vec3::Zero();
    for (int j : g.neighbours[i]) mean += s.vertices[j];
    const Vec3 towardMean = mean / static_cast<double>(g.neighbours[i].size()) - s.vertices[i];
    next[i] += factor * normal[i].dot(towardMean) * normal[i];
  }
  s.vertices.swap(next);
}

}  // namespace

void fairChordalSurface(ChordalSurface& s, int iterations) {
  const EdgeGraph g = edgeGraph(s);
  for (int it = 0; it < iterations; ++it) {
    laplacianStep(s, g, kLambda);
    laplacianStep(s, g, kMu);
  }
}

}  // namespace hexlayer
