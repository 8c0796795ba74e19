#include "sweep/rim_cap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/threads.hpp"
#include "core/union_find.hpp"
#include "geometry/wall_rays.hpp"
#include "quality/quality.hpp"
#include "sweep/cap_template.hpp"
#include "sweep/rim_projection.hpp"

namespace hexlayer {
namespace {

constexpr int kProfileRays = 32;     // rays across a rim's profile, between its two edges
constexpr double kReach = 3;         // how far the rays reach, in half-heights of the column ...
constexpr double kSkip = 0.05;       // ... past the faces they start on (a column on a side face)
constexpr double kInside = 0.25;     // an edge's profile is cast from at least this far inside the rim
constexpr double kMinLoss = 0.02;    // cap a rim whose hexes leave out more than this share of (2 h)^2 ...
constexpr double kGain = 0.5;        // ... if the cap leaves out at most this share of it
constexpr double kMinQuality = 0.3;  // every cap hex at least this scaled Jacobian
constexpr int kMinChords = 4;        // a cap's columns cut a half-round profile with at least this many chords
constexpr double kOnFace = 1e-3;     // a column this many half-heights from a lateral face lies on it
constexpr double kNudge = 1e-3;      // a side face's profile is cast this many half-heights inside it
constexpr int kEdgeProjections = 8;  // alternate projections onto two faces that put a node on their edge
constexpr double kMaxSnap = 0.1;     // a point is moved onto the lateral faces by at most this share of h

// A rim's profile in the plane through a column's middle spanned by the rim's outward direction and the
// column: the column's bottom end, where rays from the middle leave through a lateral face, its top end.
struct Profile {
  Vec3 origin, outward, up;  // up: unit, bottom to top
  double h = 0;              // half the column's length
  std::vector<Vec3> points;
};

Profile rimProfile(WallRays& rays, const Vec3& bottom, const Vec3& top, const Vec3& outward) {
  Profile p{0.5 * (bottom + top), outward, top - bottom, 0.5 * (top - bottom).norm(), {bottom}};
  if (p.h <= 0) return p;
  p.up /= 2 * p.h;
  p.outward -= p.outward.dot(p.up) * p.up;
  if (p.outward.norm() == 0) return p;
  p.outward.normalize();
  for (int i = 1; i < kProfileRays; ++i) {
    const double phi = M_PI * (static_cast<double>(i) / kProfileRays - 0.5);  // -90 .. 90 degrees from outward
    const Vec3 dir = std::cos(phi) * p.outward + std::sin(phi) * p.up;
    if (std::optional<FacePoint> hit = rays.cast(Side::Lateral, p.origin, dir, kReach * p.h, false, kSkip * p.h))
      p.points.push_back(hit->point);
  }
  p.points.push_back(top);
  return p;
}

// Whether the profile's rays start inside the part, kInside half-heights from the rim (on a flat rim they start
// on it, and would find the far side of a slot).
bool inside(const WallProjector& walls, const Profile& p) {
  const std::optional<FacePoint> rim = walls.project(Side::Lateral, p.origin);
  return rim && (rim->point - p.origin).norm() >= kInside * p.h;
}

// Signed area between the chord (bottom to top end) and the polyline bottom, points..., top in the profile's
// plane: positive where it bulges outward.
double areaBeyondChord(const Profile& p, const std::vector<Vec3>& polyline) {
  double area = 0;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Vec3 a = polyline[i] - p.origin, b = polyline[i + 1] - p.origin;
    area += 0.5 * (a.dot(p.outward) * b.dot(p.up) - a.dot(p.up) * b.dot(p.outward));
  }
  return area;
}

// The point at `fraction` of the polyline's length.
Vec3 atArcLength(const std::vector<Vec3>& polyline, double fraction) {
  double total = 0;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) total += (polyline[i + 1] - polyline[i]).norm();
  double left = fraction * total;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const double step = (polyline[i + 1] - polyline[i]).norm();
    if (left <= step && step > 0) return polyline[i] + (left / step) * (polyline[i + 1] - polyline[i]);
    left -= step;
  }
  return polyline.back();
}

