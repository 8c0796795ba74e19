#include "chordal/chordal_fairing.hpp"

#include <algorithm>

namespace hexlayer {
namespace {

constexpr double kLambda = 0.5, kMu = -0.53;  // Taubin's pass band: noise goes, the shape stays

struct EdgeGraph {
  std::vector<std::size_t> start;  // the vertices sharing a facet edge with vertex i: neighbours[start[i] .. start[i + 1])
  std::vector<int> neighbours;
  std::vector<char> onRim;         // on an edge of one facet only
};

EdgeGraph edgeGraph(const ChordalSurface& s) {
  const auto uses = facetEdgeUses(s);
  EdgeGraph g{std::vector<std::size_t>(s.vertices.size() + 1, 0), std::vector<int>(2 * uses.size()), std::vector<char>(s.vertices.size(), 0)};
  for (const auto& [edge, count] : uses) ++g.start[edge.first + 1], ++g.start[edge.second + 1];
  for (std::size_t i = 0; i < s.vertices.size(); ++i) g.start[i + 1] += g.start[i];
  std::vector<std::size_t> fill(g.start.begin(), g.start.end() - 1);
  for (const auto& [edge, count] : uses) {
    g.neighbours[fill[edge.first]++] = edge.second;
    g.neighbours[fill[edge.second]++] = edge.first;
    if (count == 1) g.onRim[edge.first] = g.onRim[edge.second] = 1;
  }
  return g;
}

// One Laplacian step v += factor n (n · (mean of the neighbours - v)) on every vertex off the rim
// (from where they all were: in parallel). Only the normal part moves: the zigzag goes, while the
// vertices do not slide along the surface (which could fold facets over the rim of a hole).
void laplacianStep(ChordalSurface& s, const EdgeGraph& g, double factor) {
  const std::vector<Vec3> normal = vertexNormals(s);
  std::vector<Vec3> next = s.vertices;
  #pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(next.size()); ++i) {
    if (g.onRim[i] || g.start[i] == g.start[i + 1]) continue;
    Vec3 mean = Vec3::Zero();
    for (std::size_t k = g.start[i]; k < g.start[i + 1]; ++k) mean += s.vertices[g.neighbours[k]];
    const Vec3 towardMean = mean / static_cast<double>(g.start[i + 1] - g.start[i]) - s.vertices[i];
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
