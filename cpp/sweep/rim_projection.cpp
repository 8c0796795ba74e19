#include "sweep/rim_projection.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <vector>

#include "core/groups.hpp"
#include "core/threads.hpp"
#include "geometry/wall_rays.hpp"
#include "quality/quality.hpp"
#include "sweep/sweep.hpp"

namespace hexlayer {
namespace {

constexpr double kSpoiled = 0.2;      // a hex below this scaled Jacobian that got worse is spoiled
constexpr double kMaxAlongRim = 0.5;  // share of a rim node's move that may run along the rim ...
constexpr double kFreeMove = 0.1;     // ... unless the move is shorter than this share of the reach
constexpr double kLean = 0.1;         // a rim column leans when its wall nodes move over this share of an edge beside
constexpr double kKeptEdge = 0.25;    // share of its length an edge along the wall keeps beside a leaning rim

// Per node, the sum of the outward normals (scaled by area) of the mesh's boundary side faces around it:
// at a rim node, the direction in which the rim faces outward.
std::vector<Vec3> sideFaceNormals(const HexMesh& mesh) {
  std::vector<Vec3> normal(mesh.nodes.size(), Vec3::Zero());
  for (const BoundaryFace& f : boundaryFaces(mesh)) {
    if (f.localFace < 2) continue;  // the bottom and top faces of the hexes lie on the walls
    const auto& x = mesh.nodes;
    const Vec3 n = 0.5 * (x[f.nodes[2]] - x[f.nodes[0]]).cross(x[f.nodes[3]] - x[f.nodes[1]]);
    for (int v : f.nodes) normal[v] += n;
  }
  return normal;
}

// The rim's directions at a column: outward (from the mesh's side faces) and along the rim (tangent).
struct RimFrame {
  Vec3 outward, tangent;
};

RimFrame rimFrame(const HexMesh& mesh, const std::vector<int>& column, const std::vector<Vec3>& sideNormals) {
  RimFrame frame{Vec3::Zero(), Vec3::Zero()};
  for (int v : column) frame.outward += sideNormals[v];
  const Vec3 sweep = mesh.nodes[column.back()] - mesh.nodes[column.front()];
  frame.outward -= frame.outward.dot(sweep) / std::max(sweep.squaredNorm(), 1e-300) * sweep;  // across the sweep line
  if (frame.outward.norm() > 0) frame.outward.normalize();
  frame.tangent = sweep.cross(frame.outward);
  if (frame.tangent.norm() > 0) frame.tangent.normalize();
  return frame;
}

// A move of a rim node to `to` within reach stays in the rim's cross-section: it may go outward and up or
// down the rim's profile, but not far along the rim (to the side faces of a part whose rim has no lateral
// face); a short move may go anywhere (onto a rim that twists, into a corner).
bool acrossRim(const RimFrame& frame, const Vec3& from, const std::optional<FacePoint>& to, double reach) {
  if (!to) return false;
  const Vec3 move = to->point - from;
  if (move.norm() > reach) return false;
  return move.norm() <= kFreeMove * reach || std::abs(move.dot(frame.tangent)) <= kMaxAlongRim * move.norm();
}

// The point of the lateral faces for p: along the rim's outward line through p if it meets one within
// reach, else the nearest one within reach if that lies across the rim.
std::optional<FacePoint> ontoRim(WallRays& rays, const WallProjector& walls, const Vec3& p, const RimFrame& frame,
                                 double reach) {
  if (frame.outward.squaredNorm() > 0)
    if (std::optional<FacePoint> hit = rays.nearestOnLine(Side::Lateral, p, frame.outward, reach)) return hit;
  std::optional<FacePoint> nearest = walls.project(Side::Lateral, p);
  if (acrossRim(frame, p, nearest, reach)) return nearest;
  return std::nullopt;
}

// The point of the `side` wall's edges on the lateral faces nearest to p, if within reach and across the
// rim, else ontoRim's.
std::optional<FacePoint> ontoWallEdge(Side side, WallRays& rays, const WallProjector& walls, const Vec3& p,
                                      const RimFrame& frame, double reach) {
  std::optional<FacePoint> edge = walls.projectOntoRimEdges(side, p);
  if (acrossRim(frame, p, edge, reach)) return edge;
  return ontoRim(rays, walls, p, frame, reach);
}

// Where the nodes of one rim column go (nullopt: where they are): the ends onto the edges where the walls
// meet the lateral faces, the nodes between them evenly spaced on the line joining the moved ends, then
// along the rim's outward line onto the lateral faces.
std::vector<std::optional<FacePoint>> layColumn(const HexMesh& mesh, const std::vector<int>& column,
                                                const RimFrame& frame, WallRays& rays, const WallProjector& walls,
                                                double reach) {
  const std::size_t m = column.size() - 1;
  std::vector<std::optional<FacePoint>> to(column.size());
  to[0] = ontoWallEdge(Side::Bottom, rays, walls, mesh.nodes[column[0]], frame, reach);
  to[m] = ontoWallEdge(Side::Top, rays, walls, mesh.nodes[column[m]], frame, reach);
  const Vec3 bottom = to[0] ? to[0]->point : mesh.nodes[column[0]], top = to[m] ? to[m]->point : mesh.nodes[column[m]];
  for (std::size_t k = 1; k < m; ++k)
    to[k] = ontoRim(rays, walls, bottom + (static_cast<double>(k) / m) * (top - bottom), frame, reach);
  return to;
}

// A sharp CAD edge where two lateral faces meet, running from the bottom wall to the top (the corner of two
// rims, or of a rim and a face cut across it): points at even arc lengths along it from its bottom end.
struct CornerEdge {
  std::vector<Vec3> points;
  int face = -1;  // one of its lateral faces, 0-based
};

constexpr int kCornerSamples = 64;

// The sharp CAD edges where two lateral faces meet, as CornerEdges (not yet oriented nor checked to join the walls).
std::vector<CornerEdge> cornerCandidates(const CadSolid& cad, const WallSides& sides) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  std::vector<CornerEdge> corners;
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    const TopoDS_Edge edge = TopoDS::Edge(edgeFaces.FindKey(e));
    std::vector<int> faces;
    for (const TopoDS_Shape& f : edgeFaces(e)) faces.push_back(cad.faces.FindIndex(f) - 1);
    if (faces.size() != 2 || faces[0] == faces[1] || BRep_Tool::Degenerated(edge)) continue;
    if (sides.faces[faces[0]].side != Side::Lateral || sides.faces[faces[1]].side != Side::Lateral) continue;
    if (BRep_Tool::Continuity(edge, TopoDS::Face(edgeFaces(e).First()), TopoDS::Face(edgeFaces(e).Last())) >=
        GeomAbs_G1)
      continue;
    BRepAdaptor_Curve curve(edge);
    GCPnts_UniformAbscissa even(curve, kCornerSamples + 1);
    if (!even.IsDone() || even.NbPoints() < 2) continue;
    CornerEdge corner{{}, faces[0]};
    for (int k = 1; k <= even.NbPoints(); ++k) {
      const gp_Pnt p = curve.Value(even.Parameter(k));
      corner.points.emplace_back(p.X(), p.Y(), p.Z());
    }
    corners.push_back(std::move(corner));
  }
  return corners;
}

