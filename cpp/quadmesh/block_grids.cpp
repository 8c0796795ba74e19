#include "quadmesh/block_grids.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/polygon.hpp"
#include "core/threads.hpp"
#include "quadmesh/quad_smoothing.hpp"

namespace hexlayer {
namespace {

constexpr double kCore = 0.4;  // half-side of the O-grid's core in the unit disc (keeps a shelled box's floor in it)
constexpr int kRadialSamples = 8;  // samples per quad along a line, to measure it

// A box of grid cells: columns i0 .. i0 + n0, rows k0 .. k0 + n1 of lines x (u, falling with i) and
// y (v, falling with k). Its boundary is walked counter-clockwise in the plane from (i0, k0), the
// (+u, +v) corner: n0 steps along side 0, n1 along side 1, n0 along 2, n1 along 3.
struct Box {
  int i0 = 0, k0 = 0, n0 = 1, n1 = 1;
  int around() const { return 2 * (n0 + n1); }
  std::array<int, 2> walk(int t) const {
    t %= around();
    if (t < n0) return {i0 + t, k0};
    if (t < n0 + n1) return {i0 + n0, k0 + t - n0};
    if (t < 2 * n0 + n1) return {i0 + 2 * n0 + n1 - t, k0 + n1};
    return {i0, k0 + around() - t};
  }
  std::array<int, 4> sides() const { return {n0, n1, n0, n1}; }
};

// A tensor grid in the plane: node (i, k) at (x[i], y[k]).
struct GridLines {
  std::vector<double> x, y;
  int node(int i, int k) const { return i * static_cast<int>(y.size()) + k; }
  Eigen::Vector2d uv(int i, int k) const { return {x[i], y[k]}; }
};

// Quads the target size needs along a line, accumulated from its start.
std::vector<double> quadsAlong(const std::vector<Vec3>& line, const SizeField& size) {
  std::vector<double> quads{0};
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    quads.push_back(quads.back() + (line[i + 1] - line[i]).norm() / size(0.5 * (line[i] + line[i + 1])));
  return quads;
}

std::vector<double> quadsAlongLoop(const SurfaceMap& map, const std::vector<int>& loop, const SizeField& size) {
  std::vector<Vec3> x;
  for (int p : loop) x.push_back(map.points[p]);
  x.push_back(x.front());
  return quadsAlong(x, size);
}

// A straight line of the plane from `from` to `to`, measured in quads the target size needs.
struct PlaneLine {
  Eigen::Vector2d from, to;
  std::vector<double> quads;  // at evenly spaced samples
};

PlaneLine planeLine(const MapLocator& locate, const Eigen::Vector2d& from, const LoopPoint& to, const SizeField& size) {
  const Vec3 start = locate(from);
  const int samples = kRadialSamples * std::max(8, static_cast<int>(std::ceil((start - to.x).norm() / size(to.x))));
  std::vector<Vec3> x{start};
  for (int s = 1; s < samples; ++s) x.push_back(locate(from + (to.uv - from) * s / samples));
  x.push_back(to.x);
  return {from, to.uv, quadsAlong(x, size)};
}

// Where (a fractional sample index) a measure accumulated at evenly spaced samples reaches j / m of its total.
double sharePlace(const std::vector<double>& measure, int j, int m) {
  const double target = measure.back() * j / m;
  const int last = static_cast<int>(measure.size()) - 1;
  const int s =
      std::clamp(static_cast<int>(std::lower_bound(measure.begin(), measure.end(), target) - measure.begin()), 1, last);
  const double g = (target - measure[s - 1]) / std::max(measure[s] - measure[s - 1], 1e-300);
  return s - 1 + g;
}

// The point of the line after j of its m quads, all needing the same share of it.
Eigen::Vector2d linePoint(const PlaneLine& line, int j, int m) {
  if (j >= m) return line.to;
  return line.from + (line.to - line.from) * sharePlace(line.quads, j, m) / (line.quads.size() - 1);
}

// Points of a loop (counter-clockwise, from its corner 0) for a box's boundary walk: sides[k] points
// from corner k towards corner k + 1, spaced by the quads the target size needs along the loop.
std::vector<LoopPoint> loopPoints(const SurfaceMap& map, const std::vector<int>& loop,
                                  const std::array<int, 4>& corners, const std::array<int, 4>& sides,
                                  const SizeField& size) {
  const std::vector<double> quads = quadsAlongLoop(map, loop, size);
  std::vector<LoopPoint> points;
  for (int k = 0; k < 4; ++k) {
    const double from = quads[corners[k]], to = k == 3 ? quads.back() : quads[corners[k + 1]];
    for (int i = 0; i < sides[k]; ++i) points.push_back(loopPoint(map, loop, quads, from + (to - from) * i / sides[k]));
  }
  return points;
}

// The rows of a ring between a box's boundary walk and as many loop points the same way round, out to the outer rim
// or in to a hole: as many rows as the most any line between them needs, the nodes spaced along each line by the
// target size, row after row (positions t = 0 .. n - 1 of the walk), the last row on the loop.
struct Ring {
  int rows = 1;
  std::vector<Vec3> nodes;
};

Ring layRing(const MapLocator& locate, const GridLines& lines, const Box& box, const std::vector<LoopPoint>& loop,
             const SizeField& size) {
  const int n = box.around();
  std::vector<PlaneLine> across;
  Ring ring;
  for (int t = 0; t < n; ++t) {
    const auto [i, k] = box.walk(t);
    across.push_back(planeLine(locate, lines.uv(i, k), loop[t], size));
    ring.rows = std::max(ring.rows, static_cast<int>(std::round(across.back().quads.back())));
  }
  for (int j = 1; j <= ring.rows; ++j)
    for (int t = 0; t < n; ++t)
      ring.nodes.push_back(j == ring.rows ? loop[t].x : locate(linePoint(across[t], j, ring.rows)));
  return ring;
}

// The ring's nodes and quads added to the grid (its row 0 is the box's boundary walk on the grid's lines).
void appendRing(BlockGrid& grid, const GridLines& lines, const Box& box, const Ring& ring, bool outward) {
  const int n = box.around(), m = ring.rows;
  const int first = static_cast<int>(grid.nodes.size());  // row j >= 1, position t: first + (j - 1) n + t
  grid.nodes.insert(grid.nodes.end(), ring.nodes.begin(), ring.nodes.end());
  auto node = [&](int j, int t) {
    const auto [i, k] = box.walk(t);
    return j == 0 ? lines.node(i, k) : first + (j - 1) * n + t % n;
  };
  for (int j = 0; j < m; ++j)
    for (int t = 0; t < n; ++t)
      grid.quads.push_back(outward
                               ? std::array<int, 4>{node(j, t), node(j + 1, t), node(j + 1, t + 1), node(j, t + 1)}
                               : std::array<int, 4>{node(j, t), node(j, t + 1), node(j + 1, t + 1), node(j + 1, t)});
  grid.blocks += 4;
}

void addRing(BlockGrid& grid, const MapLocator& locate, const GridLines& lines, const Box& box,
             const std::vector<LoopPoint>& loop, bool outward, const SizeField& size) {
  appendRing(grid, lines, box, layRing(locate, lines, box, loop, size), outward);
}

// The grid's nodes at their points and its cells as quads, but for the cells in `skip`.
void addCells(BlockGrid& grid, const MapLocator& locate, const GridLines& lines, const std::vector<char>& skip) {
  const int n0 = static_cast<int>(lines.x.size()) - 1, n1 = static_cast<int>(lines.y.size()) - 1;
  const std::size_t first = grid.nodes.size();
  grid.nodes.resize(first + (n0 + 1) * (n1 + 1));
#pragma omp parallel for schedule(static)
  for (int i = 0; i <= n0; ++i)
    for (int k = 0; k <= n1; ++k) grid.nodes[first + lines.node(i, k)] = locate(lines.uv(i, k));
  for (int i = 0; i < n0; ++i)
    for (int k = 0; k < n1; ++k)
      if (!skip[i * n1 + k])
        grid.quads.push_back({lines.node(i, k), lines.node(i + 1, k), lines.node(i + 1, k + 1), lines.node(i, k + 1)});
}

// n + 1 grid lines along one axis of the plane: where a line from -to to `to` needs equal shares of quads.
std::vector<double> linesAlong(const MapLocator& locate, const Eigen::Vector2d& to, int n, int axis,
                               const SizeField& size) {
  const PlaneLine line = planeLine(locate, -to, {locate(to), to}, size);
  std::vector<double> at;
  for (int i = 0; i <= n; ++i) at.push_back(linePoint(line, i, n)[axis]);
  return at;
}

int count(double quads) { return std::max(1, static_cast<int>(std::round(quads))); }

constexpr int kMinAround = 8;  // quads round a ring grid, at the least

// The pocket of grid cells around a hole: its box of cells one cell beyond the hole's extent in the
// plane; false if that leaves the grid, unless `toRim`: then a box side that would is on the rim (the hole lies in
// the rim's row of cells: a bend relief at a face's corner, whose sides are fixed).
bool pocketBox(const SurfaceMap& map, const std::vector<int>& hole, const GridLines& lines, bool toRim, Box& box) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (int p : hole) lo = lo.cwiseMin(map.uv[p]), hi = hi.cwiseMax(map.uv[p]);
  const int n0 = static_cast<int>(lines.x.size()) - 1, n1 = static_cast<int>(lines.y.size()) - 1;
  int i0 = 0, i1 = n0, k0 = 0, k1 = n1;
  const double tolerance = 1e-9;                                       // a hole's side on a grid line is within it
  while (i0 + 1 <= n0 && lines.x[i0 + 1] >= hi.x() - tolerance) ++i0;  // x falls with i
  while (i1 - 1 >= 0 && lines.x[i1 - 1] <= lo.x() + tolerance) --i1;
  while (k0 + 1 <= n1 && lines.y[k0 + 1] >= hi.y() - tolerance) ++k0;
  while (k1 - 1 >= 0 && lines.y[k1 - 1] <= lo.y() + tolerance) --k1;
  box = {i0 - 1, k0 - 1, i1 - i0 + 2, k1 - k0 + 2};
  if (toRim) {
    const int from0 = std::max(box.i0, 0), from1 = std::max(box.k0, 0);
    box = {from0, from1, std::min(box.i0 + box.n0, n0) - from0, std::min(box.k0 + box.n1, n1) - from1};
  }
  return box.i0 >= 0 && box.k0 >= 0 && box.i0 + box.n0 <= n0 && box.k0 + box.n1 <= n1;
}

// The hole's loop from its point nearest the box's corner 0, and its four corners (towards the
// box's corners), ascending; false if they do not follow each other round the hole.
bool holeCorners(const SurfaceMap& map, std::vector<int>& hole, std::array<int, 4>& corners) {
  std::vector<Vec3> x;
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (int p : hole)
    x.emplace_back(map.uv[p].x(), map.uv[p].y(), 0), lo = lo.cwiseMin(x.back()), hi = hi.cwiseMax(x.back());
  corners = diagonalExtremes(x, 0.5 * (lo + hi), Vec3::UnitX(), Vec3::UnitY());
  std::rotate(hole.begin(), hole.begin() + corners[0], hole.end());
  const int n = static_cast<int>(hole.size()), start = corners[0];
  for (int& c : corners) c = (c - start + n) % n;
  return corners[0] < corners[1] && corners[1] < corners[2] && corners[2] < corners[3];
}

// ---------------------------------------------------------------------------------------------------------------
// The shared grid round many holes (issue 19): where pockets of neighbouring holes would meet or one would reach
// the rim, one tensor grid is laid over the whole square, its lines through every hole's sides: a rectilinear hole
// (its loop runs along the axes in the plane, corner to corner: a cutout, with its notches) is a block of grid
// cells left out, its loop on their lines, as a quad layout traced from the holes' corners would have it (the
// lines of the motorcycle graph run on to the rim here, so every node inside is regular); any other hole gets a
// pocket of four blocks as in holedGrid, its box shrunk to half the gap to the next hole or snapped to the rim.
// ---------------------------------------------------------------------------------------------------------------

constexpr double kPocketMargin = 1.0;  // a pocket's box reaches this many quads beyond its hole, where there is room
constexpr double kMinMargin = 0.25;    // a pocket's box snapped to a line is still this many quads beyond its hole
constexpr double kSnap = 0.5;          // a pocket's side this many quads from a line or the rim is moved onto it
constexpr double kMerge = 0.35;        // lines of two holes' sides this many quads apart are merged (their mean)
constexpr double kSame = 1e-6;         // sides' lines this many quads apart are one (collinear sides, rounding)
constexpr double kOffSide = 0.5;       // a rectilinear hole's points are this many quads off their side's line, at most
constexpr double kSharpCorner = 50 * M_PI / 180;  // a hole's loop turning more has a corner (as the rim's)
constexpr double kCrowded = 0.25;  // a pocket's spokes meet its hole this share of their even spacing apart, at least
constexpr double kOffArea = 0.05;  // and its area this share off its sides' polygon's (a round hole's: 57 % more)

// One axis of the square measured in quads: those the target size needs from -1 to u, averaged over the rim's two
// sides along the axis (holedGrid's lines are the rim nodes' places averaged the same way).
class AxisMeasure {
 public:
  // [in] locate: the map's locator; [in] axis: 0 for u, 1 for v; [in] size: the target size.
  AxisMeasure(const MapLocator& locate, int axis, const SizeField& size) {
    std::array<PlaneLine, 2> sides;
    for (int s = 0; s < 2; ++s) {
      Eigen::Vector2d from = Eigen::Vector2d::Constant(s == 0 ? -1.0 : 1.0), to = from;
      from[axis] = -1, to[axis] = 1;
      sides[s] = planeLine(locate, from, {locate(to), to}, size);
    }
    const int samples = static_cast<int>(std::max(sides[0].quads.size(), sides[1].quads.size())) - 1;
    for (int i = 0; i <= samples; ++i) {
      const double f = static_cast<double>(i) / samples;
      u_.push_back(-1 + 2 * f), q_.push_back(0.5 * (at(sides[0].quads, f) + at(sides[1].quads, f)));
    }
  }
  double quads(double u) const { return interpolate(u_, q_, u); }  // from -1 to u
  double place(double q) const { return interpolate(q_, u_, q); }  // the u where quads(u) = q
  double total() const { return q_.back(); }

