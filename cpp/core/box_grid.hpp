// A uniform hash grid over boxes: each item is stored in every cell its bounding box overlaps, so a
// nearest-item query scans rings of cells around the point and stops as soon as no farther cell
// can hold anything closer. Cost per query stays O(1) whatever the spread of item sizes.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

class BoxGrid {
 public:
  explicit BoxGrid(double cellSize) : h_(cellSize > 0 ? cellSize : 1.0) {}

  void insert(int id, const Vec3& lo, const Vec3& hi) {
    const Eigen::Vector3i a = cellOf(lo), b = cellOf(hi);
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int k = a.z(); k <= b.z(); ++k) cells_[key({i, j, k})].push_back(id);
    lo_ = lo_.cwiseMin(a), hi_ = hi_.cwiseMax(b);
  }

  // Calls distance(id, bestD2) -> squared distance of item id to p, for items in growing rings of
  // cells around p, until the nearest item found is closer than any unvisited cell. bestD2 is the
  // nearest squared distance so far: an item that cannot be closer may return anything above it
  // (a bounding-box test instead of the exact distance). Returns the nearest id (-1 if the grid is
  // empty), the lowest id on a tie. An item spanning several cells may be offered more than once.
  // start: an item to begin with (-1: none): the same answer, found sooner if it is near p.
  template <class Distance>
  int nearest(const Vec3& p, Distance&& distance, int start = -1) const {
    if (!p.allFinite() || cells_.empty()) return -1;  // empty: lo_ > hi_, the rings would run to INT_MAX
    const Eigen::Vector3i c = cellOf(p);
    // Rings closer than the grid's box are empty, rings beyond it too: scan only those between.
    const int firstRing = std::max({0, (lo_ - c).maxCoeff(), (c - hi_).maxCoeff()});
    const int lastRing = std::max((hi_ - c).cwiseMax(c - lo_).maxCoeff(), firstRing);
    int best = start;
    double bestD2 =
        start >= 0 ? distance(start, std::numeric_limits<double>::infinity()) : std::numeric_limits<double>::infinity();
    // A cell of ring r+1 lies r+1 cells off along some axis: at least r*h plus p's clearance in its own cell away.
    const Vec3 inCell = p - h_ * c.cast<double>();
    const double clearance = std::max(0.0, std::min(inCell.minCoeff(), h_ - inCell.maxCoeff()));
    for (int r = firstRing; r <= lastRing; ++r) {
      forRing(c, r, [&](const Eigen::Vector3i& cell) {
        const auto it = cells_.find(key(cell));
        if (it == cells_.end()) return;
        for (int id : it->second)
          if (const double d2 = distance(id, bestD2); d2 < bestD2 || (d2 == bestD2 && id < best))
            best = id, bestD2 = d2;
      });
      const double beyond = r * h_ + clearance;  // to the nearest cell of ring r+1
      if (best >= 0 && bestD2 <= beyond * beyond) break;
    }
    return best;
  }

 private:
  // The cells at Chebyshev distance r from c that lie in the grid's box: O(r^2) per ring.
  template <class F>
  void forRing(const Eigen::Vector3i& c, int r, F&& f) const {
    const Eigen::Vector3i a = (c - Eigen::Vector3i::Constant(r)).cwiseMax(lo_);
    const Eigen::Vector3i b = (c + Eigen::Vector3i::Constant(r)).cwiseMin(hi_);
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j) {
        if (std::abs(i - c.x()) == r || std::abs(j - c.y()) == r) {  // a side of the cube: its whole column
          for (int k = a.z(); k <= b.z(); ++k) f(Eigen::Vector3i(i, j, k));
          continue;
        }
        if (c.z() - r >= a.z()) f(Eigen::Vector3i(i, j, c.z() - r));  // inside: only the lid and the floor
        if (c.z() + r <= b.z()) f(Eigen::Vector3i(i, j, c.z() + r));
      }
  }

  Eigen::Vector3i cellOf(const Vec3& p) const {  // clamped, so far or non-finite points stay defined
    auto cell = [&](double x) { return static_cast<int>(std::clamp(std::floor(x / h_), -1e9, 1e9)); };
    return {cell(p.x()), cell(p.y()), cell(p.z())};
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    return (static_cast<std::int64_t>(c.x() & 0x1FFFFF) << 42) | (static_cast<std::int64_t>(c.y() & 0x1FFFFF) << 21) |
           static_cast<std::int64_t>(c.z() & 0x1FFFFF);
  }
  double h_;
  Eigen::Vector3i lo_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::max());
  Eigen::Vector3i hi_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::min());
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace hexlayer
