#include "chordal/chordal_locator.hpp"

#include <algorithm>
#include <limits>

namespace hexlayer {

Eigen::Vector3d triangleWeights(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  // The projection of p onto the triangle's plane, p ≈ a + s (b - a) + t (c - a), if it is inside.
  Eigen::Matrix<double, 3, 2> E;
  E << b - a, c - a;
  const Eigen::Vector2d st = (E.transpose() * E).ldlt().solve(E.transpose() * (p - a));
  if (st.allFinite() && st.minCoeff() >= 0 && st.sum() <= 1) return {1 - st.sum(), st.x(), st.y()};
  // Otherwise the nearest point lies on an edge: the nearest of the three edges' nearest points.
  const std::array<Vec3, 3> corner{a, b, c};
  Eigen::Vector3d best(1, 0, 0);
  double bestD2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Vec3 &x = corner[k], &y = corner[(k + 1) % 3];
    const double u = nearestOnSegment(x, y, p);
    if (const double d2 = (x + u * (y - x) - p).squaredNorm(); d2 < bestD2) {
      bestD2 = d2;
      best.setZero();
      best[k] = 1 - u, best[(k + 1) % 3] = u;  // Eq. 4-5 on that edge
    }
  }
  return best;  // (w_a, w_b, w_c) = (A_a, A_b, A_c) / A of the nearest point
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
    const Eigen::Vector2d next = (uv + step).cwiseMax(0.0).cwiseMin(1.0);
    if (next == uv) break;  // held where it was by the clamp (p beyond the facet's side): every later step the same
    uv = next;
    if (step.squaredNorm() < 1e-24) break;
  }
  return uv;
}

ChordalLocator::ChordalLocator(const ChordalSurface& chordal)
    : chordal_(chordal), facets_(1.0), lo_(chordal.facets.size()), hi_(chordal.facets.size()) {
  std::vector<double> extent(chordal.facets.size());
  for (size_t f = 0; f < chordal.facets.size(); ++f) {
    const auto& fc = chordal.facets[f];
    lo_[f] = hi_[f] = chordal.vertices[fc[0]];
    for (int k = 1; k < (fc[3] < 0 ? 3 : 4); ++k)
      lo_[f] = lo_[f].cwiseMin(chordal.vertices[fc[k]]), hi_[f] = hi_[f].cwiseMax(chordal.vertices[fc[k]]);
    extent[f] = (hi_[f] - lo_[f]).maxCoeff();
  }
  // Cells as large as a typical facet: a few facets per cell, a long sliver in a few more cells.
  facets_ = BoxGrid(extent.empty() ? 1.0 : std::max(median(extent), 1e-12));
  for (size_t f = 0; f < chordal.facets.size(); ++f) facets_.insert(static_cast<int>(f), lo_[f], hi_[f]);
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

ChordalPoint ChordalLocator::locate(const Vec3& p) const { return locate(p, -1); }

ChordalPoint ChordalLocator::locate(const Vec3& p, int hint) const {
  const int f = facets_.nearest(
      p,
      [&](int id, double bestD2) {
        // The facet's bounding box is farther than the nearest facet so far: it cannot be nearer.
        if ((p - p.cwiseMax(lo_[id]).cwiseMin(hi_[id])).squaredNorm() > bestD2) return bestD2 * 2 + 1;
        return (project(id, p).point - p).squaredNorm();
      },
      hint >= 0 && hint < static_cast<int>(lo_.size()) ? hint : -1);
  return f < 0 ? ChordalPoint{} : project(f, p);
}

Vec3 normalAt(const ChordalSurface& chordal, const ChordalPoint& at) {
  const auto& f = chordal.facets[at.facet];
  Vec3 n = Vec3::Zero();
  for (int k = 0; k < (f[3] < 0 ? 3 : 4); ++k) n += at.weights[k] * chordal.normals[f[k]];  // Eq. 7 (Eq. 4 on an edge)
  return n;
}

}  // namespace hexlayer
