#include "quadmesh/block_grids.hpp"

#include <algorithm>
#include <cmath>

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

// The point of the line after j of its m quads, all needing the same share of it.
Eigen::Vector2d linePoint(const PlaneLine& line, int j, int m) {
  if (j >= m) return line.to;
  const double target = line.quads.back() * j / m;
  const int last = static_cast<int>(line.quads.size()) - 1;
  const int s = std::clamp(
      static_cast<int>(std::lower_bound(line.quads.begin(), line.quads.end(), target) - line.quads.begin()), 1, last);
  const double g = (target - line.quads[s - 1]) / std::max(line.quads[s] - line.quads[s - 1], 1e-300);
  return line.from + (line.to - line.from) * (s - 1 + g) / (line.quads.size() - 1);
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

// Rows of quads between a box's boundary walk and as many loop points the same way round, out to the
// outer rim or in to a hole: as many rows as the most any line between them needs, the nodes spaced
// along each line by the target size, the last row on the loop.
void addRing(BlockGrid& grid, const MapLocator& locate, const GridLines& lines, const Box& box,
             const std::vector<LoopPoint>& loop, bool outward, const SizeField& size) {
  const int n = box.around();
  std::vector<PlaneLine> across;
  int m = 1;
  for (int t = 0; t < n; ++t) {
    const auto [i, k] = box.walk(t);
    across.push_back(planeLine(locate, lines.uv(i, k), loop[t], size));
    m = std::max(m, static_cast<int>(std::round(across.back().quads.back())));
  }
  const int first = static_cast<int>(grid.nodes.size());  // row j >= 1, position t: first + (j - 1) n + t
  for (int j = 1; j <= m; ++j)
    for (int t = 0; t < n; ++t) grid.nodes.push_back(j == m ? loop[t].x : locate(linePoint(across[t], j, m)));
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
// plane; false if that leaves the grid.
bool pocketBox(const SurfaceMap& map, const std::vector<int>& hole, const GridLines& lines, Box& box) {
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

BlockGrid holedGrid(const SurfaceMap& map, const SizeField& size) {
  if (map.empty() || map.boundary != MapBoundary::Square) return {};
  const MapLocator locate(map);
  const std::vector<double> quads = quadsAlongLoop(map, map.rim, size);
  auto side = [&](int k) { return (k == 3 ? quads.back() : quads[map.corners[k + 1]]) - quads[map.corners[k]]; };
  const Box all{0, 0, count(std::max(side(0), side(2))), count(std::max(side(1), side(3)))};
  // Grid lines where sides 0 and 2 (for x) and 1 and 3 (for y) put their nodes, averaged.
  const std::vector<LoopPoint> rim = loopPoints(map, map.rim, map.corners, all.sides(), size);
  GridLines lines;
  for (int i = 0; i <= all.n0; ++i)
    lines.x.push_back(i == all.n0 ? -1.0
                                  : 0.5 * (rim[i].uv.x() + rim[(2 * all.n0 + all.n1 - i) % all.around()].uv.x()));
  for (int k = 0; k <= all.n1; ++k)
    lines.y.push_back(k == all.n1 ? -1.0
                                  : 0.5 * (rim[all.n0 + k].uv.y() + rim[(all.around() - k) % all.around()].uv.y()));
  lines.x[0] = 1, lines.y[0] = 1;
  std::vector<char> inPocket(all.n0 * all.n1, 0);
  std::vector<std::pair<Box, std::size_t>> pockets;
  for (std::size_t h = 0; h < map.holes.size(); ++h) {
    Box box;
    if (!pocketBox(map, map.holes[h], lines, box)) return {};
    for (int i = box.i0; i < box.i0 + box.n0; ++i)
      for (int k = box.k0; k < box.k0 + box.n1; ++k)
        if (inPocket[i * all.n1 + k]++) return {};  // two pockets meet
    pockets.emplace_back(box, h);
  }
  BlockGrid grid;
  addCells(grid, locate, lines, inPocket);
  grid.blocks = 1;
  for (const auto& [box, h] : pockets) {
    std::vector<int> hole = map.holes[h];
    std::array<int, 4> corners;
    if (!holeCorners(map, hole, corners)) return {};
    addRing(grid, locate, lines, box, loopPoints(map, hole, corners, box.sides(), size), false, size);
  }
  dropUnusedNodes(grid.nodes, grid.quads);  // those inside the pockets
  return grid;
}

// A rim loop's angles in the map, from its first point on, ascending: 0 at its first point, 2 pi at the end.
std::vector<double> loopAngles(const SurfaceMap& map, const std::vector<int>& loop) {
  std::vector<double> angle;
  for (int p : loop) angle.push_back(map.uv[p].x() - map.uv[loop.front()].x());
  angle.push_back(2 * M_PI);
  return angle;
}

BlockGrid ringGrid(const SurfaceMap& map, const SizeField& size) {
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
  around += around % 2;
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