// The outermost point of the polyline at height y (along `up` from the origin), else the origin's.
Vec3 atHeight(const Profile& p, double y) {
  std::optional<Vec3> best;
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    const double ya = (p.points[i] - p.origin).dot(p.up), yb = (p.points[i + 1] - p.origin).dot(p.up);
    if ((y - ya) * (y - yb) > 0 || ya == yb) continue;
    const Vec3 x = p.points[i] + (y - ya) / (yb - ya) * (p.points[i + 1] - p.points[i]);
    if (!best || (x - p.origin).dot(p.outward) > (*best - p.origin).dot(p.outward)) best = x;
  }
  return best ? *best : p.origin + y * p.up;
}

// How many columns a structured cap has (cap_template.hpp, for layer counts without a drawn template): enough
// for kMinChords chords across a half-round profile (its outermost column's layers + 1 nodes and two nodes more
// per column on the profile), at least one.
int capRows(int layers) { return std::max(1, (kMinChords - layers + 1) / 2); }

// The nodes a cap lays on the profile: at the template's fractions of its arc length.
std::vector<Vec3> profileNodes(const Profile& p, const CapTemplate& t) {
  std::vector<Vec3> nodes;
  for (double f : t.onProfile) nodes.push_back(atArcLength(p.points, f));
  return nodes;
}

// The profile area the hexes leave out: the polygon from the profile's bottom through `nodes` to its top.
double leftOut(const Profile& p, const std::vector<Vec3>& nodes) {
  std::vector<Vec3> polygon{p.points.front()};
  polygon.insert(polygon.end(), nodes.begin(), nodes.end());
  polygon.push_back(p.points.back());
  return areaBeyondChord(p, p.points) - areaBeyondChord(p, polygon);
}

// The uncapped column's nodes on the profile: layers + 1 at even heights (the rim projection's).
std::vector<Vec3> sweptNodes(const Profile& p, int layers) {
  std::vector<Vec3> nodes;
  for (int k = 1; k < layers; ++k) nodes.push_back(atHeight(p, p.h * (2.0 * k / layers - 1)));
  return nodes;
}

// One edge of the chordal surface's rim: two rim columns, a before b in the hexes' bottom quads, and the
// outward normal of the side faces along it.
struct RimEdge {
  int a = -1, b = -1;
  Vec3 outward = Vec3::Zero();
};

struct Column {
  Vec3 bottom, top;
};

Column ends(const HexMesh& mesh, const std::vector<int>& column) {
  return {mesh.nodes[column.front()], mesh.nodes[column.back()]};
}

Vec3 middle(const Column& c) { return 0.5 * (c.bottom + c.top); }

// A column beside a rim edge without a cap lies on a side face (a round end meeting a flat side): its profile
// is cast from a little inside, towards its capped edge, so that no ray runs along that face.
Column nudged(Column c, const Vec3& towardsCapped) {
  if (towardsCapped.norm() < 0.5) return c;  // capped on both sides
  const Vec3 shift = kNudge * 0.5 * (c.top - c.bottom).norm() * towardsCapped.normalized();
  return {c.bottom + shift, c.top + shift};
}

// The lateral face a column's straight line lies on (its middle within kOnFace half-heights of it), if any.
std::optional<int> lateralFaceOf(const WallProjector& walls, const Column& c) {
  const std::optional<FacePoint> on = walls.project(Side::Lateral, middle(c));
  if (!on || (on->point - middle(c)).norm() > kOnFace * 0.5 * (c.top - c.bottom).norm()) return std::nullopt;
  return on->face;
}

