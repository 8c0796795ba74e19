#include "chordal/chordal_locator.hpp"

#include <algorithm>
#include <limits>

namespace hexlayer {

Eigen::Vector3d triangleWeights(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  // Solve p ≈ a + s (b - a) + t (c - a) in the least-squares sense, then clamp into the triangle.
  Eigen::Matrix<double, 3, 2> E;
  E << b - a, c - a;
  Eigen::Vector2d st = (E.transpose() * E).ldlt().solve(E.transpose() * (p - a));
  if (!st.allFinite()) st.setZero();
  st = st.cwiseMax(0.0);
  if (st.sum() > 1) st /= st.sum();
  return {1 - st.sum(), st.x(), st.y()};  // (w_a, w_b, w_c) = (A_a, A_b, A_c) / A
}

Eigen::Vector2d inverseBilinear(const std::array<Vec3, 4>& p, const Vec3& x) {
  Eigen::Vector2d uv(0.5, 0.5);
  for (int it = 0; it < 20; ++it) {
    const double u = uv.x(), v = uv.y();
    const Vec3 P = (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
    Eigen::Matrix<double, 3, 2> J;
    J << (1 - v) * (p[1] - p[0]) + v * (p[2] - p[3]), (1 - u) * (p[3] - p[0]) + u * (p[2] - p[1]);
    const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(J.transpose() * (x - P));
    if (!step.allFinite()) break;
    uv = (uv + step).cwiseMax(0.0).cwiseMin(1.0);
    if (step.squaredNorm() < 1e-24) break;
  }
  return uv;
}

ChordalLocator::ChordalLocator(const ChordalSurface& chordal) : chordal_(chordal), centroids_(1.0) {
  std::vector<Vec3> centre(chordal.facets.size());
  for (size_t f = 0; f < chordal.facets.size(); ++f) {
    const auto& fc = chordal.facets[f];
    const int n = fc[3] < 0 ? 3 : 4;
    centre[f].setZero();
    for (int k = 0; k < n; ++k) centre[f] += chordal.vertices[fc[k]] / n;
    for (int k = 0; k < n; ++k) reach_ = std::max(reach_, (chordal.vertices[fc[k]] - centre[f]).norm());
  }
  centroids_ = PointGrid(std::max(reach_, 1e-12));
  for (size_t f = 0; f < centre.size(); ++f) centroids_.insert(static_cast<int>(f), centre[f]);
}

ChordalPoint ChordalLocator::project(int facet, const Vec3& p) const {
  const auto& f = chordal_.facets[facet];
  const auto& v = chordal_.vertices;
  ChordalPoint hit;
  hit.facet = facet;
  if (f[3] < 0) {
    const Eigen::Vector3d w = triangleWeights(v[f[0]], v[f[1]], v[f[2]], p);
    hit.weights = {w[0], w[1], w[2], 0};
  } else {
    const Eigen::Vector2d uv = inverseBilinear({v[f[0]], v[f[1]], v[f[2]], v[f[3]]}, p);
    const double u = uv.x(), w = uv.y();
    hit.weights = {(1 - u) * (1 - w), u * (1 - w), u * w, (1 - u) * w};
  }
  for (int k = 0; k < (f[3] < 0 ? 3 : 4); ++k) hit.point += hit.weights[k] * v[f[k]];
  return hit;
}

ChordalPoint ChordalLocator::locate(const Vec3& p) const {
  ChordalPoint best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (double radius = 1.01 * reach_; best.facet < 0; radius *= 2)
    centroids_.forEachNear(p, radius, [&](int f, const Vec3&) {
      const ChordalPoint hit = project(f, p);
      const double d = (hit.point - p).squaredNorm();
      if (d < bestDistance) best = hit, bestDistance = d;
    });
  return best;
}

}  // namespace hexlayer
