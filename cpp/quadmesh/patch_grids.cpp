#include "quadmesh/patch_grids.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/union_find.hpp"
#include "quadmesh/chordal_patches.hpp"

namespace hexlayer {
namespace {

const double kSideTurn = 45 * M_PI / 180;    // a curve turning more within a quad is cut there: a patch's corner
const double kMaxCorner = 135 * M_PI / 180;  // a patch's corner turns at most this much (and at least kSideTurn)
constexpr double kCornerWindow = 3;          // quads: a corner's turn is measured over this length of its sides

// A chain of chordal vertices along a patch's rim, from a corner to a corner, with the patches on either side.
struct Curve {
  std::vector<int> vertices;
  std::array<int, 2> patches;
};

// A chain's points.
std::vector<Vec3> pointsOf(const std::vector<int>& chain, const std::vector<Vec3>& x) {
  std::vector<Vec3> points;
  points.reserve(chain.size());
  for (int v : chain) points.push_back(x[v]);
  return points;
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

// The positions in a path (inside it, from `first` to `last`) where it turns more than kSideTurn, the most within a
// quad either side. [in] path; [in] size: a quad's length; [in] first, last: the range of positions looked at.
std::vector<std::size_t> sharpTurns(const std::vector<Vec3>& path, double size, std::size_t first, std::size_t last) {
  const std::vector<double> length = lengthAlong(path);
  std::vector<double> turn(path.size(), 0.0);
  for (std::size_t i = 1; i + 1 < path.size(); ++i) turn[i] = turnAt(path, length, i, size);
  std::vector<std::size_t> peaks;
  for (std::size_t i = first; i <= last; ++i) {
    // a turn within half a quad of an end is the curve's end turning (the rim's chord across a corner whose crease
    // ends there)
    if (turn[i] <= kSideTurn || std::min(length[i], length.back() - length[i]) < 0.5 * size) continue;
    bool peak = true;  // the most within a quad before (strictly) and after
    for (std::size_t j = i; peak && j-- > 1 && length[i] - length[j] < size;) peak = turn[j] < turn[i];
    for (std::size_t j = i + 1; peak && j + 1 < path.size() && length[j] - length[i] < size; ++j)
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
      const std::vector<std::size_t> peaks = sharpTurns(pointsOf(thrice, x), size, n, 2 * n - 1);
      if (peaks.empty()) {
        cut.push_back({chain, c.patches});
        continue;
      }
      chain.assign(thrice.begin() + peaks.front(), thrice.begin() + peaks.front() + n + 1);  // from its first turn
      first = 1, last = n - 1;
    }
    std::size_t from = 0;
    for (std::size_t at : sharpTurns(pointsOf(chain, x), size, first, last)) {
      cut.push_back({std::vector<int>(chain.begin() + from, chain.begin() + at + 1), c.patches});
      from = at;
    }
    cut.push_back({std::vector<int>(chain.begin() + from, chain.end()), c.patches});
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
          a.insert(a.end(), b.begin() + 1, b.end());
        else if (a.front() == b.back())
          a.insert(a.begin(), b.begin(), b.end() - 1);
        else
          continue;
        curves.erase(curves.begin() + c);
        joined = true;
      }
    }
  }
}

// A curve as one side of a patch, in the patch's loop: forward (from its first vertex) or backward.
struct SideOf {
  int curve;
  bool forward;
};

// A patch's four sides in order round it, if its curves make one loop of four. [in] curves; [in] ofPatch: the
// patch's curves, ascending.
std::optional<std::array<SideOf, 4>> fourSides(const std::vector<Curve>& curves, const std::vector<int>& ofPatch) {
  if (ofPatch.size() != 4) return std::nullopt;
  std::array<SideOf, 4> sides{SideOf{ofPatch[0], true}, {}, {}, {}};
  std::set<int> used{ofPatch[0]};
  auto endOf = [&](const SideOf& s) {
    return s.forward ? curves[s.curve].vertices.back() : curves[s.curve].vertices.front();
  };
  for (int k = 1; k < 4; ++k) {
    const int at = endOf(sides[k - 1]);
    std::optional<SideOf> next;
    for (int c : ofPatch) {
      if (used.count(c)) continue;
      for (const bool forward : {true, false}) {
        const int start = forward ? curves[c].vertices.front() : curves[c].vertices.back();
        if (start != at) continue;
        if (next) return std::nullopt;  // the patch touches itself at the corner
        next = SideOf{c, forward};
      }
    }
    if (!next) return std::nullopt;
    sides[k] = *next, used.insert(next->curve);
  }
  if (endOf(sides[3]) != curves[sides[0].curve].vertices.front()) return std::nullopt;
  return sides;
}

