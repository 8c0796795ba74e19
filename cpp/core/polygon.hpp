// Polygons in the plane.
#pragma once
#include <Eigen/Core>
#include <cmath>
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

}  // namespace hexlayer
