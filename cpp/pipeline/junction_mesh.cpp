#include "pipeline/junction_mesh.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "quality/quality.hpp"

namespace hexlayer {
namespace {

// A standing wall's footprint covering less of its feet's faces leaves some of them unjoined (wallFoot refuses it).
constexpr double kCoveredFoot = 0.75;
// A wall lying along a foot (a lap) whose hexes' faces cover less of that foot leaves notches where they do not: its
// quads straddle the foot's edges (wallFoot refuses it).
constexpr double kCoveredLap = 0.8;
// Of a layer: a wall's sweep column ending this near a foot it lies along ends on it (lapFaces).
constexpr double kLapReach = 0.25;
constexpr int kLeanRings = 3;  // rings of quads round the columns of an oblique crossing that lean less and less

// 20-node hexes: the sheet's mid-edge node of every edge whose corners are both walls' nodes is the walls' mid-edge
// node of that edge. [in] sheet, walls; [in,out] shared: footNodesShared's
// corners, the mid-edge nodes added.
void shareMidEdgeNodes(const HexMesh& sheet, const HexMesh& walls, std::vector<int>& shared) {
  if (!sheet.quadratic()) return;
  std::map<std::pair<int, int>, int> wallEdges;  // the walls' edges on the feet: their corners -> mid-edge node
  std::vector<char> onFoot(walls.nodes.size(), 0);
  for (int n : shared)
    if (n >= 0) onFoot[n] = 1;
  for (std::size_t h = 0; h < walls.hexes.size(); ++h)
    for (std::size_t e = 0; e < kHexEdges.size(); ++e) {
      const int a = walls.hexes[h][kHexEdges[e][0]], b = walls.hexes[h][kHexEdges[e][1]];
      if (onFoot[a] && onFoot[b]) wallEdges[std::minmax(a, b)] = walls.midEdges[h][e];
    }
  for (std::size_t h = 0; h < sheet.hexes.size(); ++h)
    for (std::size_t e = 0; e < kHexEdges.size(); ++e) {
      const int a = shared[sheet.hexes[h][kHexEdges[e][0]]], b = shared[sheet.hexes[h][kHexEdges[e][1]]];
      if (a < 0 || b < 0) continue;
      const auto at = wallEdges.find(std::minmax(a, b));
      if (at == wallEdges.end()) throw geometryError("junction: a sheet's edge on a wall's foot is none of the wall's");
      shared[sheet.midEdges[h][e]] = at->second;
    }
}

// The mean of the points.
Vec3 middleOf(const std::vector<Vec3>& points) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) sum += p;
  return sum / static_cast<double>(std::max<std::size_t>(points.size(), 1));
}

// Moves the nodes flagged `moved` by `move`, and at order 2 every mid-edge node at a moved node that is not a wall's
// (shared) nor moved itself by the mean of its edge's ends' moves. [in,out] mesh; [in,out] move, moved: per node;
// [in] shared: per node, its walls' node or -1 (footNodesShared's; empty: none).
void moveNodes(HexMesh& mesh, std::vector<Vec3>& move, std::vector<char>& moved, const std::vector<int>& shared) {
  if (mesh.quadratic())
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
      for (std::size_t e = 0; e < kHexEdges.size(); ++e) {
        const int a = mesh.hexes[h][kHexEdges[e][0]], b = mesh.hexes[h][kHexEdges[e][1]], mid = mesh.midEdges[h][e];
        if ((moved[a] || moved[b]) && (shared.empty() || shared[mid] < 0) && !moved[mid])
          move[mid] = 0.5 * (move[a] + move[b]), moved[mid] = 1;
      }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) mesh.nodes[n] += move[n];
}

}  // namespace

FootSurface::FootSurface(const Foot& foot, double tolerance) : area_(foot.area), tolerance_(tolerance) {
  BRepBndLib::AddOptimal(foot.face, box_, false, false);  // its curves', not its triangulation's
  box_.Enlarge(tolerance);
  const BRepAdaptor_Surface surface(foot.face);
  if (surface.GetType() == GeomAbs_Plane) {
    const gp_Pln plane = surface.Plane();
    const gp_XYZ n = plane.Axis().Direction().XYZ(), o = plane.Location().XYZ();
    plane_.emplace(Vec3(n.X(), n.Y(), n.Z()), n.Dot(o));
  } else {
    surface_ = new ShapeAnalysis_Surface(BRep_Tool::Surface(foot.face));
  }
}