// A side's path in the patch's order round it.
std::vector<Vec3> sidePath(const std::vector<std::vector<Vec3>>& paths, const SideOf& s) {
  std::vector<Vec3> path = paths[s.curve];
  if (!s.forward) std::reverse(path.begin(), path.end());
  return path;
}

// Whether the sides' paths turn into one another by kSideTurn to kMaxCorner at each corner (over a quad's length).
bool squareCorners(const std::vector<std::vector<Vec3>>& paths, const std::array<SideOf, 4>& sides,
                   const SizeField& size) {
  for (int k = 0; k < 4; ++k) {
    const std::vector<Vec3> in = sidePath(paths, sides[k]), out = sidePath(paths, sides[(k + 1) % 4]);
    const std::vector<double> inLength = lengthAlong(in), outLength = lengthAlong(out);
    const Vec3& corner = out.front();
    // over a few quads (a quarter of the shorter side at most): the creases' ends wander by a facet
    const double window = std::min(kCornerWindow * size(corner), 0.25 * std::min(inLength.back(), outLength.back()));
    const double turn = angleBetween(corner - pointAt(in, inLength, inLength.back() - window),
                                     pointAt(out, outLength, window) - corner);
    if (turn < kSideTurn || turn > kMaxCorner) return false;
  }
  return true;
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

// Whether a patch's triangles make a disc (V - E + F = 1), and their summed normal (twice their vector area).
struct PatchShape {
  bool disc = false;
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
    shapes[p].disc = static_cast<long>(vertices[p].size()) - static_cast<long>(edges[p].size()) + faces[p] == 1;
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
  for (const Curve& c : curves)
    paths.push_back(c.patches[0] >= 0 ? creasePath(c.vertices, x, window) : pointsOf(c.vertices, x));
  return paths;
}

// The nodes of each curve: its end vertices' nodes (shared by the curves meeting there) and segments[curve] - 1
// between them along its path, at even shares of its measure. [in] curves, paths, measures, segments, x; [in,out]
// grid: nodes added.
std::vector<std::vector<int>> curveNodes(const std::vector<Curve>& curves, const std::vector<std::vector<Vec3>>& paths,
                                         const std::vector<CurveMeasure>& measures, const std::vector<int>& segments,
                                         const std::vector<Vec3>& x, BlockGrid& grid) {
  std::map<int, int> cornerNode;
  auto corner = [&](int v) {
    const auto [it, added] = cornerNode.emplace(v, static_cast<int>(grid.nodes.size()));
    if (added) grid.nodes.push_back(x[v]);
    return it->second;
  };
  std::vector<std::vector<int>> nodes(curves.size());
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const std::vector<double> length = lengthAlong(paths[c]);
    const int n = segments[c];
    nodes[c].push_back(corner(curves[c].vertices.front()));
    for (int k = 1; k < n; ++k) {
      nodes[c].push_back(static_cast<int>(grid.nodes.size()));
      grid.nodes.push_back(pointAt(paths[c], length, arcAtShare(measures[c], static_cast<double>(k) / n)));
    }
    nodes[c].push_back(corner(curves[c].vertices.back()));
  }
  return nodes;
}

