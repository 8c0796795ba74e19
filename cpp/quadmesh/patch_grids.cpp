#include "quadmesh/patch_grids.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <type_traits>

#include "core/threads.hpp"
#include "core/union_find.hpp"
#include "quadmesh/quad_smoothing.hpp"

namespace hexlayer {
namespace {

const double kSideTurn = 45 * M_PI / 180;     // a curve turning more within a quad is cut there: a patch's corner
const double kMaxCorner = 135 * M_PI / 180;   // a patch's corner turns at most this much (and at least kSideTurn)
constexpr double kCornerWindow = 3;           // quads: a corner's turn is measured over this length of its sides
constexpr std::size_t kMostCorners = 6;       // a patch's loop with more corners is not cut into four sides
const double kMaxSideKink = 80 * M_PI / 180;  // the largest turn a corner left inside a side may make

// A chain of chordal vertices along a patch's rim, from a corner to a corner, with the patches on either side.
struct Curve {
  std::vector<int> vertices;
  std::array<int, 2> patches;
  // [0] and [1]: how many vertices after its first and before its last its path cuts across (a rim piece shorter
  // than a quad joined to it there: the rim's step round the end of a bend, which a path along the vertices would
  // walk back and forth)
  std::array<std::size_t, 2> across{0, 0};
  // At its first and last vertex, the quads over which the turn into the curve before and after it is measured where
  // that is more than kCornerWindow: a rounded corner of a larger radius cut there (cutAtRoundCorners); else 0.
  std::array<double, 2> cornerWindow{0, 0};
};

// A chain's points.
std::vector<Vec3> pointsOf(const std::vector<int>& chain, const std::vector<Vec3>& x) {
  std::vector<Vec3> points;
  points.reserve(chain.size());
  for (int v : chain) points.push_back(x[v]);
  return points;
}

// A curve cut at its vertices `at` (positions inside it, ascending): the pieces in order, each sharing its end
// vertex with the next; the first and last keep the curve's steps cut across at its ends.
std::vector<Curve> piecesAt(const Curve& whole, const std::vector<std::size_t>& at) {
  std::vector<Curve> pieces;
  std::size_t from = 0;
  for (std::size_t to : at) {
    pieces.push_back({std::vector<int>(whole.vertices.begin() + from, whole.vertices.begin() + to + 1),
                      whole.patches,
                      {from == 0 ? whole.across[0] : 0, 0},
                      {from == 0 ? whole.cornerWindow[0] : 0, 0}});
    from = to;
  }
  pieces.push_back({std::vector<int>(whole.vertices.begin() + from, whole.vertices.end()),
                    whole.patches,
                    {from == 0 ? whole.across[0] : 0, whole.across[1]},
                    {from == 0 ? whole.cornerWindow[0] : 0, whole.cornerWindow[1]}});
  return pieces;
}

// A rim curve's path: along its vertices, across the steps at its ends (Curve::across).
std::vector<Vec3> rimPath(const Curve& c, const std::vector<Vec3>& x) {
  std::vector<int> chain{c.vertices.front()};
  const std::size_t n = c.vertices.size();
  for (std::size_t i = 1 + c.across[0]; i + 1 + c.across[1] < n; ++i) chain.push_back(c.vertices[i]);
  chain.push_back(c.vertices.back());
  return pointsOf(chain, x);
}

// Arc length along a path from its first point: up to point i at [i].
std::vector<double> lengthAlong(const std::vector<Vec3>& path) {
  std::vector<double> length(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i) length[i] = length[i - 1] + (path[i] - path[i - 1]).norm();
  return length;
}

// The point at arc length s along a path (clamped to its ends). [in] length: lengthAlong's.
Vec3 pointAt(const std::vector<Vec3>& path, const std::vector<double>& length, double s) {
  if (s <= 0) return path.front();
  const std::size_t i = static_cast<std::size_t>(std::lower_bound(length.begin(), length.end(), s) - length.begin());
  if (i >= path.size()) return path.back();
  const double step = length[i] - length[i - 1];
  const double t = step > 0 ? (s - length[i - 1]) / step : 0.0;
  return (1 - t) * path[i - 1] + t * path[i];
}

// The angle between two directions (0 if either is zero).
double angleBetween(const Vec3& a, const Vec3& b) {
  if (a.norm() == 0 || b.norm() == 0) return 0;
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

// How much a path turns at its point i: the angle from its direction over `window` behind to over `window` ahead.
double turnAt(const std::vector<Vec3>& path, const std::vector<double>& length, std::size_t i, double window) {
  const Vec3 back = pointAt(path, length, length[i] - window), ahead = pointAt(path, length, length[i] + window);
  return angleBetween(path[i] - back, ahead - path[i]);
}

// The positions in a path (inside it, from `first` to `last`) where it turns more than kSideTurn over `window`
// either side, the most within the window either side, at least `endGap` from its ends (a turn nearer an end is
// the curve's end turning: the rim's chord across a corner whose crease ends there). [in] path; [in] window, endGap:
// lengths; [in] first, last: the range of positions looked at.
std::vector<std::size_t> sharpTurns(const std::vector<Vec3>& path, double window, double endGap, std::size_t first,
                                    std::size_t last) {
  const std::vector<double> length = lengthAlong(path);
  std::vector<double> turn(path.size(), 0.0);
  for (std::size_t i = 1; i + 1 < path.size(); ++i) turn[i] = turnAt(path, length, i, window);
  std::vector<std::size_t> peaks;
  for (std::size_t i = first; i <= last; ++i) {
    if (turn[i] <= kSideTurn || std::min(length[i], length.back() - length[i]) < endGap) continue;
    bool peak = true;  // the most within the window before (strictly) and after
    for (std::size_t j = i; peak && j-- > 1 && length[i] - length[j] < window;) peak = turn[j] < turn[i];
    for (std::size_t j = i + 1; peak && j + 1 < path.size() && length[j] - length[i] < window; ++j)
      peak = turn[j] <= turn[i];
    if (peak) peaks.push_back(i);
  }
  return peaks;
}

// The patches' curves, those along the rim cut at their sharp turns (round a corner of the part's outline; a loop,
// from a vertex back to it, kept whole if it has none). [in] topology, x; [in] size: a quad's length.
std::vector<Curve> cutAtSharpTurns(const PatchTopology& topology, const std::vector<Vec3>& x, double size) {
  std::vector<Curve> cut;
  for (const PatchCurve& c : topology.curves) {
    std::vector<int> chain = c.vertices;
    if (c.patches[0] >= 0) {  // a crease zigzags along the facets across it: only the rim's corners are cut
      cut.push_back({chain, c.patches});
      continue;
    }
    std::size_t first = 1, last = chain.size() >= 2 ? chain.size() - 2 : 0;
    const bool loop = chain.size() > 2 && chain.front() == chain.back();
    if (loop) {  // three turns of it, the middle one looked at: the turns near its ends see past them
      const std::size_t n = chain.size() - 1;
      std::vector<int> thrice;
      for (int round = 0; round < 3; ++round) thrice.insert(thrice.end(), chain.begin(), chain.end() - 1);
      thrice.push_back(chain.front());
      const std::vector<std::size_t> peaks = sharpTurns(pointsOf(thrice, x), size, 0.5 * size, n, 2 * n - 1);
      if (peaks.empty()) {
        cut.push_back({chain, c.patches});
        continue;
      }
      chain.assign(thrice.begin() + peaks.front(), thrice.begin() + peaks.front() + n + 1);  // from its first turn
      first = 1, last = n - 1;
    }
    for (Curve& piece : piecesAt({chain, c.patches}, sharpTurns(pointsOf(chain, x), size, 0.5 * size, first, last)))
      cut.push_back(std::move(piece));
  }
  return cut;
}

// A face whose loop does not turn at four corners may have rounded ones along the rim (a foot's corners rounded by
// more than a quad, a wall's top corner rounded R10 at 2 mm quads): its rim curves are cut where they turn by more
// than kSideTurn over this many quads either side, the first that gives the face four corners (the turn at a corner
// so cut is measured over as many quads: Curve::cornerWindow).
constexpr double kRoundCorners[] = {kCornerWindow, 2 * kCornerWindow};

// The rim curves of a patch cut at their rounded corners (over `window` quads; not within a quad of their ends, not
// the holes' loops), the pieces after the first added at the end. [in,out] curves, paths, ofPatch: the patch's
// curves; [in] x; [in] size: a quad's length; [in] window. Returns whether any was cut.
bool cutAtRoundCorners(std::vector<Curve>& curves, std::vector<std::vector<Vec3>>& paths, std::vector<int>& ofPatch,
                       const std::vector<Vec3>& x, double size, double window) {
  bool cut = false;
  for (const int c : std::vector<int>(ofPatch)) {
    if (curves[c].patches[0] >= 0 || curves[c].vertices.front() == curves[c].vertices.back()) continue;
    const std::vector<Vec3>& path = paths[c];  // its point i is vertex i + across[0] inside it
    if (path.size() < 3) continue;
    std::vector<std::size_t> at = sharpTurns(path, window * size, size, 1, path.size() - 2);
    if (at.empty()) continue;
    for (std::size_t& i : at) i += curves[c].across[0];
    std::vector<Curve> pieces = piecesAt(curves[c], at);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (window > kCornerWindow && k > 0) pieces[k].cornerWindow[0] = window;
      if (window > kCornerWindow && k + 1 < pieces.size()) pieces[k].cornerWindow[1] = window;
      const int to = k == 0 ? c : static_cast<int>(curves.size());
      if (k > 0) ofPatch.push_back(to), curves.emplace_back(), paths.emplace_back();
      paths[to] = rimPath(pieces[k], x), curves[to] = std::move(pieces[k]);
    }
    cut = true;
  }
  return cut;
}

// A rim curve shorter than this many quads joins the rim curve of its patch it meets (the rim's chord across a
// corner of the part, where the crease between two walls reaches the rim a facet or two away from the corner: 1.5 mm
// on a sharply bent hat section of 2 mm sheet).
constexpr double kShortRim = 1.0;

// Rim curves shorter than kShortRim quads joined to the rim curve of the same patch they meet, until none is.
// [in,out] curves; [in] x; [in] size: a quad's length.
void joinShortRimCurves(std::vector<Curve>& curves, const std::vector<Vec3>& x, double size) {
  auto length = [&](const Curve& c) { return lengthAlong(pointsOf(c.vertices, x)).back(); };
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t c = 0; c < curves.size() && !joined; ++c) {
      if (curves[c].patches[0] >= 0 || length(curves[c]) >= kShortRim * size) continue;
      for (std::size_t d = 0; d < curves.size() && !joined; ++d) {
        if (d == c || curves[d].patches != curves[c].patches) continue;
        std::vector<int>& a = curves[d].vertices;
        std::vector<int> b = curves[c].vertices;
        if (a.front() == a.back() || b.front() == b.back()) continue;
        if (a.back() == b.back() || a.front() == b.front()) std::reverse(b.begin(), b.end());
        if (a.back() == b.front())
          a.insert(a.end(), b.begin() + 1, b.end()), curves[d].across[1] = b.size() - 1;
        else if (a.front() == b.back())
          a.insert(a.begin(), b.begin(), b.end() - 1), curves[d].across[0] = b.size() - 1;
        else
          continue;
        curves.erase(curves.begin() + c);
        joined = true;
      }
    }
  }
}