// The candidates that run from the bottom wall to the top (their ends within 1e-6 part diagonals of them), bottom
// end first, in their order. The ends are tested in parallel (a wall's faces whose boxes are farther than the
// tolerance are not asked).
std::vector<CornerEdge> cornerEdges(const CadSolid& cad, const WallSides& sides, const WallProjector& walls) {
  std::vector<CornerEdge> candidates = cornerCandidates(cad, sides);
  const double tolerance = 1e-6 * cad.diagonal;
  auto on = [&](Side side, const Vec3& p) { return walls.reaches(side, p, tolerance); };
  std::vector<char> joins(candidates.size(), 0);
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 8)
  for (long i = 0; i < static_cast<long>(candidates.size()); ++i)
    errors.run([&] {
      CornerEdge& corner = candidates[i];
      if (on(Side::Top, corner.points.front()) && on(Side::Bottom, corner.points.back()))
        std::reverse(corner.points.begin(), corner.points.end());
      joins[i] = on(Side::Bottom, corner.points.front()) && on(Side::Top, corner.points.back());
    });
  errors.rethrow();
  std::vector<CornerEdge> corners;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (joins[i]) corners.push_back(std::move(candidates[i]));
  return corners;
}

// The point at share t of a polyline's length.
Vec3 alongPolyline(const std::vector<Vec3>& points, double t) {
  double total = 0;
  for (std::size_t k = 1; k < points.size(); ++k) total += (points[k] - points[k - 1]).norm();
  double left = t * total;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double step = (points[k] - points[k - 1]).norm();
    if (left <= step) return points[k - 1] + (step > 0 ? left / step : 0.0) * (points[k] - points[k - 1]);
    left -= step;
  }
  return points.back();
}