bool FootSurface::holds(const Vec3& p, double reach) {
  const gp_Pnt at(p.x(), p.y(), p.z());
  if (box_.IsOut(at) && (reach < 0 || box_.Distance(Bnd_Box(at, at)) > reach)) return false;  // the box: enlarged
  if (reach < 0) reach = tolerance_;
  if (plane_) return std::abs(p.dot(plane_->first) - plane_->second) <= reach;
  surface_->ValueOfUV(at, tolerance_);
  return surface_->Gap() <= reach;
}

Vec3 FootSurface::project(const Vec3& p) {
  if (plane_) return p - (p.dot(plane_->first) - plane_->second) * plane_->first;
  const gp_Pnt at = surface_->Value(surface_->ValueOfUV(gp_Pnt(p.x(), p.y(), p.z()), tolerance_));
  return {at.X(), at.Y(), at.Z()};
}

std::vector<FootSurface> footSurfaces(const JunctionCut& cut, int sheet, int base, double tolerance) {
  std::vector<FootSurface> surfaces;
  for (const Foot& f : cut.feet)
    if (f.sheet == sheet && f.base == base) surfaces.emplace_back(f, tolerance);
  return surfaces;
}

namespace {

// The quad's area: half its diagonals' cross product.
double quadArea(const std::vector<Vec3>& nodes, const std::array<int, 4>& q) {
  return 0.5 * (nodes[q[2]] - nodes[q[0]]).cross(nodes[q[3]] - nodes[q[1]]).norm();
}

double quadsArea(const FootprintQuads& f) {
  double area = 0;
  for (const auto& q : f.quads) area += quadArea(f.nodes, q);
  return area;
}

// A wall lying along a foot (a boss merged into a box's wall: a ring flattened there) has its side's hex faces on it:
// every quad whose sweep columns all end (layer 0 or m) on one foot, within kLapReach of their layer (the rim's columns
// on the floor's foot end a little off the flat's plane, up to a tenth of a layer: their quads left out opened a gap
// along the flat's foot). [in] wall, quads, feet: as wallFoot's; [out] area: per foot, the faces' area. Returns the
// faces, the wall's nodes.
std::vector<std::array<int, 4>> lapFaces(const HexMesh& wall, const QuadMesh& quads, std::vector<FootSurface>& feet,
                                         std::vector<double>& area) {
  const int m = wall.layers, stride = m + 1;
  area.assign(feet.size(), 0);
  std::vector<std::array<int, 4>> faces;
  for (const auto& quad : quads.quads)
    for (const int k : {0, m})
      for (std::size_t f = 0; f < feet.size(); ++f)
        if (std::all_of(quad.begin(), quad.end(), [&](int q) {
              const double layer = (wall.nodes[q * stride + m] - wall.nodes[q * stride]).norm() / m;
              return feet[f].holds(wall.nodes[q * stride + k], kLapReach * layer);
            })) {
          std::array<int, 4> face;
          for (int c = 0; c < 4; ++c) face[c] = quad[c] * stride + k;
          faces.push_back(face), area[f] += quadArea(wall.nodes, face);
          break;
        }
  return faces;
}

// The wall's boundary faces beyond its sweep lying on one foot: the faces of its rim caps' hexes (a rounded rim's
// profile beyond the sweep, rim_cap.hpp) where the rim meets the foot (a rib's round end), none of them in `foot`
// already. [in] wall, feet: as wallFoot's; [in] foot: the strip and lap faces so far. Returns the faces, the wall's
// nodes, ordered as boundaryFaces orders them.
std::vector<std::array<int, 4>> capFaces(const HexMesh& wall, std::vector<FootSurface>& feet, const WallFoot& foot) {
  std::set<std::array<int, 4>> known;
  for (const std::array<int, 4>& q : foot.footprint.quads) {
    std::array<int, 4> nodes{foot.wallNode[q[0]], foot.wallNode[q[1]], foot.wallNode[q[2]], foot.wallNode[q[3]]};
    std::sort(nodes.begin(), nodes.end());
    known.insert(nodes);
  }
  std::vector<std::array<int, 4>> faces;
  for (const BoundaryFace& b : boundaryFaces(wall)) {
    std::array<int, 4> sorted = b.nodes;
    std::sort(sorted.begin(), sorted.end());
    if (known.count(sorted) ||
        std::none_of(b.nodes.begin(), b.nodes.end(), [&](int n) { return wall.nodeOnRim[n] == kRimCap; }))
      continue;
    if (std::any_of(feet.begin(), feet.end(), [&](FootSurface& f) {
          return std::all_of(b.nodes.begin(), b.nodes.end(), [&](int n) { return f.holds(wall.nodes[n]); });
        }))
      faces.push_back(b.nodes);
  }
  return faces;
}

// Throws geometryError if the footprint covers under kCoveredFoot of the feet's area, or the laps' quads under
// kCoveredLap of a foot they lie on (lapArea: per foot of `feet`).
void requireFeetCovered(const FootprintQuads& footprint, const std::vector<double>& lapArea,
                        const std::vector<FootSurface>& feet) {
  double footArea = 0;
  for (const FootSurface& f : feet) footArea += f.area();
  if (const double covered = quadsArea(footprint) / footArea; covered < kCoveredFoot) {
    std::ostringstream what;
    what << "junction: a standing wall's hexes cover " << std::lround(100 * covered)
         << " % of its feet (it lies along a foot, as a boss merged into a box's wall, its hexes' faces not on the "
            "foot there), which is not meshed yet";
    throw geometryError(what.str());
  }
  for (std::size_t f = 0; f < feet.size(); ++f)
    if (const double covered = lapArea[f] / feet[f].area(); lapArea[f] > 0 && covered < kCoveredLap) {
      std::ostringstream what;
      what << "junction: a standing wall lies along its foot (a boss merged into a box's wall, its flat on the wall), "
              "its hexes' faces cover "
           << std::lround(100 * covered) << " % of the flat (its quads do not follow the flat's edges), which is not "
           << "meshed yet";
      throw geometryError(what.str());
    }
}

}  // namespace