// The rim's edges, each with its outward normal: normal to the edge and to its columns' straight lines (the
// rim projection has bent them), on the side its side faces face.
std::vector<RimEdge> rimEdges(const HexMesh& mesh, const std::vector<std::vector<int>>& columns,
                              const std::vector<int>& columnOf) {
  std::map<std::pair<int, int>, RimEdge> edges;  // ordered: the same caps whatever the hash
  for (const BoundaryFace& f : boundaryFaces(mesh)) {
    if (f.localFace < 2) continue;
    const auto& hex = mesh.hexes[f.hex];
    const int a = columnOf[hex[f.localFace - 2]], b = columnOf[hex[(f.localFace - 1) % 4]];
    if (a < 0 || b < 0) continue;
    RimEdge& e = edges[{a, b}];
    e.a = a, e.b = b;
    const auto& x = mesh.nodes;
    e.outward += 0.5 * (x[f.nodes[2]] - x[f.nodes[0]]).cross(x[f.nodes[3]] - x[f.nodes[1]]);
  }
  std::vector<RimEdge> out;
  for (auto& [key, e] : edges) {
    const Column a = ends(mesh, columns[e.a]), b = ends(mesh, columns[e.b]);
    const Vec3 along = 0.5 * (b.bottom + b.top - a.bottom - a.top), up = a.top - a.bottom + b.top - b.bottom;
    const Vec3 normal = along.cross(up);
    if (normal.norm() > 0) e.outward = normal.dot(e.outward) >= 0 ? normal : Vec3(-normal);
    out.push_back(e);
  }
  return out;
}

// A cap's place on one column: its template (cap_template.hpp) and the weights that lay the inside nodes.
struct CapLayout {
  CapTemplate t;
  std::vector<std::vector<double>> weights;  // insideWeights(t)
};

// The cap layouts tried on a part of `layers` layers: the drawn template (if any) and the structured cap.
std::vector<CapLayout> capLayouts(int layers) {
  std::vector<CapTemplate> templates{structuredCap(layers, capRows(layers))};
  if (std::optional<CapTemplate> drawn = drawnCap(layers)) templates.push_back(*drawn);
  std::vector<CapLayout> layouts;
  for (CapTemplate& t : templates) layouts.push_back({t, insideWeights(t)});
  return layouts;
}

// Per column, its cap's nodes beyond the column (none: not capped), laid on the profile along the mean outward
// normal of its capped edges: the template's profile nodes at their fractions of the profile's arc length (moved
// onto the lateral faces), then its inside nodes at their mean value coordinates in the polygon of the straight
// column and the profile nodes.
using Cap = std::vector<FacePoint>;

Cap layCap(WallRays& rays, const WallProjector& walls, const Column& c, const Vec3& outward, const CapLayout& layout) {
  const Profile p = rimProfile(rays, c.bottom, c.top, outward);
  if (p.points.size() < 3) return {};
  auto onRim = [&](const Vec3& x) {
    std::optional<FacePoint> on = walls.project(Side::Lateral, x);
    return on && (on->point - x).norm() <= kMaxSnap * p.h ? *on : FacePoint{x, -1};
  };
  const CapTemplate& t = layout.t;
  const std::vector<Vec3> around = profileNodes(p, t);
  Cap cap;
  for (const Vec3& x : around) cap.push_back(onRim(x));
  std::vector<Vec3> boundary;
  for (const int node : templateBoundary(t))
    boundary.push_back(node <= t.layers ? Vec3(c.bottom + (static_cast<double>(node) / t.layers) * (c.top - c.bottom))
                                        : around[node - t.layers - 1]);
  for (const std::vector<double>& w : layout.weights) {
    Vec3 x = Vec3::Zero();
    for (std::size_t i = 0; i < w.size(); ++i) x += w[i] * boundary[i];
    cap.push_back({x, -1});
  }
  return cap;
}

