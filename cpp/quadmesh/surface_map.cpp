#include "quadmesh/surface_map.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>

#include "chordal/chordal_locator.hpp"
#include "core/groups.hpp"
#include "core/polygon.hpp"
#include "core/union_find.hpp"

namespace hexlayer {
namespace {

constexpr double kSharpCorner = 50 * M_PI / 180;  // a rim turning more is a corner
// Where a rim has fewer than four corners, they are looked for again over windows this many times wider.
constexpr double kWideCorner = 3;
// An annulus longer than this (2 pi x length / circumference) is left to the other layouts: a tube more
// than 4 diameters long (its map's rectangle would be very tall, the rows many).
constexpr double kMaxAnnulusModulus = 8;
// A ring's rims: the shorter at least this share of the longer (a tube, a washer); a small hole in a plate
// is left to the grid's pocket.
constexpr double kMinRingRims = 0.4;

// The rim loops, each along its directed edges (the facets' own direction: the surface on the left),
// or none if the surface is not a connected sphere with holes whose rims do not touch.
std::vector<std::vector<int>> rimLoops(const std::vector<std::array<int, 3>>& triangles, std::size_t points) {
  std::unordered_map<std::uint64_t, int> uses;
  UnionFind connected(static_cast<int>(points));
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[edgeKey(t[k], t[(k + 1) % 3])], connected.unite(t[k], t[(k + 1) % 3]);
  std::vector<int> next(points, -1);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (uses[edgeKey(t[k], t[(k + 1) % 3])] == 1) {
        if (next[t[k]] >= 0) return {};  // two rim loops touch at a point
        next[t[k]] = t[(k + 1) % 3];
      }
  for (std::size_t p = 0; p < points; ++p)
    if (connected.find(static_cast<int>(p)) != 0) return {};
  std::vector<std::vector<int>> loops;
  std::vector<char> seen(points, 0);
  for (std::size_t p = 0; p < points; ++p) {
    if (next[p] < 0 || seen[p]) continue;
    loops.emplace_back();
    for (int q = static_cast<int>(p); !seen[q]; q = next[q]) {
      if (next[q] < 0) return {};  // a rim edge that no other follows: the rim is not oriented as one
      seen[q] = 1, loops.back().push_back(q);
    }
  }
  const long euler = static_cast<long>(points) - static_cast<long>(uses.size()) + static_cast<long>(triangles.size());
  if (loops.empty() || euler != 2 - static_cast<long>(loops.size())) return {};
  return loops;
}

// Arc length along a loop from its point i forward to its point j (positions taken round the loop),
// from `length`, the arc length from its first point (arcLength).
double loopSpan(const std::vector<double>& length, int i, int j) {
  const int n = static_cast<int>(length.size()) - 1;
  const double total = length.back();
  return std::fmod(length[(j % n + n) % n] - length[(i % n + n) % n] + 2 * total, total);
}

// How much the rim turns at each of its points in the surface's tangent plane (the rim's bends
// with a bent surface do not count): the angle from its direction `window` behind the point to
// its direction `window` ahead, positive to the left (into the surface).
std::vector<double> rimTurning(const std::vector<int>& loop, const std::vector<double>& length,
                               const std::vector<Vec3>& x, const std::vector<Vec3>& normals, double window) {
  const int n = static_cast<int>(loop.size());
  std::vector<double> turn(n, 0);
  for (int i = 0; i < n; ++i) {
    int back = i - 1, ahead = i + 1;
    while (back > i - n + 1 && loopSpan(length, back, i) < window) --back;
    while (ahead < i + n - 1 && loopSpan(length, i, ahead) < window) ++ahead;
    const Vec3& normal = normals[loop[i]];
    auto tangent = [&](const Vec3& d) { return (d - d.dot(normal) * normal).normalized(); };
    const Vec3 in = tangent(x[loop[i]] - x[loop[(back % n + n) % n]]), out = tangent(x[loop[ahead % n]] - x[loop[i]]);
    turn[i] = std::atan2(normal.dot(in.cross(out)), in.dot(out));
  }
  return turn;
}

// The point of a loop halfway (by arc length) along the longest stretch between consecutive corners (positions in
// the loop, ascending). [in] corners; [in] length: arcLength of the loop.
int longestSideMiddle(const std::vector<int>& corners, const std::vector<double>& length) {
  const int n = static_cast<int>(length.size()) - 1;
  double longest = -1;
  int middle = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const int a = corners[k], b = corners[(k + 1) % corners.size()];
    const double span = loopSpan(length, a, b > a ? b : b + n);
    if (span <= longest) continue;
    longest = span;
    for (int i = a + 1; i < (b > a ? b : b + n); ++i)  // the first point past half the span
      if (loopSpan(length, a, i) >= 0.5 * span) {
        middle = i % n;
        break;
      }
  }
  return middle;
}

// The loop's points where it turns more than kSharpCorner, most within `window` either side (ascending).
std::vector<int> turningPeaks(const std::vector<double>& turn, const std::vector<double>& length, double window) {
  const int n = static_cast<int>(turn.size());
  std::vector<int> peaks;
  for (int i = 0; i < n; ++i) {
    bool peak = turn[i] > kSharpCorner;
    for (int j = i - 1; peak && j > i - n && loopSpan(length, j, i) < window; --j)
      peak = turn[(j % n + n) % n] < turn[i];
    for (int j = i + 1; peak && j < i + n && loopSpan(length, i, j) < window; ++j) peak = turn[j % n] <= turn[i];
    if (peak) peaks.push_back(i);
  }
  return peaks;
}

// The rim's four corners, ascending along it: its four sharpest corners (turning more than
// kSharpCorner, the most within `window`) if it has four or more (then `sharp`), else the diagonal
// extremes of its principal axes (a rounded rectangle's arcs, a circle's 45° points); three sharp corners (a
// triangle) and the middle of its longest side, then the middle's position is `middle` (else -1).
std::array<int, 4> rimCorners(const ChordalSurface& chordal, const std::vector<int>& loop,
                              const std::vector<double>& length, double window, bool& sharp, int& middle) {
  middle = -1;
  const std::vector<double> turn = rimTurning(loop, length, chordal.vertices, chordal.normals, window);
  std::vector<int> peaks = turningPeaks(turn, length, window);
  std::array<int, 4> corners{};
  sharp = peaks.size() >= 4;
  if (sharp) {
    std::stable_sort(peaks.begin(), peaks.end(), [&](int a, int b) { return turn[a] > turn[b]; });
    std::copy(peaks.begin(), peaks.begin() + 4, corners.begin());
    std::sort(corners.begin(), corners.end());
    return corners;
  }
  // Fewer than four: corners rounded wider than the window (a gusset's foot round a bend) turn as much over a
  // window kWideCorner times as wide.
  const double wide = kWideCorner * window;
  const std::vector<double> wideTurn = rimTurning(loop, length, chordal.vertices, chordal.normals, wide);
  for (int p : turningPeaks(wideTurn, length, wide))
    if (std::none_of(peaks.begin(), peaks.end(),
                     [&](int q) { return std::min(loopSpan(length, p, q), loopSpan(length, q, p)) < window; }))
      peaks.push_back(p);
  std::sort(peaks.begin(), peaks.end());
  if (peaks.size() >= 4) {
    std::stable_sort(peaks.begin(), peaks.end(), [&](int a, int b) { return wideTurn[a] > wideTurn[b]; });
    std::copy(peaks.begin(), peaks.begin() + 4, corners.begin());
  } else if (peaks.size() == 3) {  // a triangle: its corners, and the middle of its longest side
    std::copy(peaks.begin(), peaks.end(), corners.begin());
    corners[3] = middle = longestSideMiddle(peaks, length);
  } else {
    std::vector<Vec3> points;
    for (int p : loop) points.push_back(chordal.vertices[p]);
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : points) mean += p / points.size();
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points) covariance += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
    corners = diagonalExtremes(points, mean, axes.eigenvectors().col(2), axes.eigenvectors().col(1));
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

// Where the outer rim goes, `f` of the way from corner k to corner k + 1.
Eigen::Vector2d boundaryPoint(MapBoundary boundary, int k, double f) {
  if (boundary == MapBoundary::Circle) {
    const double angle = M_PI / 4 + (k + f) * M_PI / 2;
    return {std::cos(angle), std::sin(angle)};
  }
  const Eigen::Vector2d corner[4] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  return (1 - f) * corner[k] + f * corner[(k + 1) % 4];
}

// Floater's mean value weights, as the matrix of "every point off the rim is the weighted mean of
// its neighbours" (row i: sum_j w_ij u_i - sum_j w_ij u_j = 0, w_ij = (tan(α/2) + tan(β/2)) / |x_j - x_i|
// with α, β the angles at i of the two triangles on the edge), and "u_i = its place" on the rim.
Eigen::SparseMatrix<double> meanValueSystem(const std::vector<std::array<int, 3>>& triangles,
                                            const std::vector<Vec3>& x, const std::vector<char>& onRim) {
  std::vector<Eigen::Triplet<double>> entries;  // Eigen sums the duplicates
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3], l = t[(k + 2) % 3];
      if (onRim[i]) continue;
      const Vec3 a = x[j] - x[i], b = x[l] - x[i];
      const double la = std::max(a.norm(), 1e-300), lb = std::max(b.norm(), 1e-300);
      const double halfTan = std::tan(0.5 * std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0)));
      entries.emplace_back(i, j, -halfTan / la), entries.emplace_back(i, l, -halfTan / lb);
      entries.emplace_back(i, i, halfTan / la + halfTan / lb);
    }
  for (std::size_t i = 0; i < x.size(); ++i)
    if (onRim[i]) entries.emplace_back(i, i, 1.0);
  Eigen::SparseMatrix<double> a(x.size(), x.size());
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