WallFoot wallFoot(const HexMesh& wall, const QuadMesh& quads, std::vector<FootSurface>& feet) {
  const int m = wall.layers, stride = m + 1;
  const std::vector<std::vector<int>> rim = rimEdgeNeighbours(quads);
  // Per foot, whether quad node q's sweep column lies on it (only rim nodes can; a node where feet meet, on a bend's
  // seam, on both).
  std::vector<std::vector<char>> on(feet.size(), std::vector<char>(quads.nodes.size(), 0));
  for (int q = 0; q < static_cast<int>(quads.nodes.size()); ++q) {
    if (rim[q].empty() || (q + 1) * stride > static_cast<int>(wall.nodes.size())) continue;
    for (std::size_t f = 0; f < feet.size(); ++f) {
      bool all = true;
      for (int k = 0; all && k <= m; ++k) all = feet[f].holds(wall.nodes[q * stride + k]);
      on[f][q] = all;
    }
  }
  auto onOneFoot = [&](int a, int b) {
    return std::any_of(on.begin(), on.end(), [&](const std::vector<char>& f) { return f[a] && f[b]; });
  };
  WallFoot foot;
  std::map<int, int> index;  // the wall's hex node -> footprint node
  auto node = [&](int n) {
    const auto [it, added] = index.emplace(n, static_cast<int>(foot.wallNode.size()));
    if (added) foot.wallNode.push_back(n), foot.footprint.nodes.push_back(wall.nodes[n]);
    return it->second;
  };
  for (int q = 0; q < static_cast<int>(quads.nodes.size()); ++q)
    if (std::any_of(on.begin(), on.end(), [&](const std::vector<char>& f) { return f[q] != 0; })) {
      foot.footColumns.emplace_back(wall.nodes.begin() + q * stride, wall.nodes.begin() + (q + 1) * stride);
    }
  std::vector<int> footEdges(quads.nodes.size(), 0);
  for (int a = 0; a < static_cast<int>(quads.nodes.size()); ++a)
    for (int b : rim[a]) {
      if (b <= a || !onOneFoot(a, b)) continue;
      ++footEdges[a], ++footEdges[b];
      for (int k = 0; k < m; ++k)
        foot.footprint.quads.push_back(
            {node(a * stride + k), node(b * stride + k), node(b * stride + k + 1), node(a * stride + k + 1)});
    }
  std::vector<double> lapArea;  // per foot
  for (const std::array<int, 4>& face : lapFaces(wall, quads, feet, lapArea)) {
    std::array<int, 4> lap;
    for (int c = 0; c < 4; ++c) lap[c] = node(face[c]);
    foot.footprint.quads.push_back(lap);
    foot.lap.resize(foot.wallNode.size(), 0);
    for (int n : lap) foot.lap[n] = 1;
  }
  for (const std::array<int, 4>& face : capFaces(wall, feet, foot)) {
    std::array<int, 4> cap;
    for (int c = 0; c < 4; ++c) cap[c] = node(face[c]);
    foot.footprint.quads.push_back(cap);
  }
  if (foot.footprint.quads.empty()) throw geometryError("junction: a standing wall has no quads along its foot");
  requireFeetCovered(foot.footprint, lapArea, feet);
  foot.lap.resize(foot.wallNode.size(), 0);
  foot.ring = std::none_of(footEdges.begin(), footEdges.end(), [](int e) { return e == 1; });
  return foot;
}