// The points of a corner edge at shares k / m of its length, k = 0 .. m: where a column of m layers would be laid.
std::vector<Vec3> cornerPlaces(const CornerEdge& corner, std::size_t m) {
  std::vector<Vec3> at;
  for (std::size_t k = 0; k <= m; ++k) at.push_back(alongPolyline(corner.points, static_cast<double>(k) / m));
  return at;
}

// How far a rim column lies from a corner edge: the mean distance of its nodes from the points of the edge at
// the same shares of its length (cornerPlaces: the column it would be laid as). Its nodes, not only its ends: where
// the swept rim lies half on a face cut across it, the ends of two columns can be as near the edge's ends.
double distanceToCorner(const HexMesh& mesh, const std::vector<int>& column, const std::vector<Vec3>& places) {
  const std::size_t m = column.size() - 1;
  double sum = 0;
  for (std::size_t k = 0; k <= m; ++k) sum += (mesh.nodes[column[k]] - places[k]).norm();
  return sum / (m + 1);
}

// Each corner edge takes the rim column nearest to it (distanceToCorner, within reach): that column is laid
// along the edge, its nodes at even arc lengths.
// [in,out] to: the places of the rim columns.
void layCorners(const std::vector<CornerEdge>& corners, const HexMesh& mesh,
                const std::vector<std::vector<int>>& columns, std::vector<std::vector<std::optional<FacePoint>>>& to,
                double reach) {
  for (const CornerEdge& corner : corners) {
    std::map<std::size_t, std::vector<Vec3>> places;  // by the columns' layer count
    auto placesOf = [&](std::size_t m) -> const std::vector<Vec3>& {
      auto it = places.find(m);
      return it != places.end() ? it->second : places.emplace(m, cornerPlaces(corner, m)).first->second;
    };
    int best = -1;
    double nearest = reach;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (const double d = distanceToCorner(mesh, columns[c], placesOf(columns[c].size() - 1)); d < nearest)
        nearest = d, best = static_cast<int>(c);
    if (best < 0) continue;
    const std::vector<Vec3>& at = placesOf(columns[best].size() - 1);
    for (std::size_t k = 0; k < at.size(); ++k) to[best][k] = FacePoint{at[k], corner.face};
  }
}

// The hexes that have a rim node, each once, and per rim column the hexes around its nodes.
struct RimHexes {
  std::vector<std::size_t> hexes;
  std::vector<std::vector<std::size_t>> ofColumn;
};