// The points off the rim placed by the mean value weights, the rim's kept: one sparse LU solve.
// False if the solve fails. Rows and columns are put in one fill-reducing order (approximate
// minimum degree of the pattern of A + A^T), which keeps the diagonal, where this diagonally
// dominant matrix has its pivots; SparseLU's own orderings permute only the columns, which moves
// the diagonal off (COLAMD: 3.5x the time on a 310 000 point surface; AMD or METIS: 100x).
bool solveInside(const Eigen::SparseMatrix<double>& a, std::vector<Eigen::Vector2d>& uv) {
  using Sparse = Eigen::SparseMatrix<double>;
  using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
  Eigen::MatrixX2d rhs(uv.size(), 2);
  for (std::size_t i = 0; i < uv.size(); ++i) rhs.row(i) = uv[i].transpose();  // zero off the rim
  Permutation order;
  Eigen::AMDOrdering<int>()(Sparse(a + Sparse(a.transpose())), order);
  const Permutation p = order.inverse();  // row i of P A P^T is row order[i] of A
  Eigen::SparseLU<Sparse, Eigen::NaturalOrdering<int>> lu(p * a * p.transpose());
  if (lu.info() != Eigen::Success) return false;
  const Eigen::MatrixX2d solution = p.transpose() * lu.solve(p * rhs);
  if (lu.info() != Eigen::Success || !solution.allFinite()) return false;
  for (std::size_t i = 0; i < uv.size(); ++i) uv[i] = solution.row(i).transpose();
  return true;
}

}  // namespace