bool columnsAcross(std::vector<FootSurface>& feet, const FootColumns& columns) {
  return !columns.empty() && std::all_of(columns.begin(), columns.end(), [&](const std::vector<Vec3>& column) {
    return std::any_of(feet.begin(), feet.end(), [&](FootSurface& f) { return f.holds(f.project(middleOf(column))); });
  });
}

constexpr double kAcross = 1e-3;  // of the reach: rim nodes this near their columns across are left there

std::size_t alignFootAcross(QuadMesh& quads, std::vector<FootSurface>& feet, const FootColumns& across, double unit,
                            double reach) {
  std::vector<Vec3> targets;  // the columns across, their middles projected onto the foot they face
  for (const std::vector<Vec3>& column : across)
    for (FootSurface& f : feet)
      if (const Vec3 p = f.project(middleOf(column)); f.holds(p)) {
        targets.push_back(p);
        break;
      }
  const std::vector<std::vector<int>> rim = rimEdgeNeighbours(quads);
  std::vector<std::tuple<double, int, int>> pairs;  // (distance, rim node, target) within reach
  std::size_t onFoot = 0;
  for (int q = 0; q < static_cast<int>(quads.nodes.size()); ++q) {
    const Vec3 p = quads.nodes[q] / unit;
    if (rim[q].empty() || std::none_of(feet.begin(), feet.end(), [&](FootSurface& f) { return f.holds(p); })) continue;
    ++onFoot;
    for (int t = 0; t < static_cast<int>(targets.size()); ++t)
      if (const double d = (targets[t] - p).norm(); d <= reach) pairs.emplace_back(d, q, t);
  }
  if (onFoot != targets.size() || targets.empty()) return 0;
  std::sort(pairs.begin(), pairs.end());  // the nearest pairs first, each node and target in one
  std::vector<int> taken(targets.size(), -1);
  std::set<int> placed;
  double farthest = 0;
  for (const auto& [d, q, t] : pairs)
    if (taken[t] < 0 && !placed.count(q)) taken[t] = q, placed.insert(q), farthest = d;
  if (placed.size() != targets.size() || farthest <= kAcross * reach) return 0;  // not one to one, or across already
  for (std::size_t t = 0; t < targets.size(); ++t) quads.nodes[taken[t]] = targets[t] * unit;
  return targets.size();
}

std::size_t snapFootColumnsAcross(HexMesh& piece, const QuadMesh& quads, std::vector<FootSurface>& feet,
                                  const FootColumns& across, double unit, double reach) {
  const int m = piece.layers, stride = m + 1;
  const std::vector<std::vector<int>> rim = rimEdgeNeighbours(quads);
  std::vector<Vec3> move(piece.nodes.size(), Vec3::Zero());
  std::vector<char> moved(piece.nodes.size(), 0);
  std::vector<std::vector<Vec3>> onFoot(feet.size());  // per foot, the columns' middles across projected onto it
  for (std::size_t f = 0; f < feet.size(); ++f)
    for (const std::vector<Vec3>& column : across) onFoot[f].push_back(feet[f].project(middleOf(column)));
  std::size_t columns = 0;
  for (int q = 0; q < static_cast<int>(quads.nodes.size()) && (q + 1) * stride <= static_cast<int>(piece.nodes.size());
       ++q) {
    if (rim[q].empty()) continue;
    std::vector<Vec3> own(piece.nodes.begin() + q * stride, piece.nodes.begin() + (q + 1) * stride);
    for (Vec3& p : own) p /= unit;
    for (std::size_t g = 0; g < feet.size(); ++g) {
      FootSurface& f = feet[g];
      if (!std::all_of(own.begin(), own.end(), [&](const Vec3& p) { return f.holds(p); })) continue;
      const Vec3 middle = middleOf(own);
      const std::vector<Vec3>* best = nullptr;
      double nearest = 0;
      for (std::size_t c = 0; c < across.size(); ++c)
        if (const double d = (onFoot[g][c] - middle).norm();
            across[c].size() == own.size() && d <= reach && (!best || d < nearest))
          best = &across[c], nearest = d;
      if (!best) break;
      const bool reversed =
          (f.project(best->front()) - own.front()).norm() > (f.project(best->back()) - own.front()).norm();
      for (int k = 0; k <= m; ++k)
        move[q * stride + k] = unit * (f.project((*best)[reversed ? m - k : k]) - own[k]), moved[q * stride + k] = 1;
      ++columns;
      break;
    }
  }
  moveNodes(piece, move, moved, {});
  return columns;
}