// One patch's grid: its sides' nodes on its rim, the nodes inside by transfinite interpolation between them (a
// bilinearly blended Coons patch: a plane's grid exactly, a cylinder's between its arcs), put on the chordal surface
// with the others when the grid is ranked. [in] sides, nodes: the patch's sides and the curves' nodes; [in] normal:
// the patch's (its quads turn counter-clockwise round it). [in,out] grid: nodes and quads added. Returns the quads
// whose normal points against the patch's (folded: a graded grid on a patch whose sides are graded unlike).
std::size_t addPatchGrid(const std::array<SideOf, 4>& sides, const std::vector<std::vector<int>>& nodes,
                         const Vec3& normal, BlockGrid& grid) {
  auto sideNode = [&](int k, int i) {
    const std::vector<int>& n = nodes[sides[k].curve];
    return sides[k].forward ? n[i] : n[n.size() - 1 - i];
  };
  const int n0 = static_cast<int>(nodes[sides[0].curve].size()) - 1;
  const int n1 = static_cast<int>(nodes[sides[1].curve].size()) - 1;
  std::vector<int> node((n0 + 1) * (n1 + 1));
  auto at = [&](int i, int j) -> int& { return node[j * (n0 + 1) + i]; };
  for (int i = 0; i <= n0; ++i) at(i, 0) = sideNode(0, i), at(i, n1) = sideNode(2, n0 - i);
  for (int j = 0; j <= n1; ++j) at(n0, j) = sideNode(1, j), at(0, j) = sideNode(3, n1 - j);
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

// The patch grid's layout: the faces' curves (their paths), each face's four sides, its shape, the chains of
// opposite curves (per curve, its chain's root).
struct PatchLayout {
  std::vector<Curve> curves;
  std::vector<std::vector<Vec3>> paths;
  std::vector<std::array<SideOf, 4>> sides;
  std::vector<PatchShape> shapes;
  std::vector<int> chain;
  double typical = 0;  // a quad's length
};

// The grid of a layout, graded towards the creases or not. [in] layout, x, size, graded; [out] grid. Returns the
// quads folded against their faces (addPatchGrid).
std::size_t gridOf(const PatchLayout& layout, const std::vector<Vec3>& x, const SizeField& size, bool graded,
                   BlockGrid& grid) {
  const std::vector<std::array<bool, 2>> ends = endsOnCreases(layout.curves);
  std::vector<CurveMeasure> measures;
  for (std::size_t c = 0; c < layout.curves.size(); ++c)
    measures.push_back(curveMeasure(layout.paths[c], ends[c], size, layout.typical, graded));
  std::map<int, int> chainSegments;  // per chain of opposite curves, the most its curves need
  for (std::size_t c = 0; c < layout.curves.size(); ++c) {
    int& s = chainSegments[layout.chain[c]];
    s = std::max(s, segmentsNeeded(measures[c]));
  }
  std::vector<int> segments;
  for (std::size_t c = 0; c < layout.curves.size(); ++c) segments.push_back(chainSegments[layout.chain[c]]);
  const std::vector<std::vector<int>> nodes = curveNodes(layout.curves, layout.paths, measures, segments, x, grid);
  std::size_t folded = 0;
  for (std::size_t p = 0; p < layout.sides.size(); ++p)
    folded += addPatchGrid(layout.sides[p], nodes, layout.shapes[p].normal, grid);
  return folded;
}

}  // namespace

PatchGrids patchGrids(const ChordalSurface& chordal, const SizeField& size, double featureAngle) {
  const std::vector<Vec3>& x = chordal.vertices;
  const std::vector<std::array<int, 3>> triangles = chordalTriangles(chordal);
  PatchLayout layout;
  layout.typical = typicalSize(x, triangles, size);
  const std::vector<int> patch = facePatches(x, triangles, featureAngle, layout.typical);
  const int patches = patch.empty() ? 0 : 1 + *std::max_element(patch.begin(), patch.end());
  if (patches < 2) return {};
  layout.curves = cutAtSharpTurns(patchTopology(triangles, patch), x, layout.typical);
  joinShortRimCurves(layout.curves, x, layout.typical);
  std::vector<std::vector<int>> ofPatch(patches);
  for (std::size_t c = 0; c < layout.curves.size(); ++c)
    for (int p : layout.curves[c].patches)
      if (p >= 0) ofPatch[p].push_back(static_cast<int>(c));
  layout.paths = curvePaths(layout.curves, x, layout.typical);
  UnionFind opposite(layout.curves.size());
  for (int p = 0; p < patches; ++p) {
    const std::optional<std::array<SideOf, 4>> four = fourSides(layout.curves, ofPatch[p]);
    if (!four || !squareCorners(layout.paths, *four, size)) return {};
    opposite.unite((*four)[0].curve, (*four)[2].curve), opposite.unite((*four)[1].curve, (*four)[3].curve);
    layout.sides.push_back(*four);
  }
  layout.shapes = patchShapes(triangles, patch, patches, x);
  if (std::any_of(layout.shapes.begin(), layout.shapes.end(), [](const PatchShape& p) { return !p.disc; })) return {};
  for (std::size_t c = 0; c < layout.curves.size(); ++c) layout.chain.push_back(opposite.find(static_cast<int>(c)));
  PatchGrids grids;
  gridOf(layout, x, size, false, grids.even);
  if (gridOf(layout, x, size, true, grids.graded) > 0) grids.graded = {};  // a quad folds: even rows only
  return grids;
}

}  // namespace hexlayer