// A curve as a piece of a patch's loop: forward (from its first vertex) or backward.
struct SideOf {
  int curve;
  bool forward;
};

// A face's side: the curves along it from a corner to the next, in order (more than one where a curve ends on it
// flat: a flange's bend ending on the side of a foot that runs on past it).
using Side = std::vector<SideOf>;

// A face of the patch grid: the four sides of its outer loop, and its holes' loops of vertices (rim curves only:
// windows in a wall, holes in a flange).
struct Face {
  std::array<Side, 4> sides;
  std::vector<std::vector<int>> holes;
};

// A group's curves in order round their loop, from its first curve forward; nothing if they do not make one loop
// (or it touches itself at a vertex). [in] curves; [in] group: the loop's curves, ascending.
std::optional<Side> loopOf(const std::vector<Curve>& curves, const std::vector<int>& group) {
  Side loop{{group[0], true}};
  std::set<int> used{group[0]};
  auto endOf = [&](const SideOf& s) {
    return s.forward ? curves[s.curve].vertices.back() : curves[s.curve].vertices.front();
  };
  while (loop.size() < group.size()) {
    const int at = endOf(loop.back());
    std::optional<SideOf> next;
    for (int c : group) {
      if (used.count(c)) continue;
      for (const bool forward : {true, false}) {
        const int start = forward ? curves[c].vertices.front() : curves[c].vertices.back();
        if (start != at) continue;
        if (next) return std::nullopt;  // the patch touches itself at the corner
        next = SideOf{c, forward};
      }
    }
    if (!next) return std::nullopt;
    loop.push_back(*next), used.insert(next->curve);
  }
  if (endOf(loop.back()) != curves[loop.front().curve].vertices.front()) return std::nullopt;
  return loop;
}

// What a side's curves have along them (their paths, nodes, vertices: perCurve(curve)) end to end in the side's
// order, each junction once.
template <typename PerCurve>
auto endToEnd(const Side& side, PerCurve perCurve) {
  std::decay_t<decltype(perCurve(0))> along;
  for (const SideOf& s : side) {
    auto piece = perCurve(s.curve);
    if (!s.forward) std::reverse(piece.begin(), piece.end());
    along.insert(along.end(), piece.begin() + (along.empty() ? 0 : 1), piece.end());
  }
  return along;
}

