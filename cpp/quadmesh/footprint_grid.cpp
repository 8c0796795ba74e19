#include "quadmesh/footprint_grid.hpp"

#include <cmath>

#include "core/error.hpp"

namespace hexlayer {
namespace {

constexpr double kOnSide = 1e-6;  // of the rectangle's width: a foot line this near a side is on it

// The grid lines along one direction: evenly spaced from lo to the foot's first line, the foot's lines, evenly
// spaced from its last line to hi. [out] first: the index of the foot's first line.
std::vector<double> gridLines(double lo, double hi, const std::vector<double>& foot, double size, int& first) {
  const double tolerance = kOnSide * (hi - lo);
  if (foot.size() < 2 || foot.front() < lo - tolerance || foot.back() > hi + tolerance)
    throw geometryError("T-junction: the rib's foot does not lie on the sheet it stands on");
  std::vector<double> lines;
  if (const double gap = foot.front() - lo; gap > tolerance) {
    const int n = std::max(1, static_cast<int>(std::lround(gap / size)));
    for (int k = 0; k < n; ++k) lines.push_back(lo + gap * k / n);
  }
  first = static_cast<int>(lines.size());
  lines.insert(lines.end(), foot.begin(), foot.end());
  if (const double gap = hi - foot.back(); gap > tolerance) {
    const int n = std::max(1, static_cast<int>(std::lround(gap / size)));
    for (int k = 1; k <= n; ++k) lines.push_back(foot.back() + gap * k / n);
  }
  return lines;
}

}  // namespace

FootprintGrid footprintGrid(const Footprint& f) {
  int firstU = 0, firstV = 0;
  const std::vector<double> us = gridLines(f.uMin, f.uMax, f.columns, f.size, firstU);
  const std::vector<double> vs = gridLines(f.vMin, f.vMax, f.rows, f.size, firstV);
  const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
  FootprintGrid g;
  for (double v : vs)
    for (double u : us) g.quads.nodes.push_back(f.origin + u * f.u + v * f.v);
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      const int a = j * nu + i;
      g.quads.quads.push_back({a, a + 1, a + nu + 1, a + nu});
    }
  g.quads.layout = QuadLayout::Grid;
  g.quads.structuredPatches = 1;
  g.strip.assign(f.rows.size(), std::vector<int>(f.columns.size()));
  for (std::size_t r = 0; r < f.rows.size(); ++r)
    for (std::size_t c = 0; c < f.columns.size(); ++c)
      g.strip[r][c] = (firstV + static_cast<int>(r)) * nu + firstU + static_cast<int>(c);
  for (std::size_t r = 0; r < f.feet.size(); ++r)
    for (std::size_t c = 0; c < f.feet[r].size(); ++c)
      g.quads.nodes[g.strip[r][c]] = f.origin + f.feet[r][c].x() * f.u + f.feet[r][c].y() * f.v;
  return g;
}

}  // namespace hexlayer
