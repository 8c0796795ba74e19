// A bounding volume hierarchy over triangles: whether any triangle is near a point, and how often a
// ray crosses them, without testing every triangle.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "core/box_tree.hpp"
#include "core/types.hpp"

namespace hexlayer {

using Triangle = std::array<Vec3, 3>;

class TriangleTree {
 public:
  explicit TriangleTree(std::vector<Triangle> triangles);

  // Whether some triangle comes within `radius` of p.
  bool anyWithin(const Vec3& p, double radius) const;

  // How many triangles the ray p + t dir (t > 0) crosses; none (std::nullopt) when it passes within a
  // hair of a triangle's edge or runs nearly in its plane, where a crossing could count once, twice
  // or not at all. dir must have no zero component.
  std::optional<int> crossings(const Vec3& p, const Vec3& dir) const;

 private:
  std::vector<Triangle> triangles_;
  BoxTree tree_;  // over the triangles' boxes
};

// Squared distance from p to the triangle (its closest point, edges and corners included).
double squaredDistanceToTriangle(const Vec3& p, const Triangle& t);

}  // namespace hexlayer