// A side's path in the patch's order round it.
std::vector<Vec3> sidePath(const std::vector<std::vector<Vec3>>& paths, const Side& side) {
  return endToEnd(side, [&](int c) -> const std::vector<Vec3>& { return paths[c]; });
}

// The directions of a path and the next where they meet, over a few quads (half the shorter path at most): the
// creases' ends wander by a facet. [in] in, out: the paths, out starting where in ends; [in] size; [in] quads: how
// many.
std::pair<Vec3, Vec3> directionsInto(const std::vector<Vec3>& in, const std::vector<Vec3>& out, const SizeField& size,
                                     double quads = kCornerWindow) {
  const std::vector<double> inLength = lengthAlong(in), outLength = lengthAlong(out);
  const Vec3& corner = out.front();
  const double window = std::min(quads * size(corner), 0.5 * std::min(inLength.back(), outLength.back()));
  return {corner - pointAt(in, inLength, inLength.back() - window), pointAt(out, outLength, window) - corner};
}

// How many quads the turn into a curve at its start in the patch's order is measured over (Curve::cornerWindow).
double cornerWindow(const std::vector<Curve>& curves, const SideOf& piece) {
  return std::max(kCornerWindow, curves[piece.curve].cornerWindow[piece.forward ? 0 : 1]);
}

// How much a path turns into the next where they meet (directionsInto). [in] in, out; [in] size, quads.
double turnInto(const std::vector<Vec3>& in, const std::vector<Vec3>& out, const SizeField& size, double quads) {
  const auto [before, after] = directionsInto(in, out, size, quads);
  return angleBetween(before, after);
}

// Whether the sides' paths turn into one another by kSideTurn to kMaxCorner at each corner.
bool squareCorners(const std::vector<Curve>& curves, const std::vector<std::vector<Vec3>>& paths,
                   const std::array<Side, 4>& sides, const SizeField& size) {
  for (int k = 0; k < 4; ++k) {
    const Side& next = sides[(k + 1) % 4];
    const double turn = turnInto(sidePath(paths, sides[k]), sidePath(paths, next), size, cornerWindow(curves, next[0]));
    if (turn < kSideTurn || turn > kMaxCorner) return false;
  }
  return true;
}

// The loop's four sides starting at its pieces `corners` (ascending). [in] loop, corners.
std::array<Side, 4> sidesFrom(const Side& loop, const std::array<std::size_t, 4>& corners) {
  std::array<Side, 4> sides;
  for (int k = 0; k < 4; ++k)
    for (std::size_t i = corners[k]; i != (k == 3 ? corners[0] + loop.size() : corners[k + 1]); ++i)
      sides[k].push_back(loop[i % loop.size()]);
  return sides;
}

// A loop of curves cut into four sides at its corners: a loop of four curves at their ends; a longer loop where its
// curves turn into one another by kSideTurn or more, or where a rounded corner was cut (Curve::cornerWindow), the
// others going on flat along a side. With PatchSides::KinksInSides, a loop with up to kMostCorners such corners keeps
// the four whose sides turn square into one another (squareCorners) and leave the gentlest turn inside a side (at
// most kMaxSideKink; on a tie the first in the loop's order), a rounded corner's cut always kept. [in] loop, curves,
// paths, size, kinks. Nothing if that does not give four corners.
std::optional<std::array<Side, 4>> sidesOf(const Side& loop, const std::vector<Curve>& curves,
                                           const std::vector<std::vector<Vec3>>& paths, const SizeField& size,
                                           PatchSides kinks) {
  std::vector<std::size_t> corners;  // the loop's pieces that start a side (a rounded corner's cut does)
  std::vector<double> turn;          // the turn into each (infinite at a rounded corner's cut: it stays a corner)
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const bool rounded = cornerWindow(curves, loop[i]) > kCornerWindow;
    const double t = loop.size() == 4 || rounded
                         ? std::numeric_limits<double>::infinity()
                         : turnInto(sidePath(paths, {loop[(i + loop.size() - 1) % loop.size()]}),
                                    sidePath(paths, {loop[i]}), size, kCornerWindow);
    if (t >= kSideTurn) corners.push_back(i), turn.push_back(t);
  }
  if (corners.size() == 4) return sidesFrom(loop, {corners[0], corners[1], corners[2], corners[3]});
  if (kinks != PatchSides::KinksInSides || corners.size() < 4 || corners.size() > kMostCorners) return std::nullopt;
  std::optional<std::array<Side, 4>> best;
  double gentlest = kMaxSideKink;
  const std::size_t m = corners.size();
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c)
        for (std::size_t d = c + 1; d < m; ++d) {
          double kink = 0;  // the largest turn left inside a side
          for (std::size_t k = 0; k < m; ++k)
            if (k != a && k != b && k != c && k != d) kink = std::max(kink, turn[k]);
          if (!(kink <= gentlest) || (best && kink == gentlest)) continue;
          const std::array<Side, 4> sides = sidesFrom(loop, {corners[a], corners[b], corners[c], corners[d]});
          if (squareCorners(curves, paths, sides, size)) best = sides, gentlest = kink;
        }
  return best;
}

// The curves of a group (that follow one another round a loop) joined into their loop of vertices, the first not
// repeated at the end; empty if they do not make one loop. [in] curves; [in] group: curves of the loop.
std::vector<int> joinedLoop(const std::vector<Curve>& curves, const std::vector<int>& group) {
  const std::optional<Side> pieces = loopOf(curves, group);
  if (!pieces) return {};
  std::vector<int> loop = endToEnd(*pieces, [&](int c) -> const std::vector<int>& { return curves[c].vertices; });
  if (loop.size() < 4 || loop.front() != loop.back()) return {};
  loop.pop_back();
  return loop;
}

// A patch's curves grouped into loops by their ends: the loop with creases (or its only loop) outside, the others
// holes along the rim. Nothing if two loops have creases (a crease round a hole: a boss's foot).
struct PatchLoops {
  std::vector<int> outer;
  std::vector<std::vector<int>> holes;
};