WallFoot columnFoot(const HexMesh& column, const QuadMesh& quads) {
  WallFoot foot;
  foot.column = true;
  foot.footprint.quads = quads.quads;
  int corners = 0;  // the hexes' corner nodes come first, their mid-edge nodes (order 2) after them
  for (const auto& hex : column.hexes) corners = std::max(corners, *std::max_element(hex.begin(), hex.end()) + 1);
  for (int n = 0; n < corners; ++n)  // each quad node's column in turn, its foot first
    if (column.nodeLayer[n] == 0)
      foot.wallNode.push_back(static_cast<int>(n)), foot.footprint.nodes.push_back(column.nodes[n]);
  return foot;
}

std::vector<int> footNodesShared(const HexMesh& sheet, const std::vector<int>& column, const HexMesh& walls,
                                 const std::vector<int>& wallNode, double tolerance) {
  const int m = sheet.layers, stride = m + 1;
  std::vector<int> shared(sheet.nodes.size(), -1);
  for (std::size_t f = 0; f < column.size(); ++f) {
    const Vec3& p = walls.nodes[wallNode[f]];
    const int a = column[f] * stride, b = a + m;
    const int end = (sheet.nodes[a] - p).norm() < (sheet.nodes[b] - p).norm() ? a : b;
    if (const double d = (sheet.nodes[end] - p).norm(); !(d <= tolerance)) {
      std::ostringstream msg;
      msg << "junction: the sheet's node under a wall's foot node (" << p.x() << ", " << p.y() << ", " << p.z()
          << ") is " << d << " from it";
      throw geometryError(msg.str());
    }
    shared[end] = wallNode[f];
  }
  shareMidEdgeNodes(sheet, walls, shared);
  return shared;
}

namespace {

// At order 2, every edge at a moved node whose mid-edge node is not a wall's gets it at its middle (evenFootColumns).
// [in,out] sheet;
// [in] moved: per node; [in] shared: footNodesShared's.
void midEdgesAtMiddle(HexMesh& sheet, const std::vector<char>& moved, const std::vector<int>& shared) {
  if (!sheet.quadratic()) return;
  for (std::size_t h = 0; h < sheet.hexes.size(); ++h)
    for (std::size_t e = 0; e < kHexEdges.size(); ++e) {
      const int a = sheet.hexes[h][kHexEdges[e][0]], b = sheet.hexes[h][kHexEdges[e][1]], mid = sheet.midEdges[h][e];
      if ((moved[a] || moved[b]) && shared[mid] < 0) sheet.nodes[mid] = 0.5 * (sheet.nodes[a] + sheet.nodes[b]);
    }
}

}  // namespace