 private:
  // The measure at a share f of a line's evenly spaced samples.
  static double at(const std::vector<double>& samples, double f) {
    const double s = f * (samples.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(s), samples.size() - 2);
    return samples[i] + (s - i) * (samples[i + 1] - samples[i]);
  }
  // y at x of the ascending table (xs, ys), linear between its entries, clamped to its ends.
  static double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    const std::size_t i =
        std::clamp<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin(), 1, xs.size() - 1);
    const double g = std::clamp((x - xs[i - 1]) / std::max(xs[i] - xs[i - 1], 1e-300), 0.0, 1.0);
    return ys[i - 1] + g * (ys[i] - ys[i - 1]);
  }
  std::vector<double> u_, q_;
};

// A grid line being laid out, along one axis: where it crosses it, in quads (AxisMeasure), and what put it there.
struct Station {
  double at = 0;
  enum Kind { Rim, Side, Pocket } kind = Rim;
  int hole = -1;                 // Pocket: whose (in the shared grid's holes)
  int outward = 0;               // Pocket: +1 on the side of the box above its hole, -1 below
  double hole0 = 0;              // Pocket: the hole's extent on that side
  std::array<double, 2> span{};  // Side: where the side runs along the other axis, in quads, ascending
};

// A hole of the shared grid, in quads of the two axis measures.
struct GridHole {
  std::vector<int> loop;             // map.holes[h]; a rectilinear one from its corner 0
  std::array<double, 2> lo{}, hi{};  // its extent
  // Rectilinear: its corners (positions in the loop, ascending), the axis each side (corner j to j + 1) keeps
  // constant and the station of its line; else empty.
  std::vector<int> corners, sideAxis, sideStation;
  std::array<double, 2> boxLo{}, boxHi{};               // the pocket's box (a rectilinear hole: its extent)
  std::array<int, 2> boxLoAt{-1, -1}, boxHiAt{-1, -1};  // the box's stations (pocket)
  bool rectilinear() const { return !corners.empty(); }
};