std::optional<PatchLoops> loopsOf(const std::vector<Curve>& curves, const std::vector<int>& ofPatch) {
  UnionFind together(static_cast<int>(ofPatch.size()));
  std::map<int, int> atEnd;  // vertex -> a curve (its place in ofPatch) ending there
  for (std::size_t i = 0; i < ofPatch.size(); ++i)
    for (int v : {curves[ofPatch[i]].vertices.front(), curves[ofPatch[i]].vertices.back()}) {
      const auto [it, added] = atEnd.emplace(v, static_cast<int>(i));
      if (!added) together.unite(it->second, static_cast<int>(i));
    }
  std::map<int, std::vector<int>> groups;  // by their root
  for (std::size_t i = 0; i < ofPatch.size(); ++i) groups[together.find(static_cast<int>(i))].push_back(ofPatch[i]);
  PatchLoops loops;
  for (const auto& [root, group] : groups) {
    const bool crease = std::any_of(group.begin(), group.end(), [&](int c) { return curves[c].patches[0] >= 0; });
    if (crease && !loops.outer.empty()) return std::nullopt;
    if (crease || groups.size() == 1)
      loops.outer = group;
    else
      loops.holes.push_back(group);
  }
  if (loops.outer.empty()) return std::nullopt;
  return loops;
}

// A patch as a face: its outer loop four sides round it, its other loops holes (loopsOf). [in] curves, paths;
// [in] ofPatch: the patch's curves, ascending; [in] size, kinks: sidesOf's. Nothing if loopsOf gives nothing or the
// outer loop is not four-sided with square corners.
std::optional<Face> faceOf(const std::vector<Curve>& curves, const std::vector<std::vector<Vec3>>& paths,
                           const std::vector<int>& ofPatch, const SizeField& size, PatchSides kinks) {
  const std::optional<PatchLoops> loops = loopsOf(curves, ofPatch);
  const std::optional<Side> loop = loops ? loopOf(curves, loops->outer) : std::nullopt;
  const std::optional<std::array<Side, 4>> sides = loop ? sidesOf(*loop, curves, paths, size, kinks) : std::nullopt;
  if (!sides || !squareCorners(curves, paths, *sides, size)) return std::nullopt;
  Face face{*sides, {}};
  for (const std::vector<int>& hole : loops->holes) {
    face.holes.push_back(joinedLoop(curves, hole));
    if (face.holes.back().empty()) return std::nullopt;
  }
  return face;
}

// Next to a crease the rows of quads along it are this much denser (fading over a quad's length away from it), so
// that the hexes round a bend with a sharp inside edge cut its outside round and its inside corner by half as much
// (the volume they leave out grows with the first row's width): box_sharp_inside's -1.8 % -> -1.2 %.
constexpr double kCreaseGrading = 2;
constexpr int kMeasureSamples = 256;  // points along a curve where its measure is summed

// Where each crease ends on another crease away from the rim (a box's floor edge where a wall's corner edge ends on
// it; a wall's corner edge at the floor): [0] its first vertex, [1] its last. The rim's curves are left even: rows
// crowding where a crease reaches a rounded rim fold the rim's hexes there. [in] curves.
std::vector<std::array<bool, 2>> endsOnCreases(const std::vector<Curve>& curves) {
  std::map<int, int> creaseEnds;  // vertex -> creases ending there
  std::set<int> onRim;            // vertices where a rim curve ends
  for (const Curve& c : curves)
    for (int v : {c.vertices.front(), c.vertices.back()}) {
      if (c.patches[0] >= 0) ++creaseEnds[v];
      if (c.patches[0] < 0) onRim.insert(v);
    }
  std::vector<std::array<bool, 2>> ends;
  for (const Curve& c : curves) {
    auto others = [&](int v) {
      const auto it = creaseEnds.find(v);
      return c.patches[0] >= 0 && !onRim.count(v) && it != creaseEnds.end() && it->second > 1;
    };
    ends.push_back({others(c.vertices.front()), others(c.vertices.back())});
  }
  return ends;
}

// A curve's measure: the quads the target size needs along it, denser by up to kCreaseGrading towards the ends
// on creases if `graded`, summed at kMeasureSamples + 1 points evenly spaced by arc length (§6.1's sizes along the
// curve).
struct CurveMeasure {
  std::vector<double> at;  // at[i]: up to sample i (at i / kMeasureSamples of the length)
  double length = 0;
};

CurveMeasure curveMeasure(const std::vector<Vec3>& path, const std::array<bool, 2>& ends, const SizeField& size,
                          double window, bool graded) {
  const std::vector<double> length = lengthAlong(path);
  CurveMeasure m;
  m.length = length.back();
  auto density = [&](double s) {
    const Vec3 p = pointAt(path, length, s);
    double d = 1;
    if (graded && ends[0]) d += (kCreaseGrading - 1) * std::exp(-s / window);
    if (graded && ends[1]) d += (kCreaseGrading - 1) * std::exp(-(m.length - s) / window);
    return d / size(p);
  };
  m.at.assign(kMeasureSamples + 1, 0.0);
  const double step = m.length / kMeasureSamples;
  double before = density(0);
  for (int i = 1; i <= kMeasureSamples; ++i) {
    const double here = density(i * step);
    m.at[i] = m.at[i - 1] + 0.5 * (before + here) * step;
    before = here;
  }
  return m;
}

// Segments a curve needs (at least one). [in] m: its measure.
int segmentsNeeded(const CurveMeasure& m) { return std::max(1, static_cast<int>(std::lround(m.at.back()))); }

// The arc length at which a curve's measure reaches share t of its whole. [in] m; [in] t: in [0, 1].
double arcAtShare(const CurveMeasure& m, double t) {
  const double target = t * m.at.back();
  const auto it = std::lower_bound(m.at.begin(), m.at.end(), target);
  if (it == m.at.begin()) return 0;
  if (it == m.at.end()) return m.length;
  const std::size_t i = static_cast<std::size_t>(it - m.at.begin());
  const double span = m.at[i] - m.at[i - 1];
  const double f = span > 0 ? (target - m.at[i - 1]) / span : 0.0;
  return (static_cast<double>(i - 1) + f) * m.length / kMeasureSamples;
}

// A patch's triangles' Euler characteristic V - E + F (a disc: 1, with h holes 1 - h), and their summed normal
// (twice their vector area).
struct PatchShape {
  long euler = 0;
  Vec3 normal = Vec3::Zero();
};

// Every patch's shape, in one pass over the triangles. [in] triangles, patch; [in] patches: their count; [in] x.
std::vector<PatchShape> patchShapes(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch,
                                    int patches, const std::vector<Vec3>& x) {
  std::vector<std::set<int>> vertices(patches);
  std::vector<std::set<std::pair<int, int>>> edges(patches);
  std::vector<long> faces(patches, 0);
  std::vector<PatchShape> shapes(patches);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const int p = patch[t];
    const auto& c = triangles[t];
    ++faces[p];
    for (int k = 0; k < 3; ++k) vertices[p].insert(c[k]), edges[p].emplace(std::minmax(c[k], c[(k + 1) % 3]));
    shapes[p].normal += (x[c[1]] - x[c[0]]).cross(x[c[2]] - x[c[0]]);
  }
  for (int p = 0; p < patches; ++p)
    shapes[p].euler = static_cast<long>(vertices[p].size()) - static_cast<long>(edges[p].size()) + faces[p];
  return shapes;
}

