#include "quadmesh/quad_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/groups.hpp"
#include "core/sweep_halves.hpp"

namespace hexlayer {

namespace {

// The quad's scaled Jacobian from its corners, the edge vectors edge[k] = p[k+1] - p[k] and their
// lengths (corner k's second edge p[k+3] - p[k] is the exact negation of edge k+3).
// [in] n: the unit normal the corners are seen along.
double scaledJacobianAlong(const Vec3& n, const std::array<Vec3, 4>& edge, const std::array<double, 4>& length) {
  double sj = 1;
  for (int k = 0; k < 4; ++k) {
    const Vec3 e2 = -edge[(k + 3) % 4];
    const double len = length[k] * length[(k + 3) % 4];
    sj = std::min(sj, len > 0 ? n.dot(edge[k].cross(e2)) / len : -1.0);
  }
  return sj;
}

double scaledJacobianFromEdges(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& edge,
                               const std::array<double, 4>& length) {
  const Vec3 n = (p[2] - p[0]).cross(p[3] - p[1]);
  if (n.norm() == 0) return -1;
  return scaledJacobianAlong(n.normalized(), edge, length);
}

std::array<Vec3, 4> edgesOf(const std::array<Vec3, 4>& p) {
  std::array<Vec3, 4> edge;
  for (int k = 0; k < 4; ++k) edge[k] = p[(k + 1) % 4] - p[k];
  return edge;
}

std::array<double, 4> lengthsOf(const std::array<Vec3, 4>& edge) {
  std::array<double, 4> length;
  for (int k = 0; k < 4; ++k) length[k] = edge[k].norm();
  return length;
}

constexpr double kFreeAspect = 4;  // quads up to this ratio of longest to shortest edge are not penalized

// quadSmoothingQuality from the corners, the edge vectors and their lengths.
double qualityFromEdges(const std::array<Vec3, 4>& p, const std::array<Vec3, 4>& edge,
                        const std::array<double, 4>& length) {
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (int k = 0; k < 4; ++k) shortest = std::min(shortest, length[k]), longest = std::max(longest, length[k]);
  return std::min(scaledJacobianFromEdges(p, edge, length), longest > 0 ? kFreeAspect * shortest / longest : -1.0);
}

}  // namespace

double quadScaledJacobian(const std::array<Vec3, 4>& p) {
  const std::array<Vec3, 4> edge = edgesOf(p);
  return scaledJacobianFromEdges(p, edge, lengthsOf(edge));
}

double quadScaledJacobian(const std::array<Vec3, 4>& p, const Vec3& normal) {
  const std::array<Vec3, 4> edge = edgesOf(p);
  const std::array<double, 4> length = lengthsOf(edge);
  const double own = scaledJacobianFromEdges(p, edge, length);  // through its diagonals, then turned to face `normal`
  const double facing = (p[2] - p[0]).cross(p[3] - p[1]).dot(normal) < 0 ? -own : own;
  const double along = scaledJacobianAlong(normal, edge, length);  // negative at a corner turned back (a bow tie)
  return along < 0 ? std::min(facing, along) : facing;
}

double quadSmoothingQuality(const std::array<Vec3, 4>& p) {
  const std::array<Vec3, 4> edge = edgesOf(p);
  return qualityFromEdges(p, edge, lengthsOf(edge));
}

namespace {

constexpr double kGoodQuad = 0.999;                  // quads below this get their nodes optimized
constexpr double kMeanWeight = 2;                    // weight of the mean quad against the worst one
constexpr double kMinGain = 1e-4;                    // a node moves only for a better score than this
constexpr double kSmallestStep = 1e-2;               // pattern search stops at this x the longest edge around
constexpr double kRimCornerAngle = 30 * M_PI / 180;  // a rim node turning more than this stays

using NodeQuads = Groups<int>;  // the quads around node i: items[start[i] .. start[i + 1])

NodeQuads quadsAroundNodes(const QuadMesh& q) {
  return groupByKey<int>(q.nodes.size(), [&](auto emit) {
    for (std::size_t e = 0; e < q.quads.size(); ++e)
      for (int v : q.quads[e]) emit(v, static_cast<int>(e));
  });
}

// The two rim neighbours of every node on the rim (the boundary of the quad mesh); {-1, -1} for an
// interior node, {-2, -2} for a rim node that must stay (a corner or a pinch).
std::vector<std::array<int, 2>> rimNeighbours(const QuadMesh& q) {
  const std::vector<std::vector<int>> around = rimEdgeNeighbours(q);
  std::vector<std::array<int, 2>> rim(q.nodes.size(), {-1, -1});
  for (size_t i = 0; i < q.nodes.size(); ++i) {
    if (around[i].empty()) continue;
    rim[i] = {-2, -2};
    if (around[i].size() != 2) continue;
    const Vec3 a = (q.nodes[i] - q.nodes[around[i][0]]).normalized(),
               b = (q.nodes[around[i][1]] - q.nodes[i]).normalized();
    if (a.dot(b) > std::cos(kRimCornerAngle)) rim[i] = {around[i][0], around[i][1]};
  }
  return rim;
}

Vec3 closestOnSegment(const Vec3& a, const Vec3& b, const Vec3& p) { return a + nearestOnSegment(a, b, p) * (b - a); }

std::array<Vec3, 4> corners(const QuadMesh& q, int e, int moved, const Vec3& at) {
  std::array<Vec3, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = q.quads[e][k] == moved ? at : q.nodes[q.quads[e][k]];
  return p;
}

// Worst quad around `node` if it stood at `at`.
double worstAround(const QuadMesh& q, const NodeQuads& nq, int node, const Vec3& at) {
  double worst = 1;
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k)
    worst = std::min(worst, quadSmoothingQuality(corners(q, nq.items[k], node, at)));
  return worst;
}

// Area-weighted mean of the centroids of the quads around the node.
Vec3 centroidTarget(const QuadMesh& q, const NodeQuads& nq, int node) {
  Vec3 sum = Vec3::Zero();
  double area = 0;
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k) {
    const auto p = corners(q, nq.items[k], -1, Vec3::Zero());
    const double a = 0.5 * (p[2] - p[0]).cross(p[3] - p[1]).norm();
    sum += a * 0.25 * (p[0] + p[1] + p[2] + p[3]);
    area += a;
  }
  return area > 0 ? Vec3(sum / area) : q.nodes[node];
}

