// A uniform hash grid over points: near-neighbour queries in O(1) per point instead of all pairs.
#pragma once
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

class PointGrid {
 public:
  explicit PointGrid(double cellSize) : h_(cellSize > 0 ? cellSize : 1.0) {}

  void insert(int id, const Vec3& p) { cells_[key(cellOf(p))].push_back({id, p}); }

  // Calls f(id, point) for every stored point within `radius` of p, in a deterministic order.
  template <class F>
  void forEachNear(const Vec3& p, double radius, F&& f) const {
    const Eigen::Vector3i lo = cellOf(p - Vec3::Constant(radius)), hi = cellOf(p + Vec3::Constant(radius));
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) {
          const auto it = cells_.find(key({i, j, k}));
          if (it == cells_.end()) continue;
          for (const Entry& e : it->second)
            if ((e.p - p).squaredNorm() <= radius * radius) f(e.id, e.p);
        }
  }

 private:
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
};

}  // namespace hexlayer
