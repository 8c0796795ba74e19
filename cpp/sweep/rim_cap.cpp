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
#include "geometry/wall_rays.hpp"
#include "quality/quality.hpp"
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

// How many columns a cap has: enough for kMinChords chords across a half-round profile (its outermost column's
// layers + 1 nodes and two nodes more per column on the profile), at least one.
int capRows(int layers) { return std::max(1, (kMinChords - layers + 1) / 2); }

// The nodes on the profile: m - 1 of them at even arc lengths for m = layers + 2 rows chords.
std::vector<Vec3> profileNodes(const Profile& p, int layers, int rows) {
  const int m = layers + 2 * rows;
  std::vector<Vec3> nodes;
  for (int i = 1; i < m; ++i) nodes.push_back(atArcLength(p.points, static_cast<double>(i) / m));
  return nodes;
}

// The profile area the hexes leave out: a column of layers + 1 nodes at even heights on the profile (the rim
// projection's), or a cap of `rows` columns (all its nodes on the profile at even arc lengths).
double leftOut(const Profile& p, int layers, int rows) {
  std::vector<Vec3> polygon{p.points.front()};
  if (rows > 0) {
    const std::vector<Vec3> c = profileNodes(p, layers, rows);
    polygon.insert(polygon.end(), c.begin(), c.end());
  } else {
    for (int k = 1; k < layers; ++k) polygon.push_back(atHeight(p, p.h * (2.0 * k / layers - 1)));
  }
  polygon.push_back(p.points.back());
  return areaBeyondChord(p, p.points) - areaBeyondChord(p, polygon);
}

