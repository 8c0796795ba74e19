#include "core/triangle_tree.hpp"

#include <algorithm>
#include <cmath>

namespace hexlayer {

namespace {

constexpr int kLeafSize = 4;
constexpr double kEdgeHair = 1e-9;  // barycentric distance to an edge below which a crossing is unsure

// Squared distance from p to the segment ab.
double squaredDistanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  return (a + nearestOnSegment(a, b, p) * (b - a) - p).squaredNorm();
}

// Squared distance from p to the box [lo, hi] (0 inside).
double squaredDistanceToBox(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
}

// Whether the ray p + t dir (t >= 0) meets the box [lo, hi]; inv is 1 / dir per component.
bool rayMeetsBox(const Vec3& p, const Vec3& inv, const Vec3& lo, const Vec3& hi) {
  const Vec3 a = (lo - p).cwiseProduct(inv), b = (hi - p).cwiseProduct(inv);
  const double enter = std::max(a.cwiseMin(b).maxCoeff(), 0.0), leave = a.cwiseMax(b).minCoeff();
  return enter <= leave;
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

TriangleTree::TriangleTree(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
  order_.resize(triangles_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
  if (!triangles_.empty()) build(0, static_cast<int>(triangles_.size()));
}

// Builds the subtree of order_[first, first + count), split at the median centre along the longest
// side of the centres' box; returns its node's index.
int TriangleTree::build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY), clo = lo, chi = hi;
  for (int i = first; i < first + count; ++i) {
    const Triangle& t = triangles_[order_[i]];
    for (const Vec3& v : t) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const Vec3 centre = (t[0] + t[1] + t[2]) / 3;
    clo = clo.cwiseMin(centre), chi = chi.cwiseMax(centre);
  }
  const Vec3 pad = Vec3::Constant(1e-9 * (hi - lo).norm() + 1e-300);  // rounding of the ray-box test
  nodes_[index].lo = lo - pad, nodes_[index].hi = hi + pad;
  if (count <= kLeafSize) {
    nodes_[index].first = first, nodes_[index].count = count;
    return index;
  }
  int axis;
  (chi - clo).maxCoeff(&axis);
  const auto centre = [&](int t) { return triangles_[t][0][axis] + triangles_[t][1][axis] + triangles_[t][2][axis]; };
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int a, int b) { return centre(a) < centre(b); });
  build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].right = right;
  return index;
}

// Depth-first walk: enter(node) says whether to look inside a node, visit(triangle) whether to stop.
template <class Visit, class Enter>
void TriangleTree::traverse(Enter&& enter, Visit&& visit) const {
  if (nodes_.empty()) return;
  std::array<int, 128> stack;  // a median split keeps the depth near log2(triangles)
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const int index = stack[--size];
    const Node& node = nodes_[index];
    if (!enter(node)) continue;
    if (node.count == 0) {
      stack[size++] = node.right, stack[size++] = index + 1;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i)
      if (visit(triangles_[order_[i]])) return;
  }
}

bool TriangleTree::anyWithin(const Vec3& p, double radius) const {
  const double r2 = radius * radius;
  bool found = false;
  traverse([&](const Node& n) { return squaredDistanceToBox(p, n.lo, n.hi) <= r2; },
           [&](const Triangle& t) { return found = squaredDistanceToTriangle(p, t) <= r2; });
  return found;
}

std::optional<int> TriangleTree::crossings(const Vec3& p, const Vec3& dir) const {
  const Vec3 inv = dir.cwiseInverse();
  int count = 0;
  bool unsure = false;
  traverse([&](const Node& n) { return rayMeetsBox(p, inv, n.lo, n.hi); },
           [&](const Triangle& t) {
             const Crossing c = crossTriangle(p, dir, t);
             count += c == Crossing::kOnce;
             return unsure = c == Crossing::kUnsure;
           });
  if (unsure) return std::nullopt;
  return count;
}

}  // namespace hexlayer