// A cap beside a rim edge without one (where a round end meets a flat side face): its side face lies on that
// face, the column it stands on too, and the cap's nodes on the profile on the CAD edge between that face and
// the profile's; alternate projections put them on both, and on that face for the grouping of the side face.
// [in] side: that face (lateralFaceOf the column); [in,out] cap.
void onSideFace(const WallProjector& walls, int side, Cap& cap) {
  for (FacePoint& x : cap) {
    if (x.face < 0) continue;  // inside
    const int profileFace = x.face;
    for (int i = 0; i < kEdgeProjections; ++i) {
      const std::optional<FacePoint> a = walls.projectOntoFace(side, x.point);
      const std::optional<FacePoint> b = a ? walls.projectOntoFace(profileFace, a->point) : std::nullopt;
      if (!b) break;
      x.point = b->point;
    }
    x.face = side;
  }
}

// The hex of template quad q between two columns of an edge, a before b (their node ids or places per template
// node): the quad's edges q0 -> q1 and q3 -> q2 are its sweep edges.
template <class T>
std::array<T, 8> capHex(const std::vector<T>& a, const std::vector<T>& b, const std::array<int, 4>& q) {
  return {b[q[0]], a[q[0]], a[q[3]], b[q[3]], b[q[1]], a[q[1]], a[q[2]], b[q[2]]};
}

// A rim column's places per template node: the sweep's column, straight, then its cap's.
std::vector<Vec3> capPlaces(const Column& c, const Cap& cap, int layers) {
  std::vector<Vec3> out;
  for (int k = 0; k <= layers; ++k) out.push_back(c.bottom + (static_cast<double>(k) / layers) * (c.top - c.bottom));
  for (const FacePoint& x : cap) out.push_back(x.point);
  return out;
}

// The scaled Jacobians of edge e's cap hexes.
std::vector<double> capQualities(const HexMesh& mesh, const std::vector<std::vector<int>>& columns,
                                 const std::vector<Cap>& caps, const RimEdge& e, const CapTemplate& t) {
  const std::vector<Vec3> a = capPlaces(ends(mesh, columns[e.a]), caps[e.a], t.layers);
  const std::vector<Vec3> b = capPlaces(ends(mesh, columns[e.b]), caps[e.b], t.layers);
  std::vector<double> sj;
  for (const auto& q : t.quads) sj.push_back(hexScaledJacobian(capHex(a, b, q)));
  return sj;
}

// Where one cap layout would cap: per edge whether capped, per column its cap (empty: none).
struct CapPlan {
  std::vector<char> capped;
  std::vector<Cap> caps;
};

// The rim's profile at the middle of each rim edge, where it has three points or more inside the walls (else none):
// the same for every layout. [in] mesh, columns, edges; [in,out] rays: per thread; [in] walls.
std::vector<std::optional<Profile>> edgeProfiles(const HexMesh& mesh, const std::vector<std::vector<int>>& columns,
                                                 const std::vector<RimEdge>& edges, std::deque<WallRays>& rays,
                                                 const WallProjector& walls) {
  std::vector<std::optional<Profile>> profiles(edges.size());
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 8)
  for (long i = 0; i < static_cast<long>(edges.size()); ++i)
    errors.run([&] {
      const RimEdge& e = edges[i];
      const Column a = ends(mesh, columns[e.a]), b = ends(mesh, columns[e.b]);
      Profile p = rimProfile(rays[threadIndex()], 0.5 * (a.bottom + b.bottom), 0.5 * (a.top + b.top), e.outward);
      if (p.points.size() >= 3 && inside(walls, p)) profiles[i] = std::move(p);
    });
  errors.rethrow();
  return profiles;
}