// A loop's sides along the axes: runs of its edges that go more along the same axis (in quads, so that a diagonal
// is a diagonal), each from its corner (the run's first point) to the next. [in] q: the loop in quads.
// [out] corners: ascending; [out] axes: per side, the axis it keeps (about) constant.
void axisRuns(const std::vector<Eigen::Vector2d>& q, std::vector<int>& corners, std::vector<int>& axes) {
  const int n = static_cast<int>(q.size());
  auto keeps = [&](int i) {
    const Eigen::Vector2d d = q[(i + 1) % n] - q[i];
    return std::abs(d.x()) >= std::abs(d.y()) ? 1 : 0;
  };
  for (int i = 0; i < n; ++i)
    if (keeps((i + n - 1) % n) != keeps(i)) corners.push_back(i), axes.push_back(keeps(i));
}

// Whether a hole runs along the axes, side after side, each across the last: its points within kOffSide of their
// side's line (the mean of its ends'), its area within kOffArea of the polygon of those lines. A hole's loop as the
// chordal surface has it can cut a notch's corner or overshoot it by a fraction of a quad: the sides' lines pass
// such points by, the grid's nodes on the side are moved onto the loop (snapSides). Then sets its loop from corner
// 0, its corners and sides' axes. [in] q: the loop in quads; [in,out] hole; [out] sides: per side, the station of
// its line (in quads), its span.
bool rectilinear(const std::vector<Eigen::Vector2d>& q, GridHole& hole, std::vector<Station>& sides) {
  std::vector<int> corners, axes;
  axisRuns(q, corners, axes);
  const int n = static_cast<int>(q.size()), m = static_cast<int>(corners.size());
  if (m < 4) return false;
  std::vector<double> at;
  for (int j = 0; j < m; ++j) {
    const int a = axes[j], from = corners[j], to = j + 1 < m ? corners[j + 1] : corners[0] + n;
    at.push_back(0.5 * (q[from][a] + q[to % n][a]));
    Station side{at[j], Station::Side};
    side.span = {q[from][1 - a], q[from][1 - a]};
    for (int i = from; i <= to; ++i) {
      if (std::abs(q[i % n][a] - at[j]) > kOffSide) return false;
      side.span = {std::min(side.span[0], q[i % n][1 - a]), std::max(side.span[1], q[i % n][1 - a])};
    }
    sides.push_back(side);
  }
  std::vector<Eigen::Vector2d> polygon;
  for (int j = 0; j < m; ++j) {
    Eigen::Vector2d c;
    c[axes[j]] = at[j], c[1 - axes[j]] = at[(j + m - 1) % m];
    polygon.push_back(c);
  }
  const double area = polygonArea(polygon);
  if (!(std::abs(polygonArea(q) - area) <= kOffArea * std::abs(area))) return false;
  std::rotate(hole.loop.begin(), hole.loop.begin() + corners[0], hole.loop.end());
  const int first = corners[0];
  for (int& c : corners) c -= first;
  hole.corners = corners, hole.sideAxis = axes;
  return true;
}

// The shared grid's holes with their extents, and the stations of the rectilinear ones' sides.
// [in] map, measure; [out] stations: per axis, those added. Returns the holes.
std::vector<GridHole> gridHoles(const SurfaceMap& map, const std::array<AxisMeasure, 2>& measure,
                                std::array<std::vector<Station>, 2>& stations) {
  std::vector<GridHole> holes;
  for (const std::vector<int>& loop : map.holes) {
    GridHole hole;
    hole.loop = loop;
    for (int a = 0; a < 2; ++a) {
      double lo = 1e300, hi = -1e300;
      for (int p : loop) lo = std::min(lo, map.uv[p][a]), hi = std::max(hi, map.uv[p][a]);
      hole.lo[a] = measure[a].quads(lo), hole.hi[a] = measure[a].quads(hi);
    }
    std::vector<Eigen::Vector2d> q;
    for (int p : loop) q.emplace_back(measure[0].quads(map.uv[p].x()), measure[1].quads(map.uv[p].y()));
    if (std::vector<Station> sides; rectilinear(q, hole, sides)) {
      for (std::size_t j = 0; j < sides.size(); ++j) {
        const int a = hole.sideAxis[j];
        hole.sideStation.push_back(static_cast<int>(stations[a].size()));
        stations[a].push_back(sides[j]);
      }
      hole.boxLo = hole.lo, hole.boxHi = hole.hi;
    } else {
      for (int a = 0; a < 2; ++a)
        hole.boxLo[a] = hole.lo[a] - kPocketMargin, hole.boxHi[a] = hole.hi[a] + kPocketMargin;
    }
    holes.push_back(std::move(hole));
  }
  return holes;
}

// Pockets that would meet another hole's box shrunk to half the gap between the two holes, along the axis where
// the gap is widest. [in,out] holes. Returns false if two holes' extents overlap along both axes.
bool separatePockets(std::vector<GridHole>& holes) {
  for (std::size_t i = 0; i < holes.size(); ++i)
    for (std::size_t j = i + 1; j < holes.size(); ++j) {
      GridHole &a = holes[i], &b = holes[j];
      auto overlap = [&](int x) { return a.boxLo[x] < b.boxHi[x] && b.boxLo[x] < a.boxHi[x]; };
      if (!overlap(0) || !overlap(1)) continue;
      auto gap = [&](int x) { return std::max(b.lo[x] - a.hi[x], a.lo[x] - b.hi[x]); };
      const int x = gap(0) >= gap(1) ? 0 : 1;
      if (!(gap(x) > 0)) return false;
      GridHole &below = a.hi[x] <= b.lo[x] ? a : b, &above = &below == &a ? b : a;
      const double middle = 0.5 * (below.hi[x] + above.lo[x]);
      below.boxHi[x] = std::min(below.boxHi[x], middle), above.boxLo[x] = std::max(above.boxLo[x], middle);
    }
  return true;
}

// The stations of the rim and of the pockets' boxes, a box kept inside the square. [in,out] holes, stations;
// [in] total: per axis, the quads across the square.
void addPocketStations(std::vector<GridHole>& holes, std::array<std::vector<Station>, 2>& stations,
                       const std::array<double, 2>& total) {
  for (int a = 0; a < 2; ++a) stations[a].push_back({0, Station::Rim}), stations[a].push_back({total[a], Station::Rim});
  for (std::size_t h = 0; h < holes.size(); ++h) {
    GridHole& hole = holes[h];
    if (hole.rectilinear()) continue;
    for (int a = 0; a < 2; ++a) {
      hole.boxLo[a] = std::max(hole.boxLo[a], 0.0), hole.boxHi[a] = std::min(hole.boxHi[a], total[a]);
      hole.boxLoAt[a] = static_cast<int>(stations[a].size());
      stations[a].push_back({hole.boxLo[a], Station::Pocket, static_cast<int>(h), -1, hole.lo[a]});
      hole.boxHiAt[a] = static_cast<int>(stations[a].size());
      stations[a].push_back({hole.boxHi[a], Station::Pocket, static_cast<int>(h), 1, hole.hi[a]});
    }
  }
}

// Where a hole's box runs along axis a as the stations have it by now (a rectilinear hole: its extent).
std::array<double, 2> boxAlong(const GridHole& hole, const std::array<std::vector<Station>, 2>& stations, int a) {
  if (hole.rectilinear()) return {hole.lo[a], hole.hi[a]};
  return {stations[a][hole.boxLoAt[a]].at, stations[a][hole.boxHiAt[a]].at};
}