constexpr int kAveraged = 4;         // points each side of a crease's point in its moving average ...
constexpr int kAveragingPasses = 2;  // ... made this many times

// A crease's path: its vertices zigzag across the bend (a facet edge on the one face, the next on the other), a
// moving average over a quad's length either side (shorter near its ends, which stay) runs along the middle of the
// bend. [in] chain, x; [in] window: the quad's length.
std::vector<Vec3> creasePath(const std::vector<int>& chain, const std::vector<Vec3>& x, double window) {
  std::vector<Vec3> path = pointsOf(chain, x);
  for (int pass = 0; pass < kAveragingPasses; ++pass) {
    const std::vector<double> length = lengthAlong(path);
    std::vector<Vec3> averaged = path;
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
      const double reach = std::min({window, length[i], length.back() - length[i]});
      Vec3 sum = Vec3::Zero();
      for (int k = -kAveraged; k <= kAveraged; ++k) sum += pointAt(path, length, length[i] + reach * k / kAveraged);
      averaged[i] = sum / (2 * kAveraged + 1);
    }
    path = std::move(averaged);
  }
  return path;
}

// Each curve's path: along its vertices on the rim, a crease's creasePath. [in] curves, x; [in] window: a quad.
std::vector<std::vector<Vec3>> curvePaths(const std::vector<Curve>& curves, const std::vector<Vec3>& x, double window) {
  std::vector<std::vector<Vec3>> paths;
  for (const Curve& c : curves) {
    if (c.patches[0] >= 0) {
      paths.push_back(creasePath(c.vertices, x, window));
      continue;
    }
    paths.push_back(rimPath(c, x));
  }
  return paths;
}

// The nodes of each curve: its end vertices' nodes (shared by the curves meeting there) and segments[curve] - 1
// between them along its path, at even shares of its measure, and where each lies along it (its share of the path's
// length). [in] curves, paths, measures, segments, x; [in,out] grid: nodes added.
struct CurveNodes {
  std::vector<std::vector<int>> nodes;
  std::vector<std::vector<double>> along;
};

CurveNodes curveNodes(const std::vector<Curve>& curves, const std::vector<std::vector<Vec3>>& paths,
                      const std::vector<CurveMeasure>& measures, const std::vector<int>& segments,
                      const std::vector<Vec3>& x, BlockGrid& grid) {
  std::map<int, int> cornerNode;
  auto corner = [&](int v) {
    const auto [it, added] = cornerNode.emplace(v, static_cast<int>(grid.nodes.size()));
    if (added) grid.nodes.push_back(x[v]);
    return it->second;
  };
  CurveNodes made{std::vector<std::vector<int>>(curves.size()), std::vector<std::vector<double>>(curves.size())};
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const std::vector<double> length = lengthAlong(paths[c]);
    const int n = segments[c];
    std::vector<int>& nodes = made.nodes[c];
    nodes.push_back(corner(curves[c].vertices.front()));
    made.along[c].push_back(0);
    for (int k = 1; k < n; ++k) {
      const double s = arcAtShare(measures[c], static_cast<double>(k) / n);
      nodes.push_back(static_cast<int>(grid.nodes.size()));
      grid.nodes.push_back(pointAt(paths[c], length, s));
      made.along[c].push_back(length.back() > 0 ? s / length.back() : 0.0);
    }
    nodes.push_back(corner(curves[c].vertices.back()));
    made.along[c].push_back(1);
  }
  return made;
}

// A side's nodes in its order. [in] side; [in] nodes: per curve.
std::vector<int> sideNodes(const Side& side, const std::vector<std::vector<int>>& nodes) {
  return endToEnd(side, [&](int c) -> const std::vector<int>& { return nodes[c]; });
}

// One patch's grid: its sides' nodes on its rim, the nodes inside by transfinite interpolation between them (a
// bilinearly blended Coons patch: a plane's grid exactly, a cylinder's between its arcs), put on the chordal surface
// with the others when the grid is ranked. [in] sides: the nodes of the patch's sides (sideNodes); [in] normal:
// the patch's (its quads turn counter-clockwise round it). [in,out] grid: nodes and quads added. Returns the quads
// whose normal points against the patch's (folded: a graded grid on a patch whose sides are graded unlike).
std::size_t addPatchGrid(const std::array<std::vector<int>, 4>& sides, const Vec3& normal, BlockGrid& grid) {
  const int n0 = static_cast<int>(sides[0].size()) - 1;
  const int n1 = static_cast<int>(sides[1].size()) - 1;
  std::vector<int> node((n0 + 1) * (n1 + 1));
  auto at = [&](int i, int j) -> int& { return node[j * (n0 + 1) + i]; };
  for (int i = 0; i <= n0; ++i) at(i, 0) = sides[0][i], at(i, n1) = sides[2][n0 - i];
  for (int j = 0; j <= n1; ++j) at(n0, j) = sides[1][j], at(0, j) = sides[3][n1 - j];
  auto p = [&](int i, int j) { return grid.nodes[at(i, j)]; };
  for (int j = 1; j < n1; ++j)
    for (int i = 1; i < n0; ++i) {
      const double u = static_cast<double>(i) / n0, v = static_cast<double>(j) / n1;
      const Vec3 blend =
          (1 - v) * p(i, 0) + v * p(i, n1) + (1 - u) * p(0, j) + u * p(n0, j) -
          ((1 - u) * (1 - v) * p(0, 0) + u * (1 - v) * p(n0, 0) + (1 - u) * v * p(0, n1) + u * v * p(n0, n1));
      at(i, j) = static_cast<int>(grid.nodes.size());
      grid.nodes.push_back(blend);
    }
  Vec3 turn = Vec3::Zero();  // the grid's summed normal as made
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) turn += (p(i + 1, j + 1) - p(i, j)).cross(p(i, j + 1) - p(i + 1, j));
  std::size_t folded = 0;
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      std::array<int, 4> q{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      if (turn.dot(normal) < 0) std::swap(q[1], q[3]);
      const Vec3 n = (grid.nodes[q[2]] - grid.nodes[q[0]]).cross(grid.nodes[q[3]] - grid.nodes[q[1]]);
      folded += n.dot(normal) <= 0;
      grid.quads.push_back(q);
    }
  ++grid.blocks;
  return folded;
}