// The rim's edges whose profile (at their middle: edgeProfiles) loses enough for a cap to be worth it with `layout`,
// and the caps of their columns, laid along their capped edges' mean normal; edges whose cap has a poor hex, or that
// would end a cap where its side face is not on the CAD, are dropped and the caps laid again, until none is.
CapPlan planCaps(const HexMesh& mesh, const std::vector<std::vector<int>>& columns, const std::vector<RimEdge>& edges,
                 const std::vector<std::optional<Profile>>& profiles, const CapLayout& layout,
                 std::deque<WallRays>& rays, const WallProjector& walls) {
  CapPlan plan{std::vector<char>(edges.size(), 0), std::vector<Cap>(columns.size())};
  ParallelErrors errors;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(edges.size()); ++i)
    errors.run([&] {
      if (!profiles[i]) return;
      const Profile& p = *profiles[i];
      const double uncapped = leftOut(p, sweptNodes(p, layout.t.layers)),
                   capped = leftOut(p, profileNodes(p, layout.t));
      plan.capped[i] = uncapped > kMinLoss * 4 * p.h * p.h && capped <= kGain * uncapped;
    });
  errors.rethrow();
  for (bool dropped = true; dropped;) {  // ends: every round drops an edge or none
    std::vector<Vec3> outward(columns.size(), Vec3::Zero()), along(columns.size(), Vec3::Zero());
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (!plan.capped[i]) continue;
      const RimEdge& e = edges[i];
      outward[e.a] += e.outward.normalized(), outward[e.b] += e.outward.normalized();
      const Vec3 ab = (middle(ends(mesh, columns[e.b])) - middle(ends(mesh, columns[e.a]))).normalized();
      along[e.a] += ab, along[e.b] -= ab;  // cancels where both edges are capped
    }
#pragma omp parallel for schedule(dynamic, 8)
    for (long c = 0; c < static_cast<long>(columns.size()); ++c)
      errors.run([&] {
        plan.caps[c] = outward[c].norm() > 0 ? layCap(rays[threadIndex()], walls,
                                                      nudged(ends(mesh, columns[c]), along[c]), outward[c], layout)
                                             : Cap{};
      });
    errors.rethrow();
    auto poor = [&](const RimEdge& e) {
      if (plan.caps[e.a].empty() || plan.caps[e.b].empty()) return true;
      const std::vector<double> sj = capQualities(mesh, columns, plan.caps, e, layout.t);
      return *std::min_element(sj.begin(), sj.end()) < kMinQuality;
    };
    dropped = false;
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (plan.capped[i] && poor(edges[i])) plan.capped[i] = false, dropped = true;
    // A cap may end only where its side face lies on the CAD (a round end meeting a flat side face).
    std::vector<int> rimAt(columns.size(), 0), cappedAt(columns.size(), 0);
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (const int c : {edges[i].a, edges[i].b}) ++rimAt[c], cappedAt[c] += plan.capped[i];
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (const int c : {edges[i].a, edges[i].b})
        if (plan.capped[i] && cappedAt[c] < rimAt[c] && !lateralFaceOf(walls, ends(mesh, columns[c])))
          plan.capped[i] = false, dropped = true;
  }
  return plan;
}

// The sum of 1 - scaled Jacobian over `hexes` with the inner nodes of the columns in `straight` on their straight
// line (as capping puts them).
double sweptDeficit(const HexMesh& mesh, const std::vector<std::vector<int>>& columns, const std::vector<int>& hexes,
                    const std::vector<int>& straight) {
  std::map<int, Vec3> moved;
  for (const int c : straight) {
    const Column end = ends(mesh, columns[c]);
    const int layers = static_cast<int>(columns[c].size()) - 1;
    for (int k = 1; k < layers; ++k)
      moved[columns[c][k]] = end.bottom + (static_cast<double>(k) / layers) * (end.top - end.bottom);
  }
  double deficit = 0;
  for (const int h : hexes) {
    std::array<Vec3, 8> x = hexCorners(mesh, h);
    for (int i = 0; i < 8; ++i)
      if (const auto it = moved.find(mesh.hexes[h][i]); it != moved.end()) x[i] = it->second;
    deficit += 1 - hexScaledJacobian(x);
  }
  return deficit;
}

