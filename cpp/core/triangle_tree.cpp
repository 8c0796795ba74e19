#include "core/triangle_tree.hpp"

#include <algorithm>
#include <cmath>

namespace hexlayer {

namespace {

constexpr double kEdgeHair = 1e-9;  // barycentric distance to an edge below which a crossing is unsure

// Squared distance from p to the segment ab.
double squaredDistanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  return (a + nearestOnSegment(a, b, p) * (b - a) - p).squaredNorm();
}

enum class Crossing { kNone, kOnce, kUnsure };

// Möller-Trumbore: whether the ray p + t dir (t > 0) crosses the triangle, unsure near its edges
// or nearly in its plane.
Crossing crossTriangle(const Vec3& p, const Vec3& dir, const Triangle& t) {
  const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0], pv = dir.cross(e2);
  const double det = e1.dot(pv);
  if (std::abs(det) <= kEdgeHair * e1.cross(e2).norm()) return Crossing::kUnsure;
  const Vec3 s = p - t[0], q = s.cross(e1);
  const double u = s.dot(pv) / det, v = dir.dot(q) / det, along = e2.dot(q) / det;
  if (along <= 0 || u < -kEdgeHair || v < -kEdgeHair || u + v > 1 + kEdgeHair) return Crossing::kNone;
  if (u < kEdgeHair || v < kEdgeHair || u + v > 1 - kEdgeHair) return Crossing::kUnsure;
  return Crossing::kOnce;
}

std::vector<Box> boxesOf(const std::vector<Triangle>& triangles) {
  std::vector<Box> boxes(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (const Vec3& v : triangles[i]) boxes[i].add(v);
  return boxes;
}

}  // namespace

double squaredDistanceToTriangle(const Vec3& p, const Triangle& t) {
  // Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi region of p decides the closest point.
  const Vec3 &a = t[0], &b = t[1], &c = t[2];
  const Vec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap), d3 = ab.dot(bp), d4 = ac.dot(bp), d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
  if (!(va > 0 && vb > 0 && vc > 0))  // closest point on an edge (or a degenerate triangle)
    return std::min(
        {squaredDistanceToSegment(p, a, b), squaredDistanceToSegment(p, b, c), squaredDistanceToSegment(p, c, a)});
  const double sum = va + vb + vc;
  return (a + ab * (vb / sum) + ac * (vc / sum) - p).squaredNorm();
}

TriangleTree::TriangleTree(std::vector<Triangle> triangles)
    : triangles_(std::move(triangles)), tree_(boxesOf(triangles_)) {}

bool TriangleTree::anyWithin(const Vec3& p, double radius) const {
  const double r2 = radius * radius;
  bool found = false;
  tree_.traverse([&](const Box& b) { return squaredDistanceToBox(p, b) <= r2; },
                 [&](int t) { return found = squaredDistanceToTriangle(p, triangles_[t]) <= r2; });
  return found;
}

std::optional<int> TriangleTree::crossings(const Vec3& p, const Vec3& dir) const {
  int count = 0;
  bool unsure = false;
  tree_.traverse([&](const Box& b) { return rayEntersBox(p, dir, b, 0, INFINITY) < INFINITY; },
                 [&](int t) {
                   const Crossing c = crossTriangle(p, dir, triangles_[t]);
                   count += c == Crossing::kOnce;
                   return unsure = c == Crossing::kUnsure;
                 });
  if (unsure) return std::nullopt;
  return count;
}

}  // namespace hexlayer
