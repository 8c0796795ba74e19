#include "sweep/cap_template.hpp"

#include <cmath>
#include <numeric>

#include "core/polygon.hpp"

namespace hexlayer {
namespace {

// A node on the half circle at `degrees` from the outward direction (-90 bottom .. 90 top), as a fraction of
// the arc from the bottom.
double atDegrees(double degrees) { return (degrees + 90) / 180; }

// 2 layers: the column's middle M and two inner nodes S, Z on the mid-line; six chords, the profile's nodes at
// -75, -47.5, 0, 47.5, 75 degrees. Quads B M S A5, M T A1 S, A5 S Z A4, S A1 A2 Z, A4 Z A2 A3 (A1 top .. A5
// bottom): in the half disc their scaled Jacobians are 0.99, 0.99, 0.92, 0.92, 0.74 (the tip quad's corner at
// A3), where a structured cap of 4 chords has 0.71 twice, and they leave out 0.113 of the half disc's 1.571
// where it leaves out 0.157. Found by a search over the symmetric placements for the least sum of 1 - scaled
// Jacobian with every quad at least 0.7 (six even chords leave out 0.071 but allow no quad above 0.61).
CapTemplate twoLayers() {
  CapTemplate t;
  t.layers = 2;
  for (double deg : {-75.0, -47.5, 0.0, 47.5, 75.0}) t.onProfile.push_back(atDegrees(deg));
  t.inside = {Vec2(0.175, 0), Vec2(0.35, 0)};
  enum { B, M, T, A5, A4, A3, A2, A1, S, Z };
  t.quads = {{B, M, S, A5}, {M, T, A1, S}, {A5, S, Z, A4}, {S, A1, A2, Z}, {A4, Z, A2, A3}};
  return t;
}

// 3 layers: a ring of quads along the profile (nodes at -60, -20, 20, 60 degrees), each profile node joined
// inwards to one of I1..I4, round two quads on the column's middle layer. Scaled Jacobians in the half disc 0.96,
// 0.90, 0.81, 0.90, 0.96 (ring), 0.99, 0.87 (inside), where a structured cap has 0.59 twice; found as above.
CapTemplate threeLayers() {
  CapTemplate t;
  t.layers = 3;
  for (double deg : {-60.0, -20.0, 20.0, 60.0}) t.onProfile.push_back(atDegrees(deg));
  t.inside = {Vec2(0.25, -0.3), Vec2(0.6, -0.1), Vec2(0.6, 0.1), Vec2(0.25, 0.3)};
  enum { D0, D1, D2, D3, A4, A3, A2, A1, I4, I3, I2, I1 };
  t.quads = {{D0, D1, I4, A4}, {D1, D2, I1, I4}, {D2, D3, A1, I1}, {A4, I4, I3, A3},
             {I4, I1, I2, I3}, {I3, I2, A2, A3}, {I1, A1, A2, I2}};
  return t;
}

}  // namespace

CapTemplate structuredCap(int layers, int rows) {
  CapTemplate t;
  t.layers = layers;
  const int m = layers + 2 * rows;
  for (int i = 1; i < m; ++i) t.onProfile.push_back(static_cast<double>(i) / m);
  auto profileNode = [&](int i) { return layers + i; };  // the i-th of m - 1, from 1
  std::vector<std::vector<int>> column(rows + 1);
  for (int k = 0; k <= layers; ++k) column[0].push_back(k);
  for (int k = 0; k <= layers; ++k) column[rows].push_back(profileNode(rows + k));
  for (int j = 1; j < rows; ++j) {
    column[j].push_back(profileNode(j));
    for (int k = 1; k < layers; ++k) {
      column[j].push_back(t.firstInside() + static_cast<int>(t.inside.size()));
      const Vec2 straight = templatePosition(t, k), outer = templatePosition(t, column[rows][k]);
      t.inside.push_back(straight + (static_cast<double>(j) / rows) * (outer - straight));
    }
    column[j].push_back(profileNode(m - j));
  }
  // Inside nodes are numbered after the profile's: firstInside() was the same for every one added above.
  for (int j = 1; j <= rows; ++j)
    for (int k = 0; k < layers; ++k)
      t.quads.push_back({column[j - 1][k], column[j - 1][k + 1], column[j][k + 1], column[j][k]});
  return t;
}

std::optional<CapTemplate> drawnCap(int layers) {
  if (layers == 2) return twoLayers();
  if (layers == 3) return threeLayers();
  return std::nullopt;
}

Vec2 templatePosition(const CapTemplate& t, int node) {
  if (node <= t.layers) return Vec2(0, 2.0 * node / t.layers - 1);
  if (node < t.firstInside()) {
    const double phi = M_PI * (t.onProfile[node - t.layers - 1] - 0.5);
    return Vec2(std::cos(phi), std::sin(phi));
  }
  return t.inside[node - t.firstInside()];
}

std::vector<int> templateBoundary(const CapTemplate& t) {
  std::vector<int> polygon(t.layers + 1);
  std::iota(polygon.begin(), polygon.end(), 0);
  for (int i = t.firstInside() - 1; i > t.layers; --i) polygon.push_back(i);
  return polygon;
}

std::vector<std::vector<double>> insideWeights(const CapTemplate& t) {
  std::vector<Vec2> polygon;
  for (int node : templateBoundary(t)) polygon.push_back(templatePosition(t, node));
  std::vector<std::vector<double>> weights;
  for (const Vec2& x : t.inside) weights.push_back(meanValueWeights({polygon}, x));
  return weights;
}

}  // namespace hexlayer