// The quads of a face's grid added with its nodes inside (its rim nodes given), turned counter-clockwise round its
// normal. [in] local: the face's grid, its first `rim` nodes those of `rimNodes`; [in] normal: the face's; [in,out]
// grid. Returns the quads whose normal points against the face's.
std::size_t addFaceQuads(const BlockGrid& local, const std::vector<int>& rimNodes, const Vec3& normal,
                         BlockGrid& grid) {
  std::vector<int> node = rimNodes;
  for (std::size_t v = rimNodes.size(); v < local.nodes.size(); ++v)
    node.push_back(static_cast<int>(grid.nodes.size())), grid.nodes.push_back(local.nodes[v]);
  auto quadNormal = [&](const std::array<int, 4>& q) {
    return (grid.nodes[q[2]] - grid.nodes[q[0]]).cross(grid.nodes[q[3]] - grid.nodes[q[1]]);
  };
  std::vector<std::array<int, 4>> quads;
  Vec3 turn = Vec3::Zero();
  for (const auto& q : local.quads) {
    quads.push_back({node[q[0]], node[q[1]], node[q[2]], node[q[3]]});
    turn += quadNormal(quads.back());
  }
  std::size_t folded = 0;
  for (auto& q : quads) {
    if (turn.dot(normal) < 0) std::swap(q[1], q[3]);
    folded += quadNormal(q).dot(normal) <= 0;
    grid.quads.push_back(q);
  }
  grid.blocks += local.blocks;
  return folded;
}

// A face with holes: its triangles mapped onto the square at its four corners (mapOntoSquare), holedGrid's pocket of
// four blocks round each hole, its rim nodes its sides' (where they lie along the sides, placed on the square's
// sides as the map places the rim). [in] face, made: the curves' nodes; [in] facets: the face's triangles; [in] x,
// size, normal; [in,out] grid. Returns the quads folded against the face (addPatchGrid's), nothing if neither
// holedGrid nor, where the pockets meet, sharedGrid gives a grid.
std::optional<std::size_t> addHoledFace(const Face& face, const std::vector<Curve>& curves, const CurveNodes& made,
                                        const std::vector<std::array<int, 3>>& facets, const std::vector<Vec3>& x,
                                        const SizeField& size, const Vec3& normal, BlockGrid& grid) {
  std::map<int, int> local;  // chordal vertex -> the face's point
  std::vector<Vec3> points;
  auto pointOf = [&](int v) {
    const auto [it, added] = local.emplace(v, static_cast<int>(points.size()));
    if (added) points.push_back(x[v]);
    return it->second;
  };
  std::vector<std::array<int, 3>> triangles;
  for (const auto& t : facets) triangles.push_back({pointOf(t[0]), pointOf(t[1]), pointOf(t[2])});
  std::vector<int> rim;
  std::array<int, 4> corners{};
  std::vector<std::vector<std::size_t>> starts(4);  // per side, where each of its curves starts in rim
  for (int k = 0; k < 4; ++k) {
    corners[k] = static_cast<int>(rim.size());
    for (const SideOf& piece : face.sides[k]) {
      std::vector<int> v = curves[piece.curve].vertices;
      if (!piece.forward) std::reverse(v.begin(), v.end());
      starts[k].push_back(rim.size());
      for (std::size_t i = 0; i + 1 < v.size(); ++i) rim.push_back(pointOf(v[i]));
    }
  }
  std::vector<std::vector<int>> holes;
  for (const std::vector<int>& hole : face.holes) {
    std::vector<int> loop;
    Vec3 centre = Vec3::Zero();
    for (int v : hole) loop.push_back(pointOf(v)), centre += x[v] / hole.size();
    if (arcLength(hole, x).back() >= size(centre)) {
      holes.push_back(std::move(loop));
      continue;
    }
    // a pinhole (shorter than a quad's edge: a bend relief where sheets meet at a corner) the quads close, as they
    // do elsewhere (the quad mesh's Euler characteristic is the chordal surface's with its pinholes closed)
    closeByFan(points, triangles, loop, false);
  }
  const SurfaceMap map = mapOntoSquare(points, triangles, rim, corners, holes);
  if (map.empty()) return std::nullopt;
  const std::vector<double> length = arcLength(map.rim, map.points);
  SquareRim given;
  given.n0 = static_cast<int>(sideNodes(face.sides[0], made.nodes).size()) - 1;
  given.n1 = static_cast<int>(sideNodes(face.sides[1], made.nodes).size()) - 1;
  std::vector<int> rimNodes;
  for (int k = 0; k < 4; ++k)
    for (std::size_t j = 0; j < face.sides[k].size(); ++j) {
      const SideOf& piece = face.sides[k][j];
      const std::vector<int>& nodes = made.nodes[piece.curve];
      const std::vector<double>& along = made.along[piece.curve];
      const std::size_t end = j + 1 < starts[k].size() ? starts[k][j + 1] : k == 3 ? map.rim.size() : corners[k + 1];
      const double from = length[starts[k][j]], to = length[end];
      const std::size_t n = nodes.size() - 1;
      for (std::size_t i = 0; i < n; ++i) {  // the piece's nodes but its last (the next piece's first)
        const std::size_t at = piece.forward ? i : n - i;
        const double f = piece.forward ? along[at] : 1 - along[at];
        LoopPoint p = loopPoint(map, map.rim, length, from + f * (to - from));
        p.x = grid.nodes[nodes[at]];
        given.points.push_back(p), rimNodes.push_back(nodes[at]);
      }
    }
  BlockGrid holed = holedGrid(map, size, given);
  if (holed.empty()) holed = sharedGrid(map, size, given);  // the holes' pockets meet
  if (holed.empty()) return std::nullopt;
  return addFaceQuads(holed, rimNodes, normal, grid);
}

// The median target size at the triangles' centres (at most kSizeSamples of them, evenly taken).
constexpr std::size_t kSizeSamples = 201;

double typicalSize(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                   const SizeField& size) {
  if (triangles.empty()) return 0;
  std::vector<double> sizes;
  const std::size_t step = std::max<std::size_t>(1, triangles.size() / kSizeSamples);
  for (std::size_t t = 0; t < triangles.size(); t += step)
    sizes.push_back(size((x[triangles[t][0]] + x[triangles[t][1]] + x[triangles[t][2]]) / 3));
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  return sizes[sizes.size() / 2];
}

// The patch grid's layout: the faces' curves (their paths), each face (its four sides, its holes) and its triangles
// and shape.
struct PatchLayout {
  std::vector<Curve> curves;
  std::vector<std::vector<Vec3>> paths;
  std::vector<Face> faces;
  std::vector<std::vector<std::array<int, 3>>> facets;
  std::vector<PatchShape> shapes;
  double typical = 0;  // a quad's length
};

// Interval assignment: each curve's segments, as many as its measure needs or more, so that each face's opposite
// sides have as many. Where they do not, the side with fewer takes one more on its curve with the most measure per
// segment, face after face, round after round, until none needs more (on faces whose sides are single curves, each
// chain of opposite curves gets the most any of them needs). [in] faces, measures. Nothing if that does not settle
// within kMaxRounds rounds (sides that cannot match: a curve on one side of a face and on both of another).
constexpr int kMaxRounds = 64;