void closeByFan(std::vector<Vec3>& points, std::vector<std::array<int, 3>>& triangles, const std::vector<int>& loop,
                bool reverse) {
  Vec3 centre = Vec3::Zero();
  for (int p : loop) centre += points[p] / loop.size();
  const int c = static_cast<int>(points.size());
  points.push_back(centre);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    triangles.push_back(reverse ? std::array<int, 3>{b, a, c} : std::array<int, 3>{a, b, c});
  }
}

namespace {

// The map's holes filled, each by a fan of triangles round its centroid, the outer rim (map.rim from its corner 0)
// placed on the boundary by arc length between its corners, the points inside by the mean value weights; the holes
// then walked counter-clockwise in the plane. [in,out] map: points, triangles, rim, corners, boundary set; uv, holes
// and the fans added. [in] holes: the rim loops of the holes, either way round. False if the solve fails.
bool placeInPlane(SurfaceMap& map, const std::vector<std::vector<int>>& holes) {
  for (const std::vector<int>& hole : holes) closeByFan(map.points, map.triangles, hole, true);
  const std::vector<int>& outer = map.rim;
  const std::vector<double> length = arcLength(outer, map.points);
  map.uv.assign(map.points.size(), Eigen::Vector2d::Zero());
  std::vector<char> onRim(map.points.size(), 0);
  for (int k = 0; k < 4; ++k) {
    const std::size_t end = k == 3 ? outer.size() : map.corners[k + 1];
    const double from = length[map.corners[k]], to = length[end];
    for (std::size_t i = map.corners[k]; i < end; ++i)
      map.uv[outer[i]] = boundaryPoint(map.boundary, k, (length[i] - from) / (to - from)), onRim[outer[i]] = 1;
  }
  if (!solveInside(meanValueSystem(map.triangles, map.points, onRim), map.uv)) return false;
  for (std::vector<int> hole : holes) {
    std::vector<Eigen::Vector2d> uv;
    for (int p : hole) uv.push_back(map.uv[p]);
    if (polygonArea(uv) < 0) std::reverse(hole.begin(), hole.end());
    map.holes.push_back(std::move(hole));
  }
  return true;
}

// The shortest path along the triangles' edges from `from` to `to` (points), through no other rim point.
std::vector<int> shortestPath(const SurfaceMap& map, const std::vector<char>& onRim, int from, int to) {
  std::vector<std::vector<int>> next(map.points.size());
  for (const auto& t : map.triangles)
    for (int k = 0; k < 3; ++k) next[t[k]].push_back(t[(k + 1) % 3]), next[t[(k + 1) % 3]].push_back(t[k]);
  std::vector<double> distance(map.points.size(), std::numeric_limits<double>::infinity());
  std::vector<int> previous(map.points.size(), -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[from] = 0, queue.push({0, from});
  while (!queue.empty()) {
    const auto [d, p] = queue.top();
    queue.pop();
    if (p == to) break;
    if (d > distance[p] || (p != from && onRim[p])) continue;
    for (int q : next[p])
      if (const double e = d + (map.points[q] - map.points[p]).norm(); e < distance[q])
        distance[q] = e, previous[q] = p, queue.push({e, q});
  }
  if (previous[to] < 0) return {};
  std::vector<int> path{to};
  while (path.back() != from) path.push_back(previous[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

// Opens the surface along the path (a cut from rim to rim): the triangles on the right of it get a
// copy of each of its points. Returns the copies, in the path's order.
std::vector<int> cutOpen(SurfaceMap& map, const std::vector<int>& path) {
  std::unordered_map<std::uint64_t, int> cutEdge;  // directed edge of the path -> 1
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    cutEdge[edgeKey(path[k], path[k + 1])] = 1, cutEdge[edgeKey(path[k + 1], path[k])] = 1;
  const Groups<int> around = groupByKey<int>(map.points.size(), [&](auto emit) {  // the triangles round each point
    for (std::size_t t = 0; t < map.triangles.size(); ++t)
      for (int p : map.triangles[t]) emit(p, static_cast<int>(t));
  });
  std::vector<int> copy;
  for (int p : path) copy.push_back(static_cast<int>(map.points.size())), map.points.push_back(map.points[p]);
  std::vector<std::pair<int, std::size_t>> moves;  // (triangle, path position): the triangle takes the copy
  for (std::size_t k = 0; k < path.size(); ++k) {  // every side decided on the uncut triangles first
    const int v = path[k];
    const std::vector<int> fan(around.items.begin() + around.start[v], around.items.begin() + around.start[v + 1]);
    std::vector<int> side(fan.size(), 0);  // +1 left of the path, -1 right
    for (std::size_t f = 0; f < fan.size(); ++f) {
      const auto& t = map.triangles[fan[f]];
      for (int e = 0; e < 3; ++e) {
        const int a = t[e], b = t[(e + 1) % 3];
        if (k + 1 < path.size() && a == v && b == path[k + 1]) side[f] = 1;
        if (k + 1 < path.size() && a == path[k + 1] && b == v) side[f] = -1;
        if (k > 0 && a == path[k - 1] && b == v) side[f] = 1;
        if (k > 0 && a == v && b == path[k - 1]) side[f] = -1;
      }
    }
    for (bool spread = true; spread;) {  // round v across the edges that are not the cut
      spread = false;
      for (std::size_t f = 0; f < fan.size(); ++f)
        for (std::size_t g = 0; g < fan.size(); ++g) {
          if (side[f] == 0 || side[g] != 0) continue;
          for (int w : map.triangles[fan[f]])
            if (w != v && !cutEdge.count(edgeKey(v, w)) &&
                std::find(map.triangles[fan[g]].begin(), map.triangles[fan[g]].end(), w) != map.triangles[fan[g]].end())
              side[g] = side[f], spread = true;
        }
    }
    for (std::size_t f = 0; f < fan.size(); ++f)
      if (side[f] < 0) moves.emplace_back(fan[f], k);
  }
  for (const auto& [t, k] : moves)
    for (int& w : map.triangles[t]) w = w == path[k] ? copy[k] : w;
  return copy;
}

// The cotangent (linear finite element) system of a surface cut open along `path` (copy[k]: the copy of path[k])
// for a function that is harmonic across the cut and free on the rims (its normal derivative 0 there: the
// stiffness rows of the rim points, which the mean value weights would tilt along the rim and so twist the
// map) and jumps by the right-hand side's values on the copies: a copy's row says value(copy) - value(path
// point); a path point's row holds the edges of both sides; the first path point's row fixes its value (to the
// right-hand side's, 0).
Eigen::SparseMatrix<double> periodicSystem(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec3>& x,
                                           const std::vector<int>& path, const std::vector<int>& copy) {
  std::vector<int> rowOf(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) rowOf[i] = static_cast<int>(i);
  for (std::size_t k = 0; k < path.size(); ++k) rowOf[copy[k]] = path[k];
  std::vector<Eigen::Triplet<double>> entries;  // Eigen sums the duplicates
  auto edge = [&](int a, int b, double w) {     // w (value(b) - value(a)) in a's row, and the other way round
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
      if (rowOf[from] == path.front()) continue;
      entries.emplace_back(rowOf[from], to, -w), entries.emplace_back(rowOf[from], from, w);
    }
  };
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int c = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];  // edge a-b, opposite corner c
      const Vec3 u = x[a] - x[c], v = x[b] - x[c];
      const double sine = u.cross(v).norm();
      if (sine > 0) edge(a, b, 0.5 * u.dot(v) / sine);  // half the cotangent of the angle at c
    }
  entries.emplace_back(path.front(), path.front(), 1.0);
  for (std::size_t k = 0; k < path.size(); ++k)
    entries.emplace_back(copy[k], copy[k], 1.0), entries.emplace_back(copy[k], path[k], -1.0);
  Eigen::SparseMatrix<double> a(x.size(), x.size());
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

// An annulus's conformal modulus from its height function h (0 on one rim, 1 on the other): 2 pi over the
// Dirichlet energy of h (conformally invariant: 2 pi / M on the rectangle of height M), on the map's triangles.
template <class Height>
double conformalModulus(const SurfaceMap& map, Height&& h) {
  double energy = 0;
  for (const auto& t : map.triangles) {
    const Vec3 &a = map.points[t[0]], &b = map.points[t[1]], &c = map.points[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double doubleArea = n.norm();
    if (doubleArea <= 0) continue;
    // grad h = sum of h_i (n x e_i) / (2 area), e_i the edge opposite corner i
    const Vec3 grad =
        (h(t[0]) * n.cross(c - b) + h(t[1]) * n.cross(a - c) + h(t[2]) * n.cross(b - a)) / (doubleArea * doubleArea);
    energy += 0.5 * doubleArea * grad.squaredNorm();
  }
  return energy > 0 ? 2 * M_PI / energy : 0;
}

// Whether the angle increases along the rim loop (by less than a turn): the map does not fold at the rim.
bool anglesIncrease(const std::vector<int>& loop, const std::vector<Eigen::Vector2d>& uv) {
  for (std::size_t i = 1; i < loop.size(); ++i)
    if (!(uv[loop[i]].x() > uv[loop[i - 1]].x())) return false;
  return uv[loop.back()].x() < uv[loop.front()].x() + 2 * M_PI;
}

// The annulus map of a surface with two rims (loops, longer first; map.points and map.triangles set).
SurfaceMap mapAnnulus(SurfaceMap map, std::vector<std::vector<int>> loops) {
  if (loops.size() != 2 || loops[0].size() < 8 || loops[1].size() < 8) return {};
  if (arcLength(loops[1], map.points).back() < kMinRingRims * arcLength(loops[0], map.points).back())
    return {};  // a hole
  std::vector<int>& outer = loops[0];
  std::vector<int>& inner = loops[1];
  std::reverse(inner.begin(), inner.end());  // round the hole the way the outer rim goes
  double apart = 0;                          // mean distance from the outer rim's points to the inner rim
  int facing = 0;
  for (std::size_t i = 0; i < outer.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < inner.size(); ++j)
      if (const double d = (map.points[outer[i]] - map.points[inner[j]]).norm(); d < nearest) {
        nearest = d;
        if (i == 0) facing = static_cast<int>(j);
      }
    apart += nearest / outer.size();
  }
  std::rotate(inner.begin(), inner.begin() + facing, inner.end());
  const std::vector<double> outerLength = arcLength(outer, map.points), innerLength = arcLength(inner, map.points);
  const double modulus = 2 * M_PI * apart / (0.5 * (outerLength.back() + innerLength.back()));
  if (!(modulus < kMaxAnnulusModulus)) return {};
  map.boundary = MapBoundary::Annulus;
  // The height between the rims: harmonic, 0 on the inner rim and 1 on the outer.
  std::vector<char> onRim(map.points.size(), 0);
  std::vector<Eigen::Vector2d> height(map.points.size(), Eigen::Vector2d::Zero());
  for (int p : inner) onRim[p] = 1;
  for (int p : outer) onRim[p] = 1, height[p].x() = 1;
  if (!solveInside(meanValueSystem(map.triangles, map.points, onRim), height)) return {};
  const std::vector<int> path = shortestPath(map, onRim, inner[0], outer[0]);
  if (path.size() < 2) return {};
  const std::size_t uncut = map.points.size();
  const std::vector<int> copy = cutOpen(map, path);
  // The rectangle: the height between the rims as solved (a copy at its point's), scaled by the annulus's
  // conformal modulus; the angle its harmonic conjugate: harmonic everywhere, free on both rims (its lines
  // meet them square) and 2 pi more on the cut's copies than on the cut.
  map.uv.assign(map.points.size(), Eigen::Vector2d::Zero());
  std::vector<Eigen::Vector2d> angle(map.points.size(), Eigen::Vector2d::Zero());
  for (std::size_t k = 0; k < path.size(); ++k) angle[copy[k]].x() = 2 * M_PI;
  if (!solveInside(periodicSystem(map.triangles, map.points, path, copy), angle)) return {};
  auto uncutOf = [&](std::size_t i) { return i < uncut ? static_cast<int>(i) : path[i - uncut]; };
  const double conformal = conformalModulus(map, [&](std::size_t i) { return height[uncutOf(i)].x(); });
  if (!(conformal > 0 && conformal < kMaxAnnulusModulus)) return {};
  map.innerRadius = std::exp(-conformal);
  for (std::size_t i = 0; i < map.points.size(); ++i)
    map.uv[i] = {angle[i].x(), -conformal * (1 - height[uncutOf(i)].x())};
  if (!anglesIncrease(outer, map.uv)) return {};
  map.rim = outer;
  map.holes = {inner};
  const int n = static_cast<int>(outer.size());
  map.corners = {0, n / 4, n / 2, 3 * n / 4};
  return map;
}

// The triangles turned to one orientation, across every shared edge (breadth first from the first). False if
// they are not connected, or not orientable.
bool orientAlike(std::vector<std::array<int, 3>>& triangles) {
  std::map<std::pair<int, int>, std::vector<int>> ofEdge;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) ofEdge[std::minmax(triangles[t][k], triangles[t][(k + 1) % 3])].push_back(t);
  std::vector<char> done(triangles.size(), 0);
  std::queue<int> next;
  next.push(0), done[0] = 1;
  std::size_t reached = 1;
  while (!next.empty()) {
    const int t = next.front();
    next.pop();
    for (int k = 0; k < 3; ++k) {
      const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      for (int u : ofEdge[std::minmax(a, b)]) {
        if (u == t) continue;
        std::array<int, 3>& tri = triangles[u];
        bool same = false;  // u runs along a -> b as t does: turned the other way
        for (int m = 0; m < 3; ++m) same = same || (tri[m] == a && tri[(m + 1) % 3] == b);
        if (done[u]) {
          if (same) return false;
          continue;
        }
        if (same) std::swap(tri[1], tri[2]);
        done[u] = 1, ++reached, next.push(u);
      }
    }
  }
  return reached == triangles.size();
}

// Per triangle, its corners in a frame of its own plane (the first at 0, the second on the x axis), as complex
// numbers: LSCM's W_j = (z_{j+2} - z_{j+1}) / sqrt(2 A) (Eq. 5), by corner.
std::array<std::complex<double>, 3> conformalWeights(const std::vector<Vec3>& x, const std::array<int, 3>& t) {
  const Vec3 e = x[t[1]] - x[t[0]], f = x[t[2]] - x[t[0]];
  const Vec3 e1 = e.normalized(), e2 = e.cross(f).cross(e).normalized();
  const std::array<std::complex<double>, 3> z{0.0, {e.norm(), 0.0}, {f.dot(e1), f.dot(e2)}};
  const double twiceArea = e.cross(f).norm();
  std::array<std::complex<double>, 3> w;
  for (int j = 0; j < 3; ++j) w[j] = (z[(j + 2) % 3] - z[(j + 1) % 3]) / std::sqrt(twiceArea);
  return w;
}

// The z component of the cross product of two vectors of the plane (twice their triangle's signed area).
double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// The map's uv scaled to its triangles' area, every triangle counter-clockwise in it; with `mirror`, a map whose
// triangles are all clockwise is mirrored (y -> -y) first. False if a triangle turns the other way or has no area in
// uv (folded). [in,out] map: points, triangles and uv set.
bool counterClockwiseToScale(SurfaceMap& map, bool mirror) {
  double area3 = 0, area2 = 0;
  std::size_t positive = 0, negative = 0;
  for (const auto& t : map.triangles) {
    area3 += 0.5 * (map.points[t[1]] - map.points[t[0]]).cross(map.points[t[2]] - map.points[t[0]]).norm();
    const double a2 = 0.5 * cross2(map.uv[t[1]] - map.uv[t[0]], map.uv[t[2]] - map.uv[t[0]]);
    area2 += std::abs(a2), positive += a2 > 0, negative += a2 < 0;
  }
  const bool clockwise = mirror && negative == map.triangles.size();
  if (positive != map.triangles.size() && !clockwise) return false;
  const double scale = std::sqrt(area3 / area2);
  for (Eigen::Vector2d& p : map.uv) p = scale * Eigen::Vector2d(p.x(), clockwise ? -p.y() : p.y());
  return true;
}

}  // namespace

std::vector<double> arcLength(const std::vector<int>& loop, const std::vector<Vec3>& x) {
  std::vector<double> length{0};
  for (std::size_t i = 0; i < loop.size(); ++i)
    length.push_back(length.back() + (x[loop[(i + 1) % loop.size()]] - x[loop[i]]).norm());
  return length;
}

std::array<int, 4> diagonalExtremes(const std::vector<Vec3>& loop, const Vec3& centre, const Vec3& e1, const Vec3& e2) {
  double a = 0, b = 0;
  for (const Vec3& p : loop)
    a = std::max(a, std::abs((p - centre).dot(e1))), b = std::max(b, std::abs((p - centre).dot(e2)));
  std::array<int, 4> extremes{};
  const int signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (int k = 0; k < 4; ++k) {
    double best = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < loop.size(); ++i)
      if (const double s = signs[k][0] * (loop[i] - centre).dot(e1) / a + signs[k][1] * (loop[i] - centre).dot(e2) / b;
          s > best)
        best = s, extremes[k] = static_cast<int>(i);
  }
  return extremes;
}