// What the node optimization maximizes, the worst quad around the node plus kMeanWeight x their mean,
// for one node moving while the others stay: the edges not at the node and their lengths are
// computed once.
class MovingNodeScore {
 public:
  MovingNodeScore(const QuadMesh& q, const NodeQuads& nq, int node) : q_(q), nq_(nq), node_(node) {
    for (int k = nq.start[node]; k < nq.start[node + 1]; ++k) {
      Quad e;
      const auto& quad = q.quads[nq.items[k]];
      e.p = corners(q, nq.items[k], -1, Vec3::Zero());
      for (int c = 0; c < 4; ++c) {
        e.edge[c] = e.p[(c + 1) % 4] - e.p[c], e.length[c] = e.edge[c].norm();
        if (quad[c] == node) e.moved = e.moved == -1 ? c : -2;  // -2: the node twice in the quad
      }
      quads_.push_back(e);
    }
  }
  // The score at `at`, or -infinity as soon as it cannot be above `floor`: every quality is at most 1,
  // so worst + kMeanWeight * (sum + quads left) / count bounds the score from above (with a margin far
  // above the rounding of the sums, so a trial is only dropped when its exact score could not pass).
  double operator()(const Vec3& at, double floor = -std::numeric_limits<double>::infinity()) const {
    double worst = 1, sum = 0;
    const double count = static_cast<double>(quads_.size());
    std::size_t left = quads_.size();
    for (const Quad& e : quads_) {
      double quality;
      if (e.moved < 0) {
        quality = quadSmoothingQuality(corners(q_, nq_.items[nq_.start[node_] + (&e - quads_.data())], node_, at));
      } else {
        std::array<Vec3, 4> p = e.p, edge = e.edge;
        std::array<double, 4> length = e.length;
        const int m = e.moved, before = (m + 3) % 4;
        p[m] = at;
        edge[before] = at - p[before], length[before] = edge[before].norm();
        edge[m] = p[(m + 1) % 4] - at, length[m] = edge[m].norm();
        quality = qualityFromEdges(p, edge, length);
      }
      worst = std::min(worst, quality), sum += quality;
      --left;
      if (worst + kMeanWeight * (sum + static_cast<double>(left)) / count + 1e-12 < floor)
        return -std::numeric_limits<double>::infinity();
    }
    return worst + kMeanWeight * sum / std::max(1, static_cast<int>(quads_.size()));
  }