std::optional<std::vector<int>> assignSegments(const std::vector<Face>& faces,
                                               const std::vector<CurveMeasure>& measures) {
  std::vector<int> n;
  for (const CurveMeasure& m : measures) n.push_back(segmentsNeeded(m));
  auto sum = [&](const Side& side) {
    int total = 0;
    for (const SideOf& s : side) total += n[s.curve];
    return total;
  };
  for (int round = 0; round < kMaxRounds; ++round) {
    bool changed = false;
    for (const Face& face : faces)
      for (int k = 0; k < 2; ++k)
        for (int a = sum(face.sides[k]), b = sum(face.sides[k + 2]); a != b;
             a = sum(face.sides[k]), b = sum(face.sides[k + 2])) {
          const Side& fewer = a < b ? face.sides[k] : face.sides[k + 2];
          const SideOf* most = &fewer.front();
          for (const SideOf& s : fewer)
            if (measures[s.curve].at.back() / n[s.curve] > measures[most->curve].at.back() / n[most->curve]) most = &s;
          ++n[most->curve], changed = true;
        }
    if (!changed) return n;
  }
  return std::nullopt;
}

// The grid of a layout, graded towards the creases or not. [in] layout, x, size, graded; [out] grid. Returns the
// quads folded against their faces (addPatchGrid), nothing if the sides' segments cannot match or a face with holes
// has no grid.
std::optional<std::size_t> gridOf(const PatchLayout& layout, const std::vector<Vec3>& x, const SizeField& size,
                                  bool graded, BlockGrid& grid) {
  const std::vector<std::array<bool, 2>> ends = endsOnCreases(layout.curves);
  std::vector<CurveMeasure> measures;
  for (std::size_t c = 0; c < layout.curves.size(); ++c)
    measures.push_back(curveMeasure(layout.paths[c], ends[c], size, layout.typical, graded));
  const std::optional<std::vector<int>> segments = assignSegments(layout.faces, measures);
  if (!segments) return std::nullopt;
  const CurveNodes made = curveNodes(layout.curves, layout.paths, measures, *segments, x, grid);
  std::size_t folded = 0;
  for (std::size_t p = 0; p < layout.faces.size(); ++p) {
    const Face& face = layout.faces[p];
    const Vec3& normal = layout.shapes[p].normal;
    if (face.holes.empty()) {
      std::array<std::vector<int>, 4> sides;
      for (int k = 0; k < 4; ++k) sides[k] = sideNodes(face.sides[k], made.nodes);
      folded += addPatchGrid(sides, normal, grid);
      continue;
    }
    const std::optional<std::size_t> holed =
        addHoledFace(face, layout.curves, made, layout.facets[p], x, size, normal, grid);
    if (!holed) return std::nullopt;
    folded += *holed;
  }
  dropUnusedNodes(grid.nodes, grid.quads);  // the holes' curves' (the pockets' rings have their own on the holes)
  return folded;
}

// ---------------------------------------------------------------------------------------------------------------
// A face with a reflex corner (an L-shaped floor: five corners turning one way round it, one the other) is cut in
// two from that corner straight on into the face (continuing the side coming into the corner) to its rim, along the
// facets' edges: two four-sided faces, the cut a curve between them like a crease (the curve it lands on split
// there, the face beyond it then has a side of two curves).
// ---------------------------------------------------------------------------------------------------------------

constexpr int kMaxCuts = 16;  // cuts at reflex corners in one surface, at the most

// The surface cut into patches: per triangle its patch, and their count.
struct Patches {
  std::vector<int> of;
  int count = 0;
};

// Per patch, its curves, ascending.
std::vector<std::vector<int>> curvesOfPatches(const std::vector<Curve>& curves, int patches) {
  std::vector<std::vector<int>> ofPatch(patches);
  for (std::size_t c = 0; c < curves.size(); ++c)
    for (int p : curves[c].patches)
      if (p >= 0) ofPatch[p].push_back(static_cast<int>(c));
  return ofPatch;
}

// The first reflex corner of a loop: where it turns by kSideTurn or more against the way it turns round `normal`
// over all (a simple loop turns a full turn round its face), with the direction coming into it. [in] loop, paths,
// normal, size. Nothing if it has none.
std::optional<std::pair<std::size_t, Vec3>> reflexCorner(const Side& loop, const std::vector<std::vector<Vec3>>& paths,
                                                         const Vec3& normal, const SizeField& size) {
  std::vector<double> turn;
  std::vector<Vec3> in;
  double total = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto [before, after] =
        directionsInto(sidePath(paths, {loop[(i + loop.size() - 1) % loop.size()]}), sidePath(paths, {loop[i]}), size);
    const double angle = angleBetween(before, after);
    turn.push_back(before.cross(after).dot(normal) < 0 ? -angle : angle), in.push_back(before.normalized());
    total += turn.back();
  }
  for (std::size_t i = 0; i < loop.size(); ++i)
    if ((total < 0 ? -turn[i] : turn[i]) <= -kSideTurn) return std::make_pair(i, in[i]);
  return std::nullopt;
}

// A chain of the patch's edges from `from` along `direction` to a vertex of its outer loop at least half a quad
// on: at each step the neighbour ahead nearest the line. [in] around: per vertex its neighbours in the patch;
// [in] onOuter, onHole: the loops' vertices; [in] x; [in] reach: half a quad. Empty if it gets stuck or reaches a
// hole.
std::vector<int> straightCut(int from, const Vec3& direction, const std::map<int, std::vector<int>>& around,
                             const std::set<int>& onOuter, const std::set<int>& onHole, const std::vector<Vec3>& x,
                             double reach) {
  std::vector<int> cut{from};
  std::set<int> visited{from};
  for (std::size_t step = 0; step < around.size(); ++step) {
    const auto it = around.find(cut.back());
    if (it == around.end()) return {};
    int best = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (int v : it->second) {
      const Vec3 d = x[v] - x[from];
      const double ahead = d.dot(direction);
      if (visited.count(v) || (x[v] - x[cut.back()]).dot(direction) <= 0) continue;
      if (onOuter.count(v) && ahead < reach) continue;  // the loop beside the corner
      const double off = (d - ahead * direction).norm();
      if (off < nearest) nearest = off, best = v;
    }
    if (best < 0 || onHole.count(best)) return {};
    cut.push_back(best), visited.insert(best);
    if (onOuter.count(best)) return cut;
  }
  return {};
}