// One edge of the chordal surface's rim: two rim columns, a before b in the hexes' bottom quads, the outward
// normal of the side faces along it, and the hexes' nodes per layer.
struct RimEdge {
  int a = -1, b = -1;
  Vec3 outward = Vec3::Zero();
  bool capped = false;
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

// Per column, the cap's columns of layers + 1 nodes (none: not capped), laid on the profile along the mean
// outward normal of its capped edges, inside out. The outermost on the profile at even arc lengths; each
// other one with its ends on the profile (outside in: the nodes next to the outermost's) and its inner nodes
// between the sweep's column (straight) and the outermost's, evenly. Nodes on the profile moved onto the
// lateral faces.
using Cap = std::vector<std::vector<FacePoint>>;

Cap layCap(WallRays& rays, const WallProjector& walls, const Column& c, const Vec3& outward, int layers, int rows) {
  const Profile p = rimProfile(rays, c.bottom, c.top, outward);
  if (p.points.size() < 3) return {};
  auto onRim = [&](const Vec3& x) {
    std::optional<FacePoint> on = walls.project(Side::Lateral, x);
    return on && (on->point - x).norm() <= kMaxSnap * p.h ? *on : FacePoint{x, -1};
  };
  const std::vector<Vec3> around = profileNodes(p, layers, rows);  // m - 1 nodes, bottom to top
  const int m = layers + 2 * rows;
  Cap cap(rows, std::vector<FacePoint>(layers + 1));
  for (int k = 0; k <= layers; ++k) cap[rows - 1][k] = onRim(around[rows - 1 + k]);
  for (int j = 1; j < rows; ++j) {
    cap[j - 1][0] = onRim(around[j - 1]), cap[j - 1][layers] = onRim(around[m - 1 - j]);
    for (int k = 1; k < layers; ++k) {
      const Vec3 straight = c.bottom + (static_cast<double>(k) / layers) * (c.top - c.bottom);
      cap[j - 1][k] = {straight + (static_cast<double>(j) / rows) * (cap[rows - 1][k].point - straight), -1};
    }
  }
  return cap;
}

// A cap beside a rim edge without one (where a round end meets a flat side face): its side face lies on that
// face, the column it stands on too, and the cap's nodes on the profile on the CAD edge between that face and
// the profile's; alternate projections put them on both, and on that face for the grouping of the side face.
// [in] side: that face (lateralFaceOf the column); [in,out] cap.
void onSideFace(const WallProjector& walls, int side, Cap& cap) {
  for (auto& row : cap)
    for (FacePoint& x : row) {
      if (x.face < 0) continue;
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

// The hex of layer k between two columns of an edge, a before b, and the columns beyond them.
std::array<int, 8> capHex(const std::vector<int>& a, const std::vector<int>& b, const std::vector<int>& capA,
                          const std::vector<int>& capB, int k) {
  return {b[k], a[k], capA[k], capB[k], b[k + 1], a[k + 1], capA[k + 1], capB[k + 1]};
}

// The columns of one rim column by position: the sweep's, straight, then its cap's.
std::vector<std::vector<Vec3>> capColumns(const Column& c, const Cap& cap, int layers) {
  std::vector<std::vector<Vec3>> out(1);
  for (int k = 0; k <= layers; ++k) out[0].push_back(c.bottom + (static_cast<double>(k) / layers) * (c.top - c.bottom));
  for (const auto& row : cap) {
    out.emplace_back();
    for (const FacePoint& x : row) out.back().push_back(x.point);
  }
  return out;
}

// The scaled Jacobian of the worst hex of edge e's cap.
double worstCapHex(const HexMesh& mesh, const std::vector<std::vector<int>>& columns, const std::vector<Cap>& caps,
                   const RimEdge& e, int layers) {
  const auto a = capColumns(ends(mesh, columns[e.a]), caps[e.a], layers);
  const auto b = capColumns(ends(mesh, columns[e.b]), caps[e.b], layers);
  double worst = 1;
  for (std::size_t j = 1; j < a.size(); ++j)
    for (int k = 0; k < layers; ++k)
      worst = std::min(worst, hexScaledJacobian({b[j - 1][k], a[j - 1][k], a[j][k], b[j][k], b[j - 1][k + 1],
                                                 a[j - 1][k + 1], a[j][k + 1], b[j][k + 1]}));
  return worst;
}

}  // namespace

RimCapStats capRims(HexMesh& mesh, const CadSolid& cad, const WallSides& sides, const WallProjector& walls) {
  RimCapStats stats;
  const int layers = mesh.layers;
  const std::vector<std::vector<int>> columns = rimColumns(mesh);
  std::vector<int> columnOf(mesh.nodes.size(), -1);
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (int v : columns[c]) columnOf[v] = static_cast<int>(c);
  std::vector<RimEdge> edges = rimEdges(mesh, columns, columnOf);
  stats.rimEdges = edges.size();
  std::deque<WallRays> rays;
  for (int t = 0; t < threadCount(); ++t) rays.emplace_back(cad, sides);
  const int rows = capRows(layers);
// Which edges lose enough of their profile for a cap to be worth it: their profile at their middle.
#pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(edges.size()); ++i) {
    RimEdge& e = edges[i];
    const Column a = ends(mesh, columns[e.a]), b = ends(mesh, columns[e.b]);
    const Profile p = rimProfile(rays[threadIndex()], 0.5 * (a.bottom + b.bottom), 0.5 * (a.top + b.top), e.outward);
    if (p.points.size() < 3 || !inside(walls, p)) continue;
    const double uncapped = leftOut(p, layers, 0), capped = leftOut(p, layers, rows);
    e.capped = uncapped > kMinLoss * 4 * p.h * p.h && capped <= kGain * uncapped;
  }
  // The caps of the columns of capped edges, laid along their capped edges' mean normal; edges whose cap has
  // a poor hex are dropped and the caps laid again, until none has.
  std::vector<Cap> caps(columns.size());
  for (bool dropped = true; dropped;) {  // ends: every round drops an edge or none
    std::vector<Vec3> outward(columns.size(), Vec3::Zero()), along(columns.size(), Vec3::Zero());
    for (const RimEdge& e : edges) {
      if (!e.capped) continue;
      outward[e.a] += e.outward.normalized(), outward[e.b] += e.outward.normalized();
      const Vec3 ab = (middle(ends(mesh, columns[e.b])) - middle(ends(mesh, columns[e.a]))).normalized();
      along[e.a] += ab, along[e.b] -= ab;  // cancels where both edges are capped
    }
#pragma omp parallel for schedule(static)
    for (long c = 0; c < static_cast<long>(columns.size()); ++c)
      caps[c] = outward[c].norm() > 0 ? layCap(rays[threadIndex()], walls, nudged(ends(mesh, columns[c]), along[c]),
                                               outward[c], layers, rows)
                                      : Cap{};
    dropped = false;
    for (RimEdge& e : edges)
      if (e.capped &&
          (caps[e.a].empty() || caps[e.b].empty() || worstCapHex(mesh, columns, caps, e, layers) < kMinQuality))
        e.capped = false, dropped = true;
    // A cap may end only where its side face lies on the CAD (a round end meeting a flat side face).
    std::vector<int> rimAt(columns.size(), 0), cappedAt(columns.size(), 0);
    for (const RimEdge& e : edges) ++rimAt[e.a], ++rimAt[e.b], cappedAt[e.a] += e.capped, cappedAt[e.b] += e.capped;
    for (RimEdge& e : edges)
      for (const int c : {e.a, e.b})
        if (e.capped && cappedAt[c] < rimAt[c] && !lateralFaceOf(walls, ends(mesh, columns[c])))
          e.capped = false, dropped = true;
  }
  // The capped columns: inner nodes back on the straight line, then the caps' nodes and hexes. Inner nodes are
  // inside the part, unless the column has an edge without a cap: then its cap's side face is on the boundary.
  std::vector<int> rimEdgesAt(columns.size(), 0), cappedAt(columns.size(), 0);
  for (const RimEdge& e : edges) {
    ++rimEdgesAt[e.a], ++rimEdgesAt[e.b];
    if (e.capped) ++cappedAt[e.a], ++cappedAt[e.b], ++stats.cappedEdges;
  }
  std::vector<std::vector<std::vector<int>>> ids(columns.size());  // per column: the sweep's, then the cap's
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (cappedAt[c] == 0) continue;
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
    if (const std::optional<int> face = side ? lateralFaceOf(walls, end) : std::nullopt)
      onSideFace(walls, *face, caps[c]);
    ids[c].push_back(columns[c]);
    for (std::size_t j = 0; j < caps[c].size(); ++j) {
      ids[c].emplace_back();
      for (int k = 0; k <= layers; ++k) {
        const int v = static_cast<int>(mesh.nodes.size());
        ids[c].back().push_back(v);
        mesh.nodes.push_back(caps[c][j][k].point);
        mesh.nodeLayer.push_back(k);
        mesh.nodeOnRim.push_back(kRimCap);
        mesh.nodeFace.push_back(caps[c][j][k].face);
        if (j + 1 < caps[c].size() && k > 0 && k < layers) inner(v, caps[c][j][k].point, kRimCap);
      }
    }
    ++stats.capColumns;
  }
  for (const RimEdge& e : edges) {
    if (!e.capped) continue;
    for (std::size_t j = 1; j < ids[e.a].size(); ++j)
      for (int k = 0; k < layers; ++k)
        mesh.hexes.push_back(capHex(ids[e.a][j - 1], ids[e.b][j - 1], ids[e.a][j], ids[e.b][j], k));
    stats.capHexes += layers * rows;
  }
  return stats;
}

}  // namespace hexlayer
