// Polygons in the plane.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace hexlayer {

// [in] p: a polygon's corners in order. Returns its area by the shoelace formula: positive if counter-clockwise.
inline double polygonArea(const std::vector<Eigen::Vector2d>& p) {
  double twice = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) twice += p[j].x() * p[i].y() - p[i].x() * p[j].y();
  return 0.5 * twice;
}

// Mean value coordinates (Floater 2003) of x in a polygon with holes: the weights, one per corner, that reproduce
// every linear function of the corners (sum 1; positive inside a convex polygon), smooth inside.
// [in] loops: each a closed polygon's corners in order (the outer loop one way round, the holes the other); [in] x:
// inside, not on a corner. Returns the weights, loop after loop, in the loops' order.
inline std::vector<double> meanValueWeights(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                            const Eigen::Vector2d& x) {
  std::vector<double> w;
  double sum = 0;
  for (const std::vector<Eigen::Vector2d>& loop : loops) {
    const std::size_t n = loop.size();
    std::vector<double> halfTan(n);  // tan(alpha_i / 2) of the signed angle at x from corner i to i + 1 (Eq. 2.1)
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d a = loop[i] - x, b = loop[(i + 1) % n] - x;
      halfTan[i] = std::tan(0.5 * std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
    }
    for (std::size_t i = 0; i < n; ++i) {
      w.push_back((halfTan[(i + n - 1) % n] + halfTan[i]) / (loop[i] - x).norm());
      sum += w.back();
    }
  }
  for (double& wi : w) wi /= sum;
  return w;
}

// Even-odd rule: whether q is inside the polygon p (its corners in order).
inline bool insidePolygon(const std::vector<Eigen::Vector2d>& p, const Eigen::Vector2d& q) {
  bool inside = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i].y() > q.y()) != (p[j].y() > q.y()) &&
        q.x() < p[j].x() + (p[i].x() - p[j].x()) * (q.y() - p[j].y()) / (p[i].y() - p[j].y()))
      inside = !inside;
  return inside;
}

// Loops in the plane sorted into regions: a counter-clockwise loop is a region's outer loop, a clockwise one a hole of
// the smallest outer loop round its first corner, but one through that corner (a loop that is one region's outer loop
// and, reversed, a hole of the region round it). [in] loops: disjoint, each its corners in order. Returns per region
// its outer loop's index, then its holes', the regions in their outer loops' order and the holes in theirs; nullopt if
// a hole lies in no outer loop.
inline std::optional<std::vector<std::vector<std::size_t>>> loopRegions(
    const std::vector<std::vector<Eigen::Vector2d>>& loops) {
  std::vector<double> area;
  for (const auto& loop : loops) area.push_back(polygonArea(loop));
  std::vector<std::vector<std::size_t>> regions;
  std::vector<std::size_t> regionOf(loops.size());
  for (std::size_t k = 0; k < loops.size(); ++k)
    if (area[k] > 0) regionOf[k] = regions.size(), regions.push_back({k});
  for (std::size_t h = 0; h < loops.size(); ++h) {
    if (area[h] > 0) continue;
    int outer = -1;
    const Eigen::Vector2d& p = loops[h].front();
    for (std::size_t s = 0; s < loops.size(); ++s)
      if (area[s] > 0 && std::find(loops[s].begin(), loops[s].end(), p) == loops[s].end() &&
          insidePolygon(loops[s], p) && (outer < 0 || area[s] < area[outer]))
        outer = static_cast<int>(s);
    if (outer < 0) return std::nullopt;
    regions[regionOf[outer]].push_back(h);
  }
  return regions;
}

}  // namespace hexlayer