 private:
  struct Quad {
    std::array<Vec3, 4> p, edge;
    std::array<double, 4> length;
    int moved = -1;
  };
  const QuadMesh& q_;
  const NodeQuads& nq_;
  int node_;
  std::vector<Quad> quads_;
};

// Pattern search: tries steps along the given directions, keeps the one that raises the worst quad
// around the node most, halves the step when none does; the end point is put back on the surface
// (or the rim) by `project` and kept if the worst quad around the node is then better than before.
template <class Project>
void improveWorst(QuadMesh& q, const NodeQuads& nq, int node, const std::vector<Vec3>& directions, Project project) {
  const MovingNodeScore score(q, nq, node);
  const double before = score(q.nodes[node]);
  double best = before, step = 0;
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k)
    for (int c : q.quads[nq.items[k]]) step = std::max(step, (q.nodes[c] - q.nodes[node]).norm());
  const double smallest = kSmallestStep * step;
  Vec3 at = q.nodes[node];
  for (step *= 0.2; step > smallest;) {
    Vec3 bestAt = at;
    for (const Vec3& d : directions) {
      const Vec3 trial = at + step * d;
      const double w = score(trial, best + 1e-9);
      if (w > best + 1e-9) best = w, bestAt = trial;
    }
    if (bestAt == at) step *= 0.5;
    at = bestAt;
  }
  const Vec3 placed = project(at);
  if (score(placed) > before + kMinGain) q.nodes[node] = placed;
}

// Eight directions in the tangent plane of the quads around an interior node.
std::vector<Vec3> tangentDirections(const QuadMesh& q, const NodeQuads& nq, int node) {
  Vec3 n = Vec3::Zero();
  for (int k = nq.start[node]; k < nq.start[node + 1]; ++k) {
    const auto p = corners(q, nq.items[k], -1, Vec3::Zero());
    n += (p[2] - p[0]).cross(p[3] - p[1]);
  }
  if (n.norm() == 0) return {};
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.normalized().cross(t1);
  std::vector<Vec3> dirs;
  for (int d = 0; d < 8; ++d) dirs.push_back(std::cos(d * M_PI / 4) * t1 + std::sin(d * M_PI / 4) * t2);
  return dirs;
}

// Index of v in the quad, -1 if absent.
int cornerOf(const std::array<int, 4>& quad, int v) {
  for (int k = 0; k < 4; ++k)
    if (quad[k] == v) return k;
  return -1;
}

// Visits the nodes in the sweep order (sweep_halves.hpp), `iterations` times, skipping those whose neighbourhood has
// not changed; update(node) returns whether it moved the node.
template <class Update>
void gaussSeidel(const QuadMesh& q, const NodeQuads& nq, const SweepHalves& order, int iterations, Update update) {
  MoveClock clock(q.nodes.size());
  const long n = static_cast<long>(q.nodes.size());
  for (int it = 0; it < iterations; ++it)
    sweepInHalves(order, [&](int node, int) {
      if (clock.unchanged(
              nq, [&](int quad) { return q.quads[quad]; }, node))
        return;
      const long t = it * n + order.position[node];
      clock.visit(node, t);
      if (update(node)) clock.moved(node, t);
    });
}

}  // namespace