// Per column, which plan caps it (-1: none). The edges capped in any plan, joined at their columns, make chains;
// each chain is capped as the first plan (the structured cap, the old way: capped where it is worth it, else
// not) unless a later one leaves the mesh's mean scaled Jacobian higher: its cap hexes added, the sweep's hexes
// at its capped columns straightened. Chains in the order of their first column, each counted into the mean.
std::vector<int> choosePlans(const HexMesh& mesh, const std::vector<std::vector<int>>& columns,
                             const std::vector<RimEdge>& edges, const std::vector<CapPlan>& plans,
                             const std::vector<CapLayout>& layouts) {
  std::vector<int> plan(columns.size(), -1);
  if (plans.size() == 1) {  // nothing to choose: the plan caps every column of its capped edges
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (plans[0].capped[i]) plan[edges[i].a] = plan[edges[i].b] = 0;
    return plan;
  }
  UnionFind chains(columns.size());
  std::vector<char> inChain(columns.size(), 0);
  for (const CapPlan& plan : plans)
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (plan.capped[i]) chains.unite(edges[i].a, edges[i].b), inChain[edges[i].a] = inChain[edges[i].b] = 1;
  // Per chain root: per plan its cap hexes' deficit and count and the columns it caps; the sweep's hexes at it.
  struct Option {
    double deficit = 0;
    std::size_t hexes = 0;
    std::vector<int> columns;
  };
  struct Chain {
    std::vector<Option> options;
    std::vector<int> hexes;
  };
  std::map<int, Chain> chainAt;
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t k = 0; k < plans.size(); ++k) {
      if (!plans[k].capped[i]) continue;
      std::vector<Option>& options = chainAt[chains.find(edges[i].a)].options;
      options.resize(plans.size());
      Option& o = options[k];
      for (const double sj : capQualities(mesh, columns, plans[k].caps, edges[i], layouts[k].t))
        o.deficit += 1 - sj, ++o.hexes;
      o.columns.push_back(edges[i].a), o.columns.push_back(edges[i].b);
    }
  std::vector<int> columnOfNode(mesh.nodes.size(), -1);
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (inChain[c])
      for (const int v : columns[c]) columnOfNode[v] = static_cast<int>(c);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (const int v : mesh.hexes[h])
      if (columnOfNode[v] >= 0) {
        chainAt[chains.find(columnOfNode[v])].hexes.push_back(static_cast<int>(h));
        break;
      }
  if (chainAt.empty()) return plan;
  double deficit = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) deficit += 1 - hexScaledJacobian(hexCorners(mesh, h));
  double count = static_cast<double>(mesh.hexes.size());
  std::map<int, int> chosen;  // per chain root
  for (auto& [root, chain] : chainAt) {
    const double uncapped = sweptDeficit(mesh, columns, chain.hexes, {});
    int best = -1;
    double bestMean = 0, bestDeficit = 0, bestCount = 0;
    for (std::size_t k = 0; k < chain.options.size(); ++k) {
      Option& o = chain.options[k];
      if (o.hexes == 0 && k > 0) continue;  // a later plan that caps none of the chain
      std::sort(o.columns.begin(), o.columns.end());
      o.columns.erase(std::unique(o.columns.begin(), o.columns.end()), o.columns.end());
      const double d = deficit - uncapped + sweptDeficit(mesh, columns, chain.hexes, o.columns) + o.deficit;
      const double n = count + static_cast<double>(o.hexes);
      if (k == 0 || d / n < bestMean) best = static_cast<int>(k), bestMean = d / n, bestDeficit = d, bestCount = n;
    }
    chosen[root] = chain.options[best].hexes > 0 ? best : -1;
    deficit = bestDeficit, count = bestCount;
  }
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (inChain[c]) plan[c] = chosen.at(chains.find(static_cast<int>(c)));
  return plan;
}

}  // namespace