// Whether moving a pocket's side along axis a from `from` to `to` would run it into another hole's box.
bool runsInto(const std::vector<GridHole>& holes, const std::array<std::vector<Station>, 2>& stations, int a,
              int pocket, double from, double to) {
  const std::array<double, 2> own = boxAlong(holes[pocket], stations, 1 - a);
  for (std::size_t g = 0; g < holes.size(); ++g) {
    if (static_cast<int>(g) == pocket) continue;
    const std::array<double, 2> across = boxAlong(holes[g], stations, 1 - a), along = boxAlong(holes[g], stations, a);
    if (across[0] < own[1] && own[0] < across[1] && along[0] < std::max(from, to) && std::min(from, to) < along[1])
      return true;
  }
  return false;
}

// Whether the lines of two sides may be one line: they lie beside each other, not facing each other (their spans
// along the other axis apart): the pieces of a side that a notch splits, the sides of holes in a row.
bool mayShare(const Station& s, const Station& t) { return s.span[1] < t.span[0] || t.span[1] < s.span[0]; }

// Rectilinear holes' side lines within kMerge of each other merged into their mean where they may share a line,
// within kSame whatever their spans. [in,out] stations: one axis's.
void mergeSides(std::vector<Station>& stations) {
  std::vector<int> sides;
  for (std::size_t s = 0; s < stations.size(); ++s)
    if (stations[s].kind == Station::Side) sides.push_back(static_cast<int>(s));
  std::stable_sort(sides.begin(), sides.end(), [&](int s, int t) { return stations[s].at < stations[t].at; });
  for (std::size_t first = 0; first < sides.size();) {
    std::vector<int> cluster{sides[first]};
    std::size_t next = first + 1;
    for (; next < sides.size() && stations[sides[next]].at - stations[sides[first]].at <= kMerge; ++next) {
      const bool fits = stations[sides[next]].at - stations[sides[first]].at <= kSame ||
                        std::all_of(cluster.begin(), cluster.end(),
                                    [&](int s) { return mayShare(stations[s], stations[sides[next]]); });
      if (!fits) break;
      cluster.push_back(sides[next]);
    }
    double mean = 0;
    for (int s : cluster) mean += stations[s].at / cluster.size();
    for (int s : cluster) stations[s].at = mean;
    first = next;
  }
}

// Whether a pocket's side may move from `from` to `to`: its box stays kMinMargin beyond its hole (or moves away from
// it) and, if it grows, runs into no other hole's box as the stations have them. [in] stations, holes, a; [in] pocket:
// a station of stations[a]; [in] from, to.
bool mayMovePocket(const std::array<std::vector<Station>, 2>& stations, const std::vector<GridHole>& holes, int a,
                   const Station& pocket, double from, double to) {
  const double margin = (to - pocket.hole0) * pocket.outward;  // its box beyond its hole, if moved
  return margin >= std::min(kMinMargin, (from - pocket.hole0) * pocket.outward) &&
         ((to - from) * pocket.outward <= 0 || !runsInto(holes, stations, a, pocket.hole, from, to));
}

// Pockets' sides within kSnap of another line (the rim, a side's, another pocket's: where the gaps between holes
// are alike but for the chordal surface's noise) moved onto one line, if each may (mayMovePocket): no sliver of cells
// across the grid between them. First each onto the nearest rim or side line; then the pockets' sides left, in runs
// along the axis each within kSnap of the run's first, onto the run's mean together (holes in a row, the boxes of
// neighbours that meet half way: one line whatever the noise's order along it), a side that may not staying; then
// each onto the nearest line as the lines are by then. [in,out] stations: along axis a (the other's to test);
// [in] holes, a.
void snapPockets(std::array<std::vector<Station>, 2>& stations, const std::vector<GridHole>& holes, int a) {
  std::vector<Station>& along = stations[a];
  auto snapToNearest = [&](Station& pocket, bool fixedOnly) {
    double best = pocket.at, nearest = kSnap;
    for (const Station& line : along) {
      const double apart = std::abs(pocket.at - line.at);
      if ((!fixedOnly || line.kind != Station::Pocket) && apart > 0 && apart < nearest &&
          mayMovePocket(stations, holes, a, pocket, pocket.at, line.at))
        best = line.at, nearest = apart;
    }
    const bool moved = best != pocket.at;
    pocket.at = best;
    return moved;
  };
  std::vector<int> left;  // the pockets' sides not on a rim or side line
  for (std::size_t s = 0; s < along.size(); ++s)
    if (along[s].kind == Station::Pocket && !snapToNearest(along[s], true)) left.push_back(static_cast<int>(s));
  std::stable_sort(left.begin(), left.end(), [&](int s, int t) { return along[s].at < along[t].at; });
  for (std::size_t first = 0; first < left.size();) {
    std::size_t next = first + 1;
    while (next < left.size() && along[left[next]].at - along[left[first]].at <= kSnap) ++next;
    std::vector<double> was;
    double mean = 0;
    for (std::size_t k = first; k < next; ++k)
      was.push_back(along[left[k]].at), mean += was.back() / static_cast<double>(next - first);
    for (std::size_t k = first; k < next; ++k) along[left[k]].at = mean;
    for (std::size_t k = first; k < next; ++k)
      if (!mayMovePocket(stations, holes, a, along[left[k]], was[k - first], mean)) along[left[k]].at = was[k - first];
    first = next;
  }
  for (int s : left) snapToNearest(along[s], false);
}

// Where the ray from `from` through `through` first crosses a loop of the plane: the position along the loop
// (segment i from point i to i + 1, plus the share of it), or -1 if it does not. [in] p: the loop's points.
double rayHit(const std::vector<Eigen::Vector2d>& p, const Eigen::Vector2d& from, const Eigen::Vector2d& through) {
  const Eigen::Vector2d d = through - from;
  const int n = static_cast<int>(p.size());
  double nearest = 1e300, at = -1;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d e = p[(i + 1) % n] - p[i], w = p[i] - from;
    const double det = e.x() * d.y() - e.y() * d.x();  // solves from + s d = p[i] + t e
    if (det == 0) continue;
    const double s = (e.x() * w.y() - e.y() * w.x()) / det, t = (d.x() * w.y() - d.y() * w.x()) / det;
    if (s > 0 && t >= 0 && t < 1 && s < nearest) nearest = s, at = i + t;
  }
  return at;
}

// Whether positions along a loop go round it once, in order: they fall once, where they pass its first point.
bool roundOnce(const std::vector<double>& at) {
  int descents = 0;
  for (std::size_t t = 0; t < at.size(); ++t) descents += at[(t + 1) % at.size()] <= at[t];
  return descents == 1;
}

// Positions along a loop moved onto its sharp corners (turning more than kSharpCorner in space), each the nearest
// one's, if they still go round it once: the ring's quads then keep the hole's corners. [in] map, hole;
// [in,out] at: positions (point i + the share of the edge to i + 1).
void onCorners(const SurfaceMap& map, const std::vector<int>& hole, std::vector<double>& at) {
  const int n = static_cast<int>(hole.size());
  std::vector<double> moved = at;
  for (int c = 0; c < n; ++c) {
    const Vec3 in = map.points[hole[c]] - map.points[hole[(c + n - 1) % n]],
               out = map.points[hole[(c + 1) % n]] - map.points[hole[c]];
    if (!(in.cross(out).norm() > std::sin(kSharpCorner) * in.norm() * out.norm() || in.dot(out) < 0)) continue;
    std::size_t nearest = 0;
    auto apart = [&](double a) { return std::min(std::abs(a - c), n - std::abs(a - c)); };
    for (std::size_t t = 1; t < at.size(); ++t)
      if (apart(at[t]) < apart(at[nearest])) nearest = t;
    moved[nearest] = c;
  }
  if (roundOnce(moved)) at = moved;
}