RimHexes rimHexes(const HexMesh& mesh, const std::vector<std::vector<int>>& columns) {
  const Groups<std::size_t> at = groupByKey<std::size_t>(mesh.nodes.size(), [&](auto emit) {
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
      for (int v : mesh.hexes[h])
        if (mesh.nodeOnRim[v]) emit(v, h);
  });
  RimHexes r;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (int v : mesh.hexes[h])
      if (mesh.nodeOnRim[v]) {
        r.hexes.push_back(h);
        break;
      }
  for (const std::vector<int>& column : columns) {
    std::vector<std::size_t> around;
    for (int v : column)
      around.insert(around.end(), at.items.begin() + at.start[v], at.items.begin() + at.start[v + 1]);
    r.ofColumn.push_back(std::move(around));
  }
  return r;
}

// The rim columns among them, in the order of their bottom nodes.
std::vector<std::vector<int>> rimColumnsOf(const HexMesh& mesh, const std::vector<std::vector<int>>& columns) {
  std::vector<std::vector<int>> rim;
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (mesh.nodeOnRim[i] && !columns[i].empty()) rim.push_back(columns[i]);
  return rim;
}

// The move of a rim column's wall nodes, fading over `rows` rows of the walls beside it.
struct WallMove {
  Vec3 bottom = Vec3::Zero(), top = Vec3::Zero();
  double rows = 0;
};

// Per bottom node of layer 0, its neighbours in that layer (the edges of the hexes' bottom faces), sorted.
std::vector<std::vector<int>> bottomNeighbours(const HexMesh& mesh) {
  std::vector<std::vector<int>> next(mesh.nodes.size());
  for (const auto& h : mesh.hexes)
    if (mesh.nodeLayer[h[0]] == 0)
      for (int k = 0; k < 4; ++k) next[h[k]].push_back(h[(k + 1) % 4]), next[h[(k + 1) % 4]].push_back(h[k]);
  for (auto& n : next) std::sort(n.begin(), n.end()), n.erase(std::unique(n.begin(), n.end()), n.end());
  return next;
}

double leanOf(const WallMove& m) { return std::max(m.bottom.norm(), m.top.norm()); }

// The move of a rim column's wall nodes to where `to` puts them (zero where it puts none).
WallMove wallMove(const HexMesh& mesh, const std::vector<int>& column,
                  const std::vector<std::optional<FacePoint>>& to) {
  WallMove m;
  if (to.front()) m.bottom = to.front()->point - mesh.nodes[column.front()];
  if (to.back()) m.top = to.back()->point - mesh.nodes[column.back()];
  return m;
}

// A column (its bottom node `v`) moved by `move` faded by `fade`: its wall nodes onto the walls (onto the walls'
// rim edges for a rim column, whose inner nodes go onto the lateral faces), evenly between them.
// Returns the new places (nullopt where a projection failed).
std::vector<std::optional<FacePoint>> movedColumn(const HexMesh& mesh, const std::vector<int>& column,
                                                  const WallMove& move, double fade, bool rim,
                                                  const WallProjector& walls) {
  const Vec3 bottom0 = mesh.nodes[column.front()], top0 = mesh.nodes[column.back()];
  const std::size_t m = column.size() - 1;
  std::vector<std::optional<FacePoint>> to(column.size());
  to[0] = rim ? walls.projectOntoRimEdges(Side::Bottom, bottom0 + fade * move.bottom)
              : walls.project(Side::Bottom, bottom0 + fade * move.bottom);
  to[m] = rim ? walls.projectOntoRimEdges(Side::Top, top0 + fade * move.top)
              : walls.project(Side::Top, top0 + fade * move.top);
  if (!to[0] || !to[m]) return std::vector<std::optional<FacePoint>>(column.size());
  for (std::size_t k = 1; k < m; ++k) {
    const double t = static_cast<double>(k) / m;
    const Vec3 p = (1 - t) * to[0]->point + t * to[m]->point;
    to[k] = rim ? walls.project(Side::Lateral, p) : FacePoint{p, mesh.nodeFace[column[k]]};
  }
  return to;
}

