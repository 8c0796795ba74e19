// A uniform hash grid over points: near-neighbour queries in O(1) per point instead of all pairs.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

class PointGrid {
 public:
  explicit PointGrid(double cellSize) : h_(cellSize > 0 ? cellSize : 1.0), slots_(kFirstSlots) {}

  void insert(int id, const Vec3& p) {
    const Eigen::Vector3i c = cellOf(p);
    cellAt(key(c)).push_back({id, p});
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
          const int cell = find(key({i, j, k}));
          if (cell < 0) continue;
          for (const Entry& e : cells_[cell])
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

  // The occupied cells by key in an open-addressing table: slots_ (a power of two, at most half full) hold indices
  // into cells_, probed one after the other from the key's multiplicative hash. Most queries ask for empty cells:
  // one multiplication and a probe or two each.
  struct Slot {
    std::int64_t key = 0;
    int cell = -1;  // -1: empty
  };
  static constexpr std::size_t kFirstSlots = 64;  // 2^(64 - kFirstShift)
  static constexpr int kFirstShift = 58;
  std::size_t slotOf(std::int64_t k) const {  // the product's top bits: every bit of the key moves them
    return static_cast<std::size_t>((static_cast<std::uint64_t>(k) * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  int find(std::int64_t k) const {
    for (std::size_t s = slotOf(k);; s = (s + 1) & (slots_.size() - 1)) {
      if (slots_[s].cell < 0) return -1;
      if (slots_[s].key == k) return slots_[s].cell;
    }
  }
  void place(std::int64_t k, int cell) {
    std::size_t s = slotOf(k);
    while (slots_[s].cell >= 0) s = (s + 1) & (slots_.size() - 1);
    slots_[s] = {k, cell};
  }
  std::vector<Entry>& cellAt(std::int64_t k) {
    if (const int cell = find(k); cell >= 0) return cells_[cell];
    if (2 * (keys_.size() + 1) > slots_.size()) {
      slots_.assign(2 * slots_.size(), Slot{});
      --shift_;
      for (std::size_t c = 0; c < keys_.size(); ++c) place(keys_[c], static_cast<int>(c));
    }
    place(k, static_cast<int>(cells_.size()));
    keys_.push_back(k);
    cells_.emplace_back();
    return cells_.back();
  }

  double h_;
  std::vector<Slot> slots_;
  int shift_ = kFirstShift;                // 64 - log2(slots)
  std::vector<std::int64_t> keys_;         // per occupied cell, its key
  std::vector<std::vector<Entry>> cells_;  // per occupied cell, its points in the order of insertion
  Eigen::Vector3i lo_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::max());  // box of the occupied cells
  Eigen::Vector3i hi_ = Eigen::Vector3i::Constant(std::numeric_limits<int>::min());
};

}  // namespace hexlayer