// The loop points of a pocket's ring seen from the hole's centre: each where the ray from the centre through the
// box's node crosses the hole (an O-grid's straight spokes, square where the ring is thin), the nearest moved onto
// each sharp corner (onCorners); empty unless each node's ray crosses it and they go round it once, in the walk's
// order and no two are closer than kCrowded of their spacing were they even (spokes through box nodes that lines
// crowd). [in] map, hole, lines, box.
std::vector<LoopPoint> spokePoints(const SurfaceMap& map, const std::vector<int>& hole, const GridLines& lines,
                                   const Box& box) {
  std::vector<Eigen::Vector2d> p;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (int i : hole) p.push_back(map.uv[i]), centre += map.uv[i] / hole.size();
  const int n = static_cast<int>(p.size());
  std::vector<double> at;
  for (int t = 0; t < box.around(); ++t) {
    const auto [i, k] = box.walk(t);
    at.push_back(rayHit(p, centre, lines.uv(i, k)));
    if (at.back() < 0) return {};
  }
  if (!roundOnce(at)) return {};
  onCorners(map, hole, at);
  std::vector<LoopPoint> points;
  for (double a : at) {
    const int i = static_cast<int>(a);
    const double g = a - i;
    const int j = hole[(i + 1) % n];
    points.push_back({(1 - g) * map.points[hole[i]] + g * map.points[j], (1 - g) * p[i] + g * p[(i + 1) % n]});
  }
  const double even = arcLength(hole, map.points).back() / points.size();  // the points' spacing, were they even
  for (std::size_t t = 0; t < points.size(); ++t)
    if ((points[(t + 1) % points.size()].x - points[t].x).norm() < kCrowded * even) return {};
  return points;
}

// One axis's grid lines: the stations' places, ascending and once each (those within kSame of the one before as
// one: rounding), and between each two as many more as the quads between them need (one cell at the least).
struct AxisLines {
  std::vector<double> at;    // in quads, ascending: at[0] = 0 and at.back() the quads across (the rim's)
  std::vector<int> station;  // per station, its line
  int cells() const { return static_cast<int>(at.size()) - 1; }
};

// The stations' places along one axis and the rim's (0 and total), ascending, those within kSame of the one before
// taken as it. [in] stations, total.
std::vector<double> stationPlaces(const std::vector<Station>& stations, double total) {
  std::vector<double> all{0, total}, places;
  for (const Station& s : stations) all.push_back(s.at);
  std::sort(all.begin(), all.end());
  for (double at : all)
    if (places.empty() || at - places.back() > kSame) places.push_back(at);
  places.back() = total;
  return places;
}

// Per station, the line of its place (the place at or just below it). [in] stations, places; [in] lineOf: per place.
std::vector<int> stationLines(const std::vector<Station>& stations, const std::vector<double>& places,
                              const std::vector<int>& lineOf) {
  std::vector<int> line;
  for (const Station& s : stations)
    line.push_back(lineOf[std::upper_bound(places.begin(), places.end(), s.at + kSame) - places.begin() - 1]);
  return line;
}

// [in] stations: one axis's; [in] total: the quads across the square. Returns its lines.
AxisLines axisLines(const std::vector<Station>& stations, double total) {
  const std::vector<double> places = stationPlaces(stations, total);
  AxisLines lines;
  std::vector<int> lineOf;  // per place
  for (std::size_t p = 0; p < places.size(); ++p) {
    lineOf.push_back(static_cast<int>(lines.at.size()));
    if (p + 1 == places.size()) {
      lines.at.push_back(places[p]);
      break;
    }
    const int cells = count(places[p + 1] - places[p] - kSame);  // a half quad rounded down, whatever the rounding
    for (int c = 0; c < cells; ++c) lines.at.push_back(places[p] + (places[p + 1] - places[p]) * c / cells);
  }
  lines.station = stationLines(stations, places, lineOf);
  return lines;
}

// The lines of one axis through its stations, as many as a given rim's (sharedGrid with its rim given): each
// station's place on the nearest of the rim's lines after the last one taken (the rim's places on the rim), keeping
// one for every place still to come; the lines between two so moved moved with them, their shares of the gap kept.
// [in] stations: one axis's; [in] rim: the rim's lines in quads, ascending, 0 to the quads across. Nothing if the
// places are more than the lines.
std::optional<AxisLines> rimAxisLines(const std::vector<Station>& stations, const std::vector<double>& rim) {
  const std::vector<double> places = stationPlaces(stations, rim.back());
  const int n = static_cast<int>(rim.size()) - 1, inner = static_cast<int>(places.size()) - 2;
  if (inner > n - 1) return std::nullopt;
  std::vector<int> lineOf{0};  // per place
  for (int p = 1; p <= inner; ++p) {
    int best = lineOf.back() + 1;
    for (int j = best; j <= n - 1 - (inner - p); ++j)
      if (std::abs(rim[j] - places[p]) < std::abs(rim[best] - places[p])) best = j;
    lineOf.push_back(best);
  }
  lineOf.push_back(n);
  AxisLines lines;
  lines.at.resize(n + 1);
  for (std::size_t p = 0; p + 1 < places.size(); ++p) {
    const int a = lineOf[p], b = lineOf[p + 1];
    for (int j = a; j <= b; ++j) {
      const double share = rim[b] > rim[a] ? (rim[j] - rim[a]) / (rim[b] - rim[a]) : double(j - a) / (b - a);
      lines.at[j] = places[p] + (places[p + 1] - places[p]) * share;
    }
  }
  lines.station = stationLines(stations, places, lineOf);
  return lines;
}

// The grid's lines in the plane, falling with their index as holedGrid's, the outermost on the rim.
GridLines planeLines(const std::array<AxisLines, 2>& axis, const std::array<AxisMeasure, 2>& measure) {
  GridLines lines;
  for (int a = 0; a < 2; ++a) {
    std::vector<double>& plane = a == 0 ? lines.x : lines.y;
    const int n = axis[a].cells();
    for (int i = 0; i <= n; ++i) plane.push_back(i == 0 ? 1.0 : i == n ? -1.0 : measure[a].place(axis[a].at[n - i]));
  }
  return lines;
}

// A pocket's box of grid cells (Box: its corner 0 at +u, +v, where the lines' index is lowest).
Box pocketCells(const GridHole& hole, const std::array<AxisLines, 2>& axis) {
  const int u0 = axis[0].station[hole.boxLoAt[0]], u1 = axis[0].station[hole.boxHiAt[0]];
  const int v0 = axis[1].station[hole.boxLoAt[1]], v1 = axis[1].station[hole.boxHiAt[1]];
  return {axis[0].cells() - u1, axis[1].cells() - v1, u1 - u0, v1 - v0};
}

// A rectilinear hole's corners on the grid, in quads: corner j where the lines of sides j - 1 and j cross.
std::vector<Eigen::Vector2d> cornerPlaces(const GridHole& hole, const std::array<AxisLines, 2>& axis) {
  const int m = static_cast<int>(hole.corners.size());
  std::vector<Eigen::Vector2d> at;
  for (int j = 0; j < m; ++j) {
    const int a = hole.sideAxis[j], before = (j + m - 1) % m;
    Eigen::Vector2d c;
    c[a] = axis[a].at[axis[a].station[hole.sideStation[j]]];
    c[1 - a] = axis[1 - a].at[axis[1 - a].station[hole.sideStation[before]]];
    at.push_back(c);
  }
  return at;
}

// Whether each side of a rectilinear hole still spans one grid cell at least (merged lines may not close it).
bool sidesOpen(const GridHole& hole, const std::array<AxisLines, 2>& axis) {
  const int m = static_cast<int>(hole.corners.size());
  for (int j = 0; j < m; ++j) {
    const int b = 1 - hole.sideAxis[j];
    if (axis[b].station[hole.sideStation[(j + m - 1) % m]] == axis[b].station[hole.sideStation[(j + 1) % m]])
      return false;
  }
  return true;
}