// The move of a column beside a leaning rim (its bottom node n, its neighbours in the wall `next`, the rim's side
// at level - 1): as given where both wall nodes move the same way, or one does, along the wall away from the rim;
// where they move apart (a "scissor": a rim cut obliquely, its bottom edge going out and its top edge in), both
// by the move of the one that goes in. A sheared column beside such a rim would lean the hexes between them
// twice, a shifted one keeps them upright: only the rim's own hexes then have its sharp corners.
WallMove shiftedIfScissor(const HexMesh& mesh, int n, const std::vector<int>& next, const std::vector<int>& level,
                          const WallMove& move) {
  Vec3 from = Vec3::Zero();
  int count = 0;
  for (int p : next)
    if (level[p] == level[n] - 1) from += mesh.nodes[p], ++count;
  if (count == 0) return move;
  const Vec3 in = mesh.nodes[n] - from / count;  // away from the rim, along the wall
  const double bottom = move.bottom.dot(in), top = move.top.dot(in);
  if (bottom * top >= 0) return move;
  const Vec3 shift = bottom > 0 ? move.bottom : move.top;
  return {shift, shift, move.rows};
}

// Where a rim is cut obliquely, its columns lean (their wall nodes move apart along the walls, by up to 1.5
// walls on a rim 3 walls wide) and the hexes beside them would fold. The columns beside such a rim move with
// it: by its move times 1 - j / (rows + 1) in the j-th row (rows enough that an edge along the wall keeps
// kKeptEdge of its length), their wall nodes projected back onto the walls (onto the walls' rim edges on another rim),
// their inner nodes evenly on the line between. A rim column leans when its wall nodes move more than kLean of the
// edges beside it. [in,out] mesh: the nodes of columns off the rim moved; [in] columns: every column
// (columnsByBottom); [in] rim: the rim columns; [in,out] to: their places.
void spreadRimMoves(HexMesh& mesh, const std::vector<std::vector<int>>& columns,
                    const std::vector<std::vector<int>>& rim, std::vector<std::vector<std::optional<FacePoint>>>& to,
                    const WallProjector& walls) {
  const std::vector<std::vector<int>> next = bottomNeighbours(mesh);
  std::vector<int> rimOf(mesh.nodes.size(), -1);
  for (std::size_t c = 0; c < rim.size(); ++c) rimOf[rim[c].front()] = static_cast<int>(c);
  std::vector<WallMove> move(mesh.nodes.size());
  std::vector<int> level(mesh.nodes.size(), -1);
  for (std::size_t c = 0; c < rim.size(); ++c) {  // the rim columns that lean
    const int v = rim[c].front();
    if (next[v].empty() || !to[c].front() || !to[c].back()) continue;
    WallMove m = wallMove(mesh, rim[c], to[c]);
    double edge = 0;  // the mean length of the edges along the wall at the rim node
    for (int n : next[v]) edge += (mesh.nodes[n] - mesh.nodes[v]).norm();
    edge /= next[v].size();
    const double lean = leanOf(m) / std::max(edge, 1e-300);
    m.rows = std::max(std::ceil(lean / (1 - kKeptEdge)) - 1, 0.0);
    if (lean > kLean) move[v] = m, level[v] = 0;
  }
  std::vector<int> front;
  for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
    if (level[v] == 0) front.push_back(static_cast<int>(v));
  for (int j = 1; !front.empty(); ++j) {
    std::vector<int> reached;
    for (int v : front)
      for (int n : next[v])
        if (level[n] < 0 && !columns[n].empty()) level[n] = j, reached.push_back(n);
    std::sort(reached.begin(), reached.end());
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
    std::vector<int> kept;
    for (int n : reached) {
      WallMove mean;
      int from = 0;
      for (int p : next[n])
        if (level[p] == j - 1 && move[p].rows >= j)
          mean.bottom += move[p].bottom, mean.top += move[p].top, mean.rows += move[p].rows, ++from;
      if (from == 0) continue;
      move[n] = {mean.bottom / from, mean.top / from, mean.rows / from};
      kept.push_back(n);
    }
    for (int n : kept) {
      const double fade = 1 - j / (move[n].rows + 1);
      const WallMove shifted = shiftedIfScissor(mesh, n, next[n], level, move[n]);
      if (rimOf[n] >= 0) {
        to[rimOf[n]] = movedColumn(mesh, columns[n], shifted, fade, true, walls);
        continue;
      }
      const std::vector<std::optional<FacePoint>> at = movedColumn(mesh, columns[n], shifted, fade, false, walls);
      for (std::size_t k = 0; k < at.size(); ++k)
        if (at[k]) mesh.nodes[columns[n][k]] = at[k]->point, mesh.nodeFace[columns[n][k]] = at[k]->face;
    }
    front = std::move(kept);
  }
}

}  // namespace

