// A uniform hash grid over points: near-neighbour queries in O(1) per point instead of all pairs.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

class PointGrid {
 public:
  explicit PointGrid(double cellSize) : h_(cellSize > 0 ? cellSize : 1.0) {}

  void insert(int id, const Vec3& p) {
    const Eigen::Vector3i c = cellOf(p);
    cells_[key(c)].push_back({id, p});
    lo_ = lo_.cwiseMin(c), hi_ = hi_.cwiseMax(c);
  }

  // Calls f(id, point) for every stored point within `radius` of p, in a deterministic order: cell
  // by cell (x, then y, then z), in each cell in the order of insertion.
  template <class F>
  void forEachNear(const Vec3& p, double radius, F&& f) const {
    visitNear(p, radius, [&](int id, const Vec3& q) { return f(id, q), false; });
  }

  // Whether pred(id, point) holds for a stored point within `radius` of p; stops at the first.
  template <class Pred>
  bool anyNear(const Vec3& p, double radius, Pred&& pred) const {
    return visitNear(p, radius, pred);
  }

 private:
  // Calls f(id, point) on the stored points within `radius` of p in forEachNear's order until f
  // returns true; returns whether it did.
  template <class F>
  bool visitNear(const Vec3& p, double radius, F&& f) const {
    // Cells outside the box of the occupied ones are empty: a thin sheet's query skips most.
    const Eigen::Vector3i lo = cellOf(p - Vec3::Constant(radius)).cwiseMax(lo_);
    const Eigen::Vector3i hi = cellOf(p + Vec3::Constant(radius)).cwiseMin(hi_);
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) {
          const auto it = cells_.find(key({i, j, k}));
          if (it == cells_.end()) continue;
          for (const Entry& e : it->second)
            if ((e.p - p).squaredNorm() <= radius * radius && f(e.id, e.p)) return true;
        }
    return false;
  }

  struct Entry {
    int id;
    Vec3 p;
  };
  Eigen::Vector3i cellOf(const Vec3& p) const {
    return {static_cast<int>(std::floor(p.x() / h_)), static_cast<int>(std::floor(p.y() / h_)),
            static_cast<int>(std::floor(p.z() / h_))};
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    return (static_cast<std::int64_t>(c.x() & 0x1FFFFF) << 42) | (static_cast<std::int64_t>(c.y() & 0x1FFFFF) << 21) |
           static_cast<std::int64_t>(c.z() & 0x1FFFFF);
  }
  double h_;
  std::unordered_map<std::int64_t, std::vector<Entry>> cells_;
  Eigen::Vector3i lo_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::max());  // box of the occupied cells
  Eigen::Vector3i hi_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::min());
};

}  // namespace hexlayer
