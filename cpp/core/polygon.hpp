// Polygons in the plane.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace hexlayer {

// [in] p: a polygon's corners in order. Returns its area by the shoelace formula: positive if counter-clockwise.
inline double polygonArea(const std::vector<Eigen::Vector2d>& p) {
  double twice = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) twice += p[j].x() * p[i].y() - p[i].x() * p[j].y();
  return 0.5 * twice;
}

}  // namespace hexlayer