std::vector<std::vector<int>> rimColumns(const HexMesh& mesh) { return rimColumnsOf(mesh, columnsByBottom(mesh)); }

RimProjectionStats projectRim(HexMesh& mesh, const CadSolid& cad, const WallSides& sides, const WallProjector& walls,
                              double reach) {
  const std::vector<std::vector<int>> all = columnsByBottom(mesh);
  const std::vector<std::vector<int>> columns = rimColumnsOf(mesh, all);
  const std::vector<Vec3> normal = sideFaceNormals(mesh);
  // The new places first, in parallel (one ray caster per thread: OpenCASCADE's keeps state); a column's
  // depend only on where the sweep put it.
  std::vector<std::vector<std::optional<FacePoint>>> to(columns.size());
  std::deque<WallRays> rays;
  for (int t = 0; t < threadCount(); ++t) rays.emplace_back(cad, sides);
  ParallelErrors errors;
#pragma omp parallel for schedule(static)
  for (long c = 0; c < static_cast<long>(columns.size()); ++c)
    errors.run([&] {
      to[c] = layColumn(mesh, columns[c], rimFrame(mesh, columns[c], normal), rays[threadIndex()], walls, reach);
    });
  errors.rethrow();
  layCorners(cornerEdges(cad, sides, walls), mesh, columns, to, reach);
  // Then all columns at once, and back where the sweep put them those that spoil a hex (below a scaled
  // Jacobian of 0.2 and worse than before), until none does: the result does not depend on the order.
  spreadRimMoves(mesh, all, columns, to, walls);
  RimProjectionStats stats;
  const RimHexes around = rimHexes(mesh, columns);
  std::vector<double> before(mesh.hexes.size(), 1.0);
  for (std::size_t h : around.hexes) before[h] = hexScaledJacobian(hexCorners(mesh, h));
  const std::vector<Vec3> swept = mesh.nodes;
  std::vector<char> moved(columns.size(), 0);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    stats.rimNodes += columns[c].size();
    for (std::size_t k = 0; k < columns[c].size(); ++k)
      if (to[c][k]) mesh.nodes[columns[c][k]] = to[c][k]->point, moved[c] = 1;
  }
  auto spoiled = [&](std::size_t c) {
    for (std::size_t h : around.ofColumn[c]) {
      const double sj = hexScaledJacobian(hexCorners(mesh, h));
      if (sj < kSpoiled && sj < before[h]) return true;
    }
    return false;
  };
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::size_t> back;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (moved[c] && spoiled(c)) back.push_back(c);
    for (std::size_t c : back) {
      for (int v : columns[c]) mesh.nodes[v] = swept[v];
      moved[c] = 0, changed = true, ++stats.columnsKept;
    }
  }
  // The columns put back get their nodes moved one at a time where that spoils no hex.
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (std::size_t k = 0; k < columns[c].size(); ++k) {
      const int v = columns[c][k];
      if (!to[c][k]) continue;
      if (!moved[c]) {
        mesh.nodes[v] = to[c][k]->point;
        if (spoiled(c)) {
          mesh.nodes[v] = swept[v];
          continue;
        }
      }
      mesh.nodeFace[v] = to[c][k]->face, ++stats.onLateralFaces;
    }
  return stats;
}

}  // namespace hexlayer