SurfaceMap mapToPlane(const ChordalSurface& chordal, double window, MapBoundary boundary) {
  SurfaceMap map;
  map.points = chordal.vertices;
  map.triangles = chordalTriangles(chordal);
  std::vector<std::vector<int>> loops = rimLoops(map.triangles, map.points.size());
  if (loops.empty()) return {};
  auto lengthOf = [&](const std::vector<int>& loop) { return arcLength(loop, map.points).back(); };
  std::stable_sort(loops.begin(), loops.end(), [&](const auto& a, const auto& b) { return lengthOf(a) > lengthOf(b); });
  if (boundary == MapBoundary::Annulus) return mapAnnulus(std::move(map), std::move(loops));
  std::vector<int> outer = loops[0];
  if (outer.size() < 8) return {};
  int middle = -1;
  const std::array<int, 4> at =
      rimCorners(chordal, outer, arcLength(outer, map.points), window, map.sharpCorners, middle);
  if (std::adjacent_find(at.begin(), at.end()) != at.end()) return {};
  for (int k = 0; k < 4; ++k)
    if (at[k] == middle) map.sideMiddle = k;
  std::rotate(outer.begin(), outer.begin() + at[0], outer.end());  // the rim starts at a corner
  map.rim = outer;
  for (int k = 0; k < 4; ++k) map.corners[k] = at[k] - at[0];
  map.boundary = boundary;
  loops.erase(loops.begin());
  if (!placeInPlane(map, loops)) return {};
  return map;
}

