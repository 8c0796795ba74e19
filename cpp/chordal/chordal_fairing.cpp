#include "chordal/chordal_fairing.hpp"

#include <algorithm>

#include "core/groups.hpp"

namespace hexlayer {
namespace {

constexpr double kLambda = 0.5, kMu = -0.53;  // Taubin's pass band: noise goes, the shape stays

struct EdgeGraph {
  Groups<int> neighbours;   // the vertices sharing a facet edge with vertex i: items[start[i] .. start[i + 1])
  std::vector<char> onRim;  // on an edge of one facet only
};

EdgeGraph edgeGraph(const ChordalSurface& s) {
  const auto uses = facetEdgeUses(s);
  EdgeGraph g{groupByKey<int>(s.vertices.size(),
                              [&](auto emit) {
                                for (const auto& [edge, count] : uses)
                                  emit(edge.first, edge.second), emit(edge.second, edge.first);
                              }),
              std::vector<char>(s.vertices.size(), 0)};
  for (const auto& [edge, count] : uses)
    if (count == 1) g.onRim[edge.first] = g.onRim[edge.second] = 1;
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
    const int first = g.neighbours.start[i], end = g.neighbours.start[i + 1];
    if (g.onRim[i] || first == end) continue;
    Vec3 mean = Vec3::Zero();
    for (int k = first; k < end; ++k) mean += s.vertices[g.neighbours.items[k]];
    const Vec3 towardMean = mean / static_cast<double>(end - first) - s.vertices[i];
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