// The cells the holes leave out of the grid: each pocket's box and each rectilinear hole's inside, per cell
// (i, k) of holedGrid's numbering at [i * n1 + k]. [out] skip. Returns false if two holes take a cell or a
// rectilinear hole's side closed.
bool leaveOutHoles(const std::vector<GridHole>& holes, const std::array<AxisLines, 2>& axis, std::vector<char>& skip) {
  const int n0 = axis[0].cells(), n1 = axis[1].cells();
  skip.assign(n0 * n1, 0);
  auto take = [&](int u, int v) { return skip[(n0 - 1 - u) * n1 + (n1 - 1 - v)]++ == 0; };  // ascending cell
  for (const GridHole& hole : holes) {
    if (!hole.rectilinear()) {
      const Box box = pocketCells(hole, axis);
      for (int i = box.i0; i < box.i0 + box.n0; ++i)
        for (int k = box.k0; k < box.k0 + box.n1; ++k)
          if (skip[i * n1 + k]++) return false;
      continue;
    }
    if (!sidesOpen(hole, axis)) return false;
    const std::vector<Eigen::Vector2d> polygon = cornerPlaces(hole, axis);
    std::array<int, 2> lo{1 << 30, 1 << 30}, hi{-1, -1};
    for (std::size_t j = 0; j < hole.corners.size(); ++j) {
      const int a = hole.sideAxis[j], line = axis[a].station[hole.sideStation[j]];
      lo[a] = std::min(lo[a], line), hi[a] = std::max(hi[a], line);
    }
    for (int u = lo[0]; u < hi[0]; ++u)
      for (int v = lo[1]; v < hi[1]; ++v) {
        const Eigen::Vector2d centre(0.5 * (axis[0].at[u] + axis[0].at[u + 1]),
                                     0.5 * (axis[1].at[v] + axis[1].at[v + 1]));
        if (insidePolygon(polygon, centre) && !take(u, v)) return false;
      }
  }
  return true;
}

// A rectilinear hole's loop measured along its sides: each step by how far it goes, in quads, along the axis its
// side runs along (so a side's points are where a grid line across the side crosses it).
std::vector<double> sideMeasure(const SurfaceMap& map, const GridHole& hole,
                                const std::array<AxisMeasure, 2>& measure) {
  const int n = static_cast<int>(hole.loop.size()), m = static_cast<int>(hole.corners.size());
  std::vector<double> along{0};
  for (int j = 0; j < m; ++j) {
    const int b = 1 - hole.sideAxis[j], end = j + 1 < m ? hole.corners[j + 1] : n;
    for (int i = hole.corners[j]; i < end; ++i)
      along.push_back(along.back() + std::abs(measure[b].quads(map.uv[hole.loop[(i + 1) % n]][b]) -
                                              measure[b].quads(map.uv[hole.loop[i]][b])));
  }
  return along;
}

// The grid's nodes on a rectilinear hole's sides moved onto its loop: side j's from corner j to corner j + 1,
// each where its line across the side crosses the loop (sideMeasure). [in,out] grid: nodes (addCells'); [in] map,
// hole, axis, measure, lines.
void snapSides(BlockGrid& grid, const SurfaceMap& map, const GridHole& hole, const std::array<AxisLines, 2>& axis,
               const std::array<AxisMeasure, 2>& measure, const GridLines& lines) {
  const std::vector<double> along = sideMeasure(map, hole, measure);
  const int n = static_cast<int>(hole.loop.size()), m = static_cast<int>(hole.corners.size());
  for (int j = 0; j < m; ++j) {
    const int a = hole.sideAxis[j], b = 1 - a, line = axis[a].station[hole.sideStation[j]];
    const int from = axis[b].station[hole.sideStation[(j + m - 1) % m]],
              to = axis[b].station[hole.sideStation[(j + 1) % m]];
    const double s0 = along[hole.corners[j]], s1 = along[j + 1 < m ? hole.corners[j + 1] : n];
    const int step = to > from ? 1 : -1;
    for (int t = from; t != to + step; t += step) {
      const double f = (axis[b].at[t] - axis[b].at[from]) / (axis[b].at[to] - axis[b].at[from]);
      std::array<int, 2> asc;
      asc[a] = line, asc[b] = t;
      const int node = lines.node(axis[0].cells() - asc[0], axis[1].cells() - asc[1]);
      grid.nodes[node] = loopPoint(map, hole.loop, along, s0 + f * (s1 - s0)).x;
    }
  }
}

// Grid lines where sides 0 and 2 (for x) and 1 and 3 (for y) of a box's walk round the rim put their nodes, averaged;
// the outermost on the square's sides. [in] all: the box of all cells; [in] rim: its walk's points.
GridLines rimLines(const Box& all, const std::vector<LoopPoint>& rim) {
  GridLines lines;
  for (int i = 0; i <= all.n0; ++i)
    lines.x.push_back(i == all.n0 ? -1.0
                                  : 0.5 * (rim[i].uv.x() + rim[(2 * all.n0 + all.n1 - i) % all.around()].uv.x()));
  for (int k = 0; k <= all.n1; ++k)
    lines.y.push_back(k == all.n1 ? -1.0
                                  : 0.5 * (rim[all.n0 + k].uv.y() + rim[(all.around() - k) % all.around()].uv.y()));
  lines.x[0] = 1, lines.y[0] = 1;
  return lines;
}

// The tensor grid of the lines with a pocket of four blocks round each hole (holedGrid's; `toRim`: pocketBox's),
// the nodes inside the pockets kept (unused). Empty if a pocket leaves the grid, two meet or a hole has no four corners
// in turn.
BlockGrid gridWithPockets(const SurfaceMap& map, const MapLocator& locate, const GridLines& lines, bool toRim,
                          const SizeField& size) {
  const int n0 = static_cast<int>(lines.x.size()) - 1, n1 = static_cast<int>(lines.y.size()) - 1;
  std::vector<char> inPocket(n0 * n1, 0);
  std::vector<std::pair<Box, std::size_t>> pockets;
  for (std::size_t h = 0; h < map.holes.size(); ++h) {
    Box box;
    if (!pocketBox(map, map.holes[h], lines, toRim, box)) return {};
    for (int i = box.i0; i < box.i0 + box.n0; ++i)
      for (int k = box.k0; k < box.k0 + box.n1; ++k)
        if (inPocket[i * n1 + k]++) return {};  // two pockets meet
    pockets.emplace_back(box, h);
  }
  BlockGrid grid;
  addCells(grid, locate, lines, inPocket);
  grid.blocks = 1;
  // The pockets' rings laid out side by side (each on its own), added in the holes' order.
  std::vector<std::optional<Ring>> rings(pockets.size());
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic)
  for (long p = 0; p < static_cast<long>(pockets.size()); ++p)
    errors.run([&] {
      const auto& [box, h] = pockets[p];
      std::vector<int> hole = map.holes[h];
      std::array<int, 4> corners;
      if (holeCorners(map, hole, corners))
        rings[p] = layRing(locate, lines, box, loopPoints(map, hole, corners, box.sides(), size), size);
    });
  errors.rethrow();
  for (std::size_t p = 0; p < pockets.size(); ++p) {
    if (!rings[p]) return {};
    appendRing(grid, lines, pockets[p].first, *rings[p], false);
  }
  return grid;
}

// Whether a given rim has its cells (at least one along each side) and a point per cell round them.
bool fitsItsCells(const SquareRim& rim) {
  return rim.n0 >= 1 && rim.n1 >= 1 && static_cast<int>(rim.points.size()) == 2 * (rim.n0 + rim.n1);
}

// The grid's nodes renumbered: `first` in their order, then the others in theirs. [in,out] grid; [in] first.
void numberFirst(BlockGrid& grid, const std::vector<int>& first) {
  std::vector<int> index(grid.nodes.size(), -1);
  std::vector<Vec3> nodes;
  for (int v : first) index[v] = static_cast<int>(nodes.size()), nodes.push_back(grid.nodes[v]);
  for (std::size_t v = 0; v < grid.nodes.size(); ++v)
    if (index[v] < 0) index[v] = static_cast<int>(nodes.size()), nodes.push_back(grid.nodes[v]);
  for (auto& quad : grid.quads)
    for (int& v : quad) v = index[v];
  grid.nodes = std::move(nodes);
}