SurfaceMap mapOntoSquare(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles, std::vector<int> rim,
                         const std::array<int, 4>& corners, const std::vector<std::vector<int>>& holes) {
  SurfaceMap map;
  map.points = std::move(points), map.triangles = std::move(triangles), map.rim = std::move(rim);
  map.corners = corners, map.boundary = MapBoundary::Square;
  if (corners[0] != 0 || !std::is_sorted(corners.begin(), corners.end()) ||
      std::adjacent_find(corners.begin(), corners.end()) != corners.end() ||
      corners[3] >= static_cast<int>(map.rim.size()) || !placeInPlane(map, holes))
    return {};
  return map;
}

LoopPoint loopPoint(const SurfaceMap& map, const std::vector<int>& loop, const std::vector<double>& measure, double s) {
  const std::size_t n = loop.size();
  const std::size_t i =
      std::clamp<std::size_t>(std::upper_bound(measure.begin(), measure.end(), s) - measure.begin(), 1, n) - 1;
  const double span = measure[i + 1] - measure[i];
  const double g = span > 0 ? std::clamp((s - measure[i]) / span, 0.0, 1.0) : 0.0;
  const int a = loop[i], b = loop[(i + 1) % n];
  return {(1 - g) * map.points[a] + g * map.points[b], (1 - g) * map.uv[a] + g * map.uv[b]};
}