int removeDoublets(QuadMesh& q) {
  int removed = 0;
  for (bool again = true; again;) {
    again = false;
    const NodeQuads nq = quadsAroundNodes(q);
    const std::vector<std::array<int, 2>> rim = rimNeighbours(q);
    std::vector<char> dead(q.quads.size(), 0);
    for (size_t n = 0; n < q.nodes.size(); ++n) {
      if (rim[n][0] != -1 || nq.start[n + 1] - nq.start[n] != 2) continue;
      const int A = nq.items[nq.start[n]], B = nq.items[nq.start[n] + 1];
      if (dead[A] || dead[B]) continue;
      // A = (n, a, x, b) and B = (n, b, y, a) share the edges n-a and n-b: they become (a, x, b, y).
      const int ka = cornerOf(q.quads[A], static_cast<int>(n)), kb = cornerOf(q.quads[B], static_cast<int>(n));
      const int a = q.quads[A][(ka + 1) % 4], x = q.quads[A][(ka + 2) % 4], b = q.quads[A][(ka + 3) % 4];
      const int y = q.quads[B][(kb + 2) % 4];
      if (q.quads[B][(kb + 1) % 4] != b || q.quads[B][(kb + 3) % 4] != a) continue;
      q.quads[A] = {a, x, b, y};
      dead[B] = 1;
      ++removed, again = true;
    }
    std::vector<std::array<int, 4>> alive;
    for (size_t e = 0; e < q.quads.size(); ++e)
      if (!dead[e]) alive.push_back(q.quads[e]);
    q.quads.swap(alive);
  }
  dropUnusedNodes(q.nodes, q.quads);
  return removed;
}

void dropUnusedNodes(std::vector<Vec3>& nodes, std::vector<std::array<int, 4>>& quads) {
  std::vector<int> newIndex(nodes.size(), -1);
  std::vector<Vec3> kept;
  for (const auto& quad : quads)
    for (int v : quad) newIndex[v] = -2;  // used
  for (size_t i = 0; i < nodes.size(); ++i)
    if (newIndex[i] == -2) newIndex[i] = static_cast<int>(kept.size()), kept.push_back(nodes[i]);
  for (auto& quad : quads)
    for (int& v : quad) v = newIndex[v];
  nodes.swap(kept);
}

void smoothQuadMesh(QuadMesh& q, const ChordalLocator& chordal, int iterations, bool slideRim,
                    const std::vector<char>& fixed) {
  const auto stays = [&](int node) { return !fixed.empty() && fixed[node]; };
  const NodeQuads nq = quadsAroundNodes(q);
  const std::vector<std::array<int, 2>> rim = rimNeighbours(q);
  const std::vector<Vec3> rimStart = q.nodes;  // rim nodes slide along the rim as Gmsh placed it
  // the sweeps cut in two through the nodes of poor quads
  const SweepHalves order = sweepHalves(
      q.nodes, [&](int node) { return worstAround(q, nq, node, q.nodes[node]) < kGoodQuad; }, nq,
      [&](int quad) { return q.quads[quad]; });
  std::vector<int> facet(q.nodes.size(), -1);  // the chordal facet a node was last put on: where to look first
  auto locate = [&](int node, const Vec3& p) {
    const ChordalPoint at = chordal.locate(p, facet[node]);
    facet[node] = at.facet;
    return at.point;
  };
  gaussSeidel(q, nq, order, iterations, [&](int node) {
    if (rim[node][0] != -1 || stays(node)) return false;
    const double before = worstAround(q, nq, node, q.nodes[node]);
    if (before >= kGoodQuad) return false;  // its quads are square already (a structured grid's)
    const Vec3 target = locate(node, centroidTarget(q, nq, node));
    if (!(worstAround(q, nq, node, target) >= std::min(before, 0.999)) || target == q.nodes[node]) return false;
    q.nodes[node] = target;
    return true;
  });
  // Then the nodes of poor quads are moved to make the worst quad around them as good as can be.
  gaussSeidel(q, nq, order, iterations, [&](int node) {
    const Vec3 from = q.nodes[node];
    if (rim[node][0] == -2 || (!slideRim && rim[node][0] != -1) || stays(node) ||
        worstAround(q, nq, node, from) >= kGoodQuad)
      return false;
    if (rim[node][0] == -1) {
      improveWorst(q, nq, node, tangentDirections(q, nq, node), [&](const Vec3& p) { return locate(node, p); });
      return q.nodes[node] != from;
    }
    const Vec3 a = rimStart[rim[node][0]], b = rimStart[node], c = rimStart[rim[node][1]];
    const Vec3 t = (c - a).normalized();
    improveWorst(q, nq, node, {t, -t}, [&](const Vec3& p) {
      const Vec3 x = closestOnSegment(a, b, p), y = closestOnSegment(b, c, p);
      return (x - p).squaredNorm() < (y - p).squaredNorm() ? x : y;
    });
    return q.nodes[node] != from;
  });
}

}  // namespace hexlayer