// A side of a block: its nodes in the grid, from its first corner to its last.
struct BlockSide {
  std::vector<int> node;
  int cells() const { return static_cast<int>(node.size()) - 1; }
};

BlockSide reversed(BlockSide side) {
  std::reverse(side.node.begin(), side.node.end());
  return side;
}

// A block from its four sides (counter-clockwise, side k from corner k to k + 1; opposite sides with as many cells):
// its inner nodes by transfinite (Coons) interpolation of the sides' nodes, put on the surface, then its quads.
// [in,out] grid; [in] onSurface: the surface's point nearest to a point; [in] side.
void addCoonsBlock(BlockGrid& grid, const std::function<Vec3(const Vec3&)>& onSurface,
                   const std::array<BlockSide, 4>& side) {
  const int n0 = side[0].cells(), n1 = side[1].cells();
  auto boundary = [&](int i, int j) -> int {
    if (j == 0) return side[0].node[i];
    if (i == n0) return side[1].node[j];
    if (j == n1) return side[2].node[n0 - i];
    return side[3].node[n1 - j];
  };
  auto x = [&](int i, int j) { return grid.nodes[boundary(i, j)]; };
  std::vector<int> id((n0 + 1) * (n1 + 1));
  for (int i = 0; i <= n0; ++i)
    for (int j = 0; j <= n1; ++j) {
      if (i == 0 || j == 0 || i == n0 || j == n1) {
        id[i * (n1 + 1) + j] = boundary(i, j);
        continue;
      }
      const double u = static_cast<double>(i) / n0, v = static_cast<double>(j) / n1;
      const Vec3 p =
          (1 - v) * x(i, 0) + v * x(i, n1) + (1 - u) * x(0, j) + u * x(n0, j) -
          ((1 - u) * (1 - v) * x(0, 0) + u * (1 - v) * x(n0, 0) + u * v * x(n0, n1) + (1 - u) * v * x(0, n1));
      id[i * (n1 + 1) + j] = static_cast<int>(grid.nodes.size());
      grid.nodes.push_back(onSurface(p));
    }
  auto at = [&](int i, int j) { return id[i * (n1 + 1) + j]; };
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < n1; ++j) grid.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  ++grid.blocks;
}

// The segment from node `first` to node `last` of the grid as a side of m cells, each needing as many quads of the
// target size, its inner nodes put on the surface and added to the grid. [in,out] grid.
BlockSide spoke(BlockGrid& grid, const std::function<Vec3(const Vec3&)>& onSurface, int first, int last, int m,
                const SizeField& size) {
  const Vec3 a = grid.nodes[first], b = grid.nodes[last];
  const int samples = kRadialSamples * m;
  std::vector<Vec3> line;
  for (int k = 0; k <= samples; ++k) line.push_back(a + (b - a) * k / samples);
  const std::vector<double> quads = quadsAlong(line, size);
  BlockSide side{{first}};
  for (int j = 1; j < m; ++j) {
    side.node.push_back(static_cast<int>(grid.nodes.size()));
    grid.nodes.push_back(onSurface(a + (b - a) * sharePlace(quads, j, m) / samples));
  }
  side.node.push_back(last);
  return side;
}

}  // namespace

BlockGrid oGrid(const SurfaceMap& map, const SizeField& size) {
  if (map.empty() || map.boundary != MapBoundary::Circle || !map.holes.empty()) return {};
  const MapLocator locate(map);
  const std::vector<double> quads = quadsAlongLoop(map, map.rim, size);
  auto side = [&](int k) { return (k == 3 ? quads.back() : quads[map.corners[k + 1]]) - quads[map.corners[k]]; };
  const Box core{0, 0, count(std::max(side(0), side(2))), count(std::max(side(1), side(3)))};
  const GridLines lines{linesAlong(locate, {-kCore, 0.0}, core.n0, 0, size),
                        linesAlong(locate, {0.0, -kCore}, core.n1, 1, size)};
  BlockGrid grid;
  addCells(grid, locate, lines, std::vector<char>(core.n0 * core.n1, 0));
  grid.blocks = 1;
  addRing(grid, locate, lines, core, loopPoints(map, map.rim, map.corners, core.sides(), size), true, size);
  return grid;
}

BlockGrid triangleGrid(const SurfaceMap& map, const SizeField& size,
                       const std::function<Vec3(const Vec3&)>& onSurface) {
  if (map.empty() || map.boundary != MapBoundary::Square || !map.holes.empty() || map.sideMiddle < 0) return {};
  const std::vector<double> quads = quadsAlongLoop(map, map.rim, size);
  const double around = quads.back();
  // corners A, B, C (k = 0, 1, 2) counter-clockwise after the side's middle; side k runs from corner k to k + 1
  std::array<double, 3> at;  // the measure at each corner
  std::array<Vec3, 3> corner;
  for (int k = 0; k < 3; ++k) {
    const int p = map.corners[(map.sideMiddle + 1 + k) % 4];
    at[k] = quads[p], corner[k] = map.points[map.rim[p]];
  }
  auto span = [&](int k) { return std::fmod(at[(k + 1) % 3] - at[k] + around, around); };
  // The blocks meet at the incircle's centre and touch the sides where it does (each block a kite, right-angled at
  // the touch points): t[k], corner k's tangent length (t_A = (c + b - a) / 2), in quads of the target size.
  std::array<double, 3> t;
  for (int k = 0; k < 3; ++k) t[k] = 0.5 * (span(k) + span((k + 2) % 3) - span((k + 1) % 3));
  // x[j]: the cells of the spoke to side j's touch point, which the grid also puts on the rim from side j - 1's touch
  // point to corner j (t[j] long) and from corner j + 1 to side j + 1's touch point (t[j + 1] long): their geometric
  // mean, so that the cells on either are as much longer and shorter than the target size
  std::array<int, 3> x;
  for (int j = 0; j < 3; ++j) x[j] = count(std::sqrt(std::max(t[j], 0.0) * std::max(t[(j + 1) % 3], 0.0)));
  BlockGrid grid;  // the rim's nodes first, from A round it: side k from corner k to its touch point, then on
  std::array<int, 3> first, touch;
  for (int k = 0; k < 3; ++k) {
    const int before = x[(k + 2) % 3], after = x[(k + 1) % 3];  // cells from corner k to the touch point, and on
    first[k] = static_cast<int>(grid.nodes.size());
    for (int i = 0; i < before; ++i)
      grid.nodes.push_back(loopPoint(map, map.rim, quads, std::fmod(at[k] + t[k] * i / before, around)).x);
    touch[k] = static_cast<int>(grid.nodes.size());
    for (int i = 0; i < after; ++i)
      grid.nodes.push_back(
          loopPoint(map, map.rim, quads, std::fmod(at[k] + t[k] + (span(k) - t[k]) * i / after, around)).x);
  }
  const int rim = static_cast<int>(grid.nodes.size());
  auto rimSide = [&](int from, int cellCount) {
    BlockSide side;
    for (int i = from; i <= from + cellCount; ++i) side.node.push_back(i % rim);
    return side;
  };
  std::array<double, 3> opposite;  // side lengths, for the incentre (I = (a A + b B + c C) / (a + b + c))
  for (int k = 0; k < 3; ++k) opposite[k] = (corner[(k + 2) % 3] - corner[(k + 1) % 3]).norm();
  const Vec3 centre = (opposite[0] * corner[0] + opposite[1] * corner[1] + opposite[2] * corner[2]) /
                      (opposite[0] + opposite[1] + opposite[2]);
  const int o = static_cast<int>(grid.nodes.size());
  grid.nodes.push_back(onSurface(centre));
  std::array<BlockSide, 3> out;  // from the centre to each side's touch point
  for (int j = 0; j < 3; ++j) out[j] = spoke(grid, onSurface, o, touch[j], x[j], size);
  // block k: its corner, the touch point after it, the centre, the touch point before it
  for (int k = 0; k < 3; ++k) {
    const int before = (k + 2) % 3;
    addCoonsBlock(grid, onSurface,
                  {rimSide(first[k], x[before]), reversed(out[k]), out[before], rimSide(touch[before], x[k])});
  }
  return grid;
}

