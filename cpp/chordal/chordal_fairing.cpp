#include "chordal/chordal_fairing.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace hexlayer {
namespace {

constexpr double kLambda = 0.5, kMu = -0.53;  // Taubin's pass band: noise goes, the shape stays

struct EdgeGraph {
  std::vector<std::vector<int>> neighbours;  // vertices sharing a facet edge
  std::vector<char> onRim;                   // on an edge of one facet only
};

EdgeGraph edgeGraph(const ChordalSurface& s) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : s.facets) {
    const int n = f[3] < 0 ? 3 : 4;
    for (int k = 0; k < n; ++k) ++uses[std::minmax(f[k], f[(k + 1) % n])];
  }
  EdgeGraph g{std::vector<std::vector<int>>(s.vertices.size()), std::vector<char>(s.vertices.size(), 0)};
  for (const auto& [edge, count] : uses) {
    g.neighbours[edge.first].push_back(edge.second);
    g.neighbours[edge.second].push_back(edge.first);
    if (count == 1) g.onRim[edge.first] = g.onRim[edge.second] = 1;
  }
  return g;
}

// One Laplacian step v += factor (mean of the neighbours - v) on every vertex off the rim.
void laplacianStep(std::vector<Vec3>& v, const EdgeGraph& g, double factor) {
  std::vector<Vec3> next = v;
  for (size_t i = 0; i < v.size(); ++i) {
    if (g.onRim[i] || g.neighbours[i].empty()) continue;
    Vec3 mean = Vec3::Zero();
    for (int j : g.neighbours[i]) mean += v[j];
    next[i] = v[i] + factor * (mean / static_cast<double>(g.neighbours[i].size()) - v[i]);
  }
  v.swap(next);
}

}  // namespace

void fairChordalSurface(ChordalSurface& s, int iterations) {
  const EdgeGraph g = edgeGraph(s);
  for (int it = 0; it < iterations; ++it) {
    laplacianStep(s.vertices, g, kLambda);
    laplacianStep(s.vertices, g, kMu);
  }
}

}  // namespace hexlayer