RimCapStats capRims(HexMesh& mesh, const CadSolid& cad, const WallSides& sides, const WallProjector& walls) {
  RimCapStats stats;
  const int layers = mesh.layers;
  const std::vector<std::vector<int>> columns = rimColumns(mesh);
  std::vector<int> columnOf(mesh.nodes.size(), -1);
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (int v : columns[c]) columnOf[v] = static_cast<int>(c);
  const std::vector<RimEdge> edges = rimEdges(mesh, columns, columnOf);
  stats.rimEdges = edges.size();
  std::deque<WallRays> rays;
  for (int t = 0; t < threadCount(); ++t) rays.emplace_back(cad, sides);
  const std::vector<CapLayout> layouts = capLayouts(layers);
  std::vector<CapPlan> plans;
  const std::vector<std::optional<Profile>> profiles = edgeProfiles(mesh, columns, edges, rays, walls);
  for (const CapLayout& layout : layouts)
    plans.push_back(planCaps(mesh, columns, edges, profiles, layout, rays, walls));
  const std::vector<int> planOf = choosePlans(mesh, columns, edges, plans, layouts);
  // The capped columns: inner nodes back on the straight line, then the caps' nodes and hexes. Inner nodes are
  // inside the part, unless the column has an edge without a cap: then its cap's side face is on the boundary.
  auto capped = [&](std::size_t i) {
    const int k = planOf[edges[i].a];
    return k >= 0 && plans[k].capped[i];
  };
  std::vector<int> rimEdgesAt(columns.size(), 0), cappedAt(columns.size(), 0);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    ++rimEdgesAt[edges[i].a], ++rimEdgesAt[edges[i].b];
    if (capped(i)) ++cappedAt[edges[i].a], ++cappedAt[edges[i].b], ++stats.cappedEdges;
  }
  std::vector<std::vector<int>> ids(columns.size());  // per column: its node per template node
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (cappedAt[c] == 0) continue;
    const CapTemplate& t = layouts[planOf[c]].t;
    Cap& cap = plans[planOf[c]].caps[c];
    const bool side = cappedAt[c] < rimEdgesAt[c];
    const Column end = ends(mesh, columns[c]);
    const double reach = kMaxSnap * 0.5 * (end.top - end.bottom).norm();
    auto inner = [&](int v, const Vec3& x, char onRim) {
      mesh.nodes[v] = x, mesh.nodeOnRim[v] = 0, mesh.nodeFace[v] = -1;
      if (!side) return;
      mesh.nodeOnRim[v] = onRim;
      const std::optional<FacePoint> on = walls.project(Side::Lateral, x);
      if (on && (on->point - x).norm() <= reach) mesh.nodes[v] = on->point, mesh.nodeFace[v] = on->face;
    };
    for (int k = 1; k < layers; ++k)
      inner(columns[c][k], end.bottom + (static_cast<double>(k) / layers) * (end.top - end.bottom), kRimSwept);
    if (const std::optional<int> face = side ? lateralFaceOf(walls, end) : std::nullopt) onSideFace(walls, *face, cap);
    ids[c] = columns[c];
    for (int node = layers + 1; node < t.nodeCount(); ++node) {
      const int v = static_cast<int>(mesh.nodes.size());
      const FacePoint& x = cap[node - layers - 1];
      ids[c].push_back(v);
      mesh.nodes.push_back(x.point);
      // a profile node in the layer nearest its height in the half disc; an inside node in none (-1)
      const bool onProfile = node < t.firstInside();
      mesh.nodeLayer.push_back(
          onProfile ? static_cast<int>(std::lround(0.5 * layers * (templatePosition(t, node).y() + 1))) : -1);
      mesh.nodeOnRim.push_back(kRimCap);
      mesh.nodeFace.push_back(x.face);
      if (!onProfile) inner(v, x.point, kRimCap);
    }
    ++stats.capColumns;
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!capped(i)) continue;
    const CapTemplate& t = layouts[planOf[edges[i].a]].t;
    for (const auto& q : t.quads) mesh.hexes.push_back(capHex(ids[edges[i].a], ids[edges[i].b], q));
    stats.capHexes += t.quads.size();
  }
  return stats;
}

}  // namespace hexlayer