BlockGrid holedGrid(const SurfaceMap& map, const SizeField& size) {
  if (map.empty() || map.boundary != MapBoundary::Square) return {};
  const MapLocator locate(map);
  const std::vector<double> quads = quadsAlongLoop(map, map.rim, size);
  auto side = [&](int k) { return (k == 3 ? quads.back() : quads[map.corners[k + 1]]) - quads[map.corners[k]]; };
  const Box all{0, 0, count(std::max(side(0), side(2))), count(std::max(side(1), side(3)))};
  BlockGrid grid = gridWithPockets(map, locate, rimLines(all, loopPoints(map, map.rim, map.corners, all.sides(), size)),
                                   false, size);
  dropUnusedNodes(grid.nodes, grid.quads);  // those inside the pockets
  return grid;
}

BlockGrid holedGrid(const SurfaceMap& map, const SizeField& size, const SquareRim& rim) {
  const Box all{0, 0, rim.n0, rim.n1};
  if (map.empty() || map.boundary != MapBoundary::Square || !fitsItsCells(rim)) return {};
  const GridLines lines = rimLines(all, rim.points);
  BlockGrid grid = gridWithPockets(map, MapLocator(map), lines, true, size);
  if (grid.empty()) return {};
  std::vector<int> walk;
  for (int t = 0; t < all.around(); ++t) {
    const auto [i, k] = all.walk(t);
    walk.push_back(lines.node(i, k));
    grid.nodes[walk.back()] = rim.points[t].x;
  }
  numberFirst(grid, walk);
  dropUnusedNodes(grid.nodes, grid.quads);  // those inside the pockets (the rim's are used: they stay first)
  return grid;
}

namespace {

// sharedGrid, its rim's nodes given or not (rim: nothing).
BlockGrid sharedGridOn(const SurfaceMap& map, const SizeField& size, const SquareRim* rim) {
  if (map.empty() || map.boundary != MapBoundary::Square || map.holes.empty() || (rim && !fitsItsCells(*rim)))
    return {};
  const MapLocator locate(map);
  const std::array<AxisMeasure, 2> measure{AxisMeasure(locate, 0, size), AxisMeasure(locate, 1, size)};
  std::array<std::vector<Station>, 2> stations;
  std::vector<GridHole> holes = gridHoles(map, measure, stations);
  if (!separatePockets(holes)) return {};
  addPocketStations(holes, stations, {measure[0].total(), measure[1].total()});
  const Box all{0, 0, rim ? rim->n0 : 0, rim ? rim->n1 : 0};
  const GridLines given = rim ? rimLines(all, rim->points) : GridLines{};
  std::array<AxisLines, 2> axis;
  for (int a = 0; a < 2; ++a) {
    mergeSides(stations[a]);
    snapPockets(stations, holes, a);
    if (!rim) {
      axis[a] = axisLines(stations[a], measure[a].total());
      continue;
    }
    const std::vector<double>& plane = a == 0 ? given.x : given.y;  // falling with the index
    std::vector<double> quads;
    for (std::size_t j = plane.size(); j-- > 0;) quads.push_back(measure[a].quads(plane[j]));
    quads.front() = 0, quads.back() = measure[a].total();
    std::optional<AxisLines> lines = rimAxisLines(stations[a], quads);
    if (!lines) return {};
    axis[a] = std::move(*lines);
  }
  std::vector<char> skip;
  if (!leaveOutHoles(holes, axis, skip)) return {};
  const GridLines lines = planeLines(axis, measure);
  BlockGrid grid;
  addCells(grid, locate, lines, skip);
  grid.blocks = 1;
  for (GridHole& hole : holes) {
    if (hole.rectilinear()) {
      snapSides(grid, map, hole, axis, measure, lines);
      continue;
    }
    const Box box = pocketCells(hole, axis);
    std::vector<LoopPoint> ring = spokePoints(map, hole.loop, lines, box);
    std::array<int, 4> corners;
    if (ring.empty() && !holeCorners(map, hole.loop, corners)) return {};
    if (ring.empty()) ring = loopPoints(map, hole.loop, corners, box.sides(), size);  // by arc length, as holedGrid
    addRing(grid, locate, lines, box, ring, false, size);
  }
  if (rim) {
    std::vector<int> walk;
    for (int t = 0; t < all.around(); ++t) {
      const auto [i, k] = all.walk(t);
      walk.push_back(lines.node(i, k));
      grid.nodes[walk.back()] = rim->points[t].x;
    }
    numberFirst(grid, walk);
  }
  dropUnusedNodes(grid.nodes, grid.quads);  // those inside the holes and pockets (the rim's are used: they stay first)
  return grid;
}

}  // namespace

BlockGrid sharedGrid(const SurfaceMap& map, const SizeField& size) { return sharedGridOn(map, size, nullptr); }

BlockGrid sharedGrid(const SurfaceMap& map, const SizeField& size, const SquareRim& rim) {
  return sharedGridOn(map, size, &rim);
}

// A rim loop's angles in the map, from its first point on, ascending: 0 at its first point, 2 pi at the end.
std::vector<double> loopAngles(const SurfaceMap& map, const std::vector<int>& loop) {
  std::vector<double> angle;
  for (int p : loop) angle.push_back(map.uv[p].x() - map.uv[loop.front()].x());
  angle.push_back(2 * M_PI);
  return angle;
}

BlockGrid ringGrid(const SurfaceMap& map, const SizeField& size, int given) {
  if (map.empty() || map.boundary != MapBoundary::Annulus || map.holes.size() != 1) return {};
  const MapLocator locate(map);
  const std::vector<int>& inner = map.holes[0];
  const std::vector<double> innerAngle = loopAngles(map, inner), outerAngle = loopAngles(map, map.rim);
  if (!std::is_sorted(innerAngle.begin(), innerAngle.end()) || !std::is_sorted(outerAngle.begin(), outerAngle.end()))
    return {};
  const double outerQuads = quadsAlongLoop(map, map.rim, size).back(),
               innerQuads = quadsAlongLoop(map, inner, size).back();
  // Even: a tube standing on a sheet (a boss) puts a ring of `around` quads in the sheet's quads, and the quads
  // inside and round it can only be all quads if their boundaries are even.
  int around = std::max(kMinAround, count(std::max(outerQuads, innerQuads)));
  around = given > 0 ? given : around + around % 2;
  // Rows as square as the columns: the map's rectangle is -log(inner radius) tall and 2 pi wide.
  const double height = -std::log(map.innerRadius);
  const int across = count(height / (2 * M_PI) * around);
  // Column i at angle 2 pi i / around on every row: on a rim, that angle from the rim's first point.
  auto onRim = [&](const std::vector<int>& loop, const std::vector<double>& angle, double u) {
    const double fromFirst = std::fmod(u - map.uv[loop.front()].x() + 4 * M_PI, 2 * M_PI);
    return loopPoint(map, loop, angle, fromFirst).x;
  };
  BlockGrid grid;
  for (int j = 0; j <= across; ++j)
    for (int i = 0; i < around; ++i) {
      const double u = 2 * M_PI * i / around;
      if (j == 0)
        grid.nodes.push_back(onRim(inner, innerAngle, u));
      else if (j == across)
        grid.nodes.push_back(onRim(map.rim, outerAngle, u));
      else
        grid.nodes.push_back(locate.periodic({u, -height * (1 - static_cast<double>(j) / across)}, 2 * M_PI));
    }
  auto node = [&](int i, int j) { return j * around + (i % around); };
  for (int j = 0; j < across; ++j)
    for (int i = 0; i < around; ++i)
      grid.quads.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
  grid.blocks = 1;
  return grid;
}

}  // namespace hexlayer