void leanCrossedColumns(HexMesh& sheet, const QuadMesh& quads, const std::vector<int>& shared, const HexMesh& walls) {
  const int m = sheet.layers, stride = m + 1, columns = static_cast<int>(quads.nodes.size());
  if (columns * stride > static_cast<int>(shared.size())) return;
  // Per column, its ends' offsets (the low end's, the high end's) and its ring round the crossed columns.
  std::vector<std::pair<Vec3, Vec3>> offset(columns, {Vec3::Zero(), Vec3::Zero()});
  std::vector<int> ring(columns, -1), front;
  for (int c = 0; c < columns; ++c) {
    const int a = c * stride, b = a + m;
    if (shared[a] < 0 || shared[b] < 0) continue;
    offset[c] = {walls.nodes[shared[a]] - sheet.nodes[a], walls.nodes[shared[b]] - sheet.nodes[b]};
    ring[c] = 0, front.push_back(c);
  }
  if (front.empty()) return;
  const std::vector<std::vector<int>> rim = rimEdgeNeighbours(quads);
  std::vector<std::set<int>> next(columns);  // quad edges
  for (const auto& q : quads.quads)
    for (int k = 0; k < 4; ++k) next[q[k]].insert(q[(k + 1) % 4]), next[q[(k + 1) % 4]].insert(q[k]);
  std::vector<int> source(columns, -1);  // the crossed column a column's offsets come from
  for (int c : front) source[c] = c;
  for (int r = 1; r <= kLeanRings && !front.empty(); ++r) {  // breadth first, in column order: deterministic
    std::vector<int> grown;
    for (int c : front)
      for (int n : next[c]) {
        const int a = n * stride, b = a + m;
        if (ring[n] >= 0 || shared[a] >= 0 || shared[b] >= 0) continue;
        const bool alongRim = !rim[source[c]].empty() && std::count(rim[c].begin(), rim[c].end(), n) > 0;
        if (!rim[n].empty() && !alongRim) continue;  // a rim column leans only along the rim, as its crossed one
        ring[n] = r, source[n] = source[c], grown.push_back(n);
      }
    std::sort(grown.begin(), grown.end());
    front = std::move(grown);
  }
  // Each node of a leaning column moves by its ends' offsets interpolated along it (a straight, even column stays
  // one; a rim column on a round rim, on it, where its ends barely move); at order 2 a mid-edge node by the mean of its
  // edge's ends' moves.
  std::vector<Vec3> move(sheet.nodes.size(), Vec3::Zero());
  std::vector<char> moved(sheet.nodes.size(), 0);
  for (int c = 0; c < columns; ++c) {
    if (ring[c] < 0) continue;
    const double w = 1.0 - static_cast<double>(ring[c]) / (kLeanRings + 1);
    const auto& [low, high] = offset[source[c]];
    for (int k = 0, a = c * stride; k <= m; ++k)
      move[a + k] = w * (low + (high - low) * (static_cast<double>(k) / m)), moved[a + k] = 1;
  }
  moveNodes(sheet, move, moved, shared);
}

void evenFootColumns(HexMesh& sheet, int columns, const std::vector<int>& shared, const HexMesh& walls) {
  const int m = sheet.layers, stride = m + 1;
  if (columns * stride > static_cast<int>(shared.size()) || m < 2) return;
  std::vector<char> moved(sheet.nodes.size(), 0);
  for (int c = 0; c < columns; ++c) {
    const int a = c * stride, b = a + m;
    if ((shared[a] < 0) == (shared[b] < 0)) continue;  // on no foot, or on two (leanCrossedColumns)
    const Vec3 from = shared[a] >= 0 ? walls.nodes[shared[a]] : sheet.nodes[a];
    const Vec3 to = shared[b] >= 0 ? walls.nodes[shared[b]] : sheet.nodes[b];
    double off = 0;
    for (int k = 1; k < m; ++k) off = std::max(off, (sheet.nodes[a + k] - from - (to - from) * (double(k) / m)).norm());
    if (off <= kUnevenColumn * (to - from).norm() / m) continue;
    for (int k = 1; k < m; ++k) sheet.nodes[a + k] = from + (to - from) * (double(k) / m), moved[a + k] = 1;
  }
  midEdgesAtMiddle(sheet, moved, shared);
}

JunctionHexes junctionHexes(const HexMesh& mesh, const std::vector<double>& scaledJacobian,
                            const std::vector<int>& footNodes) {
  std::vector<char> onFoot(mesh.nodes.size(), 0);
  for (int n : footNodes) onFoot[n] = 1;
  JunctionHexes j;
  j.minScaledJacobian = std::numeric_limits<double>::infinity();
  double sum = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    if (std::none_of(mesh.hexes[h].begin(), mesh.hexes[h].end(), [&](int n) { return onFoot[n] != 0; })) continue;
    ++j.hexes, sum += scaledJacobian[h];
    j.minScaledJacobian = std::min(j.minScaledJacobian, scaledJacobian[h]);
  }
  if (j.hexes == 0) j.minScaledJacobian = 0;
  j.meanScaledJacobian = j.hexes ? sum / j.hexes : 0;
  return j;
}

}  // namespace hexlayer