// Patch p cut in two at its first reflex corner (straightCut), the part on one side of the cut a new patch: its
// triangles moved to it, its curves' patch changed, the curve the cut lands on split there, the cut a curve of both.
// [in,out] layout (curves and paths), patches; [in] triangles, x, size; [in] p, ofPatch: the patch and its curves.
// False if p has no reflex corner or the cut does not part it.
bool cutAtReflexCorner(PatchLayout& layout, Patches& patches, const std::vector<std::array<int, 3>>& triangles,
                       const std::vector<Vec3>& x, const SizeField& size, int p, const std::vector<int>& ofPatch) {
  std::vector<Curve>& curves = layout.curves;
  const std::optional<PatchLoops> loops = loopsOf(curves, ofPatch);
  const std::optional<Side> loop = loops ? loopOf(curves, loops->outer) : std::nullopt;
  if (!loop) return false;
  Vec3 normal = Vec3::Zero();
  std::map<int, std::vector<int>> around;
  std::map<std::pair<int, int>, std::vector<int>> edgeTriangles;
  std::size_t inPatch = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (patches.of[t] != p) continue;
    const auto& c = triangles[t];
    ++inPatch;
    normal += (x[c[1]] - x[c[0]]).cross(x[c[2]] - x[c[0]]);
    for (int k = 0; k < 3; ++k) {
      around[c[k]].push_back(c[(k + 1) % 3]), around[c[k]].push_back(c[(k + 2) % 3]);
      edgeTriangles[std::minmax(c[k], c[(k + 1) % 3])].push_back(static_cast<int>(t));
    }
  }
  const std::optional<std::pair<std::size_t, Vec3>> reflex = reflexCorner(*loop, layout.paths, normal, size);
  if (!reflex) return false;
  std::set<int> onOuter, onHole;
  for (int c : loops->outer) onOuter.insert(curves[c].vertices.begin(), curves[c].vertices.end());
  for (const auto& hole : loops->holes)
    for (int c : hole) onHole.insert(curves[c].vertices.begin(), curves[c].vertices.end());
  const SideOf& at = (*loop)[reflex->first];
  const int corner = at.forward ? curves[at.curve].vertices.front() : curves[at.curve].vertices.back();
  const std::vector<int> cut = straightCut(corner, reflex->second, around, onOuter, onHole, x, 0.5 * layout.typical);
  if (cut.size() < 2) return false;
  // the triangles on one side of the cut: those reached from one of its first edge's without crossing it
  std::set<std::pair<int, int>> across;
  for (std::size_t i = 0; i + 1 < cut.size(); ++i) across.insert(std::minmax(cut[i], cut[i + 1]));
  std::vector<int> todo{edgeTriangles[std::minmax(cut[0], cut[1])].front()};
  std::set<int> side{todo.front()};
  while (!todo.empty()) {
    const auto& c = triangles[todo.back()];
    todo.pop_back();
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> e = std::minmax(c[k], c[(k + 1) % 3]);
      if (across.count(e)) continue;
      for (int t : edgeTriangles[e])
        if (side.insert(t).second) todo.push_back(t);
    }
  }
  if (side.size() == inPatch) return false;  // the cut does not part the patch
  const int q = patches.count++;
  for (int t : side) patches.of[t] = q;
  // the curve the cut lands on split there
  for (int c : loops->outer) {
    const std::vector<int>& v = curves[c].vertices;
    const auto it = std::find(v.begin() + 1, v.end() - 1, cut.back());
    if (it == v.end() - 1) continue;
    std::vector<Curve> pieces = piecesAt(curves[c], {static_cast<std::size_t>(it - v.begin())});
    curves[c] = std::move(pieces[0]), curves.push_back(std::move(pieces[1]));
    break;
  }
  // the patch's curves along the new patch's triangles are the new patch's
  for (Curve& c : curves) {
    if (c.patches[0] != p && c.patches[1] != p) continue;
    const std::vector<int>& tri = edgeTriangles[std::minmax(c.vertices[0], c.vertices[1])];
    if (std::any_of(tri.begin(), tri.end(), [&](int t) { return patches.of[t] == q; }))
      for (int& patchOf : c.patches) patchOf = patchOf == p ? q : patchOf;
    std::sort(c.patches.begin(), c.patches.end());
  }
  curves.push_back({cut, {p, q}});
  layout.paths = curvePaths(curves, x, layout.typical);
  return true;
}

}  // namespace

PatchGrids patchGrids(const ChordalSurface& chordal, const SizeField& size, double featureAngle, PatchSeeds seeds,
                      PatchRims rims, PatchSides sides) {
  const std::vector<Vec3>& x = chordal.vertices;
  const std::vector<std::array<int, 3>> triangles = chordalTriangles(chordal);
  PatchLayout layout;
  layout.typical = typicalSize(x, triangles, size);
  std::size_t fitted = 0;
  Patches patch{facePatches(x, triangles, featureAngle, layout.typical, seeds, rims, &fitted), 0};
  if (rims == PatchRims::FittedToNormals && fitted == 0) return {};  // the faces as grown: their grid made already
  patch.count = patch.of.empty() ? 0 : 1 + *std::max_element(patch.of.begin(), patch.of.end());
  if (patch.count < 2) return {};
  layout.curves = cutAtSharpTurns(patchTopology(triangles, patch.of), x, layout.typical);
  joinShortRimCurves(layout.curves, x, layout.typical);
  layout.paths = curvePaths(layout.curves, x, layout.typical);
  std::vector<std::vector<int>> ofPatch = curvesOfPatches(layout.curves, patch.count);
  for (int p = 0, cuts = 0; p < patch.count; ++p) {
    std::optional<Face> face = faceOf(layout.curves, layout.paths, ofPatch[p], size, sides);
    for (const double window : kRoundCorners)
      if (!face && cutAtRoundCorners(layout.curves, layout.paths, ofPatch[p], x, layout.typical, window))
        face = faceOf(layout.curves, layout.paths, ofPatch[p], size, sides);
    if (!face && cuts < kMaxCuts && cutAtReflexCorner(layout, patch, triangles, x, size, p, ofPatch[p])) {
      ++cuts, p = -1;  // the faces again: the cut may have split a curve of one made already
      layout.faces.clear(), ofPatch = curvesOfPatches(layout.curves, patch.count);
      continue;
    }
    if (!face) return {};
    layout.faces.push_back(*face);
  }
  const int patches = patch.count;
  layout.shapes = patchShapes(triangles, patch.of, patches, x);
  for (int p = 0; p < patches; ++p)
    if (layout.shapes[p].euler != 1 - static_cast<long>(layout.faces[p].holes.size())) return {};
  layout.facets.resize(patches);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (!layout.faces[patch.of[t]].holes.empty()) layout.facets[patch.of[t]].push_back(triangles[t]);
  PatchGrids grids;
  std::optional<std::size_t> even, folded;
  sideBySide({[&] { even = gridOf(layout, x, size, false, grids.even); },  // neither reads the other
              [&] { folded = gridOf(layout, x, size, true, grids.graded); }});
  if (!even) return {};
  if (!folded || *folded > 0) grids.graded = {};  // a quad folds: even rows only
  return grids;
}

}  // namespace hexlayer