// A cell size for the map's triangles: its extent in the plane over the square root of their count (the square's
// and the disc's extent is 2).
double mapCell(const SurfaceMap& map) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Eigen::Vector2d& p : map.uv) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double extent = map.uv.empty() ? 2.0 : (hi - lo).maxCoeff();
  return extent / std::sqrt(static_cast<double>(map.triangles.size()) + 1);
}

MapLocator::MapLocator(const SurfaceMap& map) : map_(map), triangles_(mapCell(map)) {
  for (size_t t = 0; t < map.triangles.size(); ++t) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int p : map.triangles[t]) lo = lo.cwiseMin(at(p)), hi = hi.cwiseMax(at(p));
    triangles_.insert(static_cast<int>(t), lo, hi);
    box_.push_back({lo.head<2>(), hi.head<2>()});
  }
}

MapLocator::Found MapLocator::find(const Eigen::Vector2d& uv) const {
  const Vec3 p(uv.x(), uv.y(), 0);
  auto weights = [&](int t) {
    const auto& tri = map_.triangles[t];
    return triangleWeights(at(tri[0]), at(tri[1]), at(tri[2]), p);
  };
  auto miss = [&](int t) {
    const Eigen::Vector3d w = weights(t);
    const auto& tri = map_.triangles[t];
    return (w[0] * at(tri[0]) + w[1] * at(tri[1]) + w[2] * at(tri[2]) - p).squaredNorm();
  };
  // A triangle whose box lies farther than the nearest so far cannot be nearer (its point is in its box).
  auto boxMiss = [&](int t) { return (uv - uv.cwiseMax(box_[t][0]).cwiseMin(box_[t][1])).squaredNorm(); };
  const int t = triangles_.nearest(p, [&](int id, double best) {
    const double outside = boxMiss(id);
    return outside > best ? outside : miss(id);
  });
  const Eigen::Vector3d w = weights(t);
  const auto& tri = map_.triangles[t];
  return {w[0] * map_.points[tri[0]] + w[1] * map_.points[tri[1]] + w[2] * map_.points[tri[2]], miss(t)};
}

Vec3 MapLocator::operator()(const Eigen::Vector2d& uv) const { return find(uv).point; }

Vec3 MapLocator::periodic(const Eigen::Vector2d& uv, double period) const {
  Found best = find(uv);
  for (const double shift : {-period, period})
    if (best.miss > 0)
      if (const Found other = find(uv + Eigen::Vector2d(shift, 0)); other.miss < best.miss) best = other;
  return best.point;
}

SurfaceMap unfoldConformally(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles) {
  SurfaceMap map;
  if (triangles.empty() || !orientAlike(triangles)) return map;
  const int n = static_cast<int>(points.size());
  // Two points pinned: the first triangle's first corner at 0, the point farthest from it on the x axis.
  const int p0 = triangles[0][0];
  int p1 = p0;
  for (int i = 0; i < n; ++i)
    if ((points[i] - points[p0]).squaredNorm() > (points[p1] - points[p0]).squaredNorm()) p1 = i;
  if (p1 == p0) return map;
  std::vector<Eigen::Vector2d> uv(n, Eigen::Vector2d::Zero());
  uv[p1] = {(points[p1] - points[p0]).norm(), 0};
  // Unknowns u_i, v_i (2 i, 2 i + 1) of the free points; per triangle the real and imaginary parts of
  // sum_j W_j (u_j + i v_j) (Eq. 5) are two rows of the least-squares system A x = b.
  std::vector<int> column(n, -1);
  int free = 0;
  for (int i = 0; i < n; ++i)
    if (i != p0 && i != p1) column[i] = free++;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * static_cast<long>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto w = conformalWeights(points, triangles[t]);
    const int re = static_cast<int>(2 * t), im = re + 1;
    for (int j = 0; j < 3; ++j) {
      const int i = triangles[t][j];
      const double a = w[j].real(), c = w[j].imag();  // W U = (a u - c v) + i (c u + a v)
      if (column[i] < 0) {
        b[re] -= a * uv[i].x() - c * uv[i].y(), b[im] -= c * uv[i].x() + a * uv[i].y();
        continue;
      }
      entries.emplace_back(re, 2 * column[i], a), entries.emplace_back(re, 2 * column[i] + 1, -c);
      entries.emplace_back(im, 2 * column[i], c), entries.emplace_back(im, 2 * column[i] + 1, a);
    }
  }
  Eigen::SparseMatrix<double> a(2 * static_cast<long>(triangles.size()), 2 * free);
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> normal = Eigen::SparseMatrix<double>(a.transpose()) * a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return map;
  const Eigen::VectorXd x = solver.solve(a.transpose() * b);
  if (solver.info() != Eigen::Success || !x.allFinite()) return map;
  for (int i = 0; i < n; ++i)
    if (column[i] >= 0) uv[i] = {x[2 * column[i]], x[2 * column[i] + 1]};
  map.points = std::move(points), map.triangles = std::move(triangles), map.uv = std::move(uv);
  if (!counterClockwiseToScale(map, /*mirror=*/false)) return {};
  return map;
}

SurfaceMap unfoldRing(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles) {
  SurfaceMap map;
  if (triangles.empty() || !orientAlike(triangles)) return map;
  map.points = std::move(points), map.triangles = std::move(triangles);
  std::vector<std::vector<int>> loops = rimLoops(map.triangles, map.points.size());
  if (loops.size() != 2) return {};
  if (arcLength(loops[1], map.points).back() > arcLength(loops[0], map.points).back()) std::swap(loops[0], loops[1]);
  map = mapAnnulus(std::move(map), std::move(loops));
  if (map.empty()) return map;
  for (Eigen::Vector2d& p : map.uv) p = std::exp(p.y()) * Eigen::Vector2d(std::cos(p.x()), std::sin(p.x()));
  if (!counterClockwiseToScale(map, /*mirror=*/true)) return {};
  return map;
}

}  // namespace hexlayer
