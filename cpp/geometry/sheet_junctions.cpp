#include "geometry/sheet_junctions.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_OBB.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/union_find.hpp"
#include "geometry/column_piece.hpp"
#include "geometry/face_sampling.hpp"
#include "geometry/sheet_edges.hpp"

namespace hexlayer {
namespace {

constexpr double kSmallFeatureWalls = 2;  // a column within a box this many walls across (diagonal) may be small
// A group of faces that encloses no more than this share of its area times the wall with its foot stands out of
// nothing: a face at the wall's level (the floor of a boss's bore over a smaller hole through the plate).
constexpr double kStandsOut = 1e-3;
constexpr double kStepCos = 0.866;        // cos 30 deg: the walls on either side of a thickness step face the same way
constexpr double kSamePlaneAngle = 1e-6;  // rad: the faces of a sheet and of the sheet joined to it lie on one plane

std::vector<FaceSample> centreSamples(const TopoDS_Shape& face, double area) {
  return sampleFace(face, std::sqrt(std::max(area, 1e-30) / 16));
}

Vec3 faceCentre(const TopoDS_Shape& face, double area) {
  Vec3 c = Vec3::Zero();
  for (const FaceSample& s : centreSamples(face, area)) c += s.area * s.point;
  return c;
}

// The faces as a column: their area, centre and the volume they enclose with a plane through `origin` closing them,
// V = 1/3 * sum over the faces of (x - origin) . n dA (the divergence theorem; the closing plane adds nothing), from
// one sampling: negative where the faces are a dent below the plane (a drill point's cone at a blind bore's bottom:
// their outward normals face what they enclose). [in] cad, sides, faces, origin.
Sheet columnOf(const CadSolid& cad, const WallSides& sides, const std::vector<int>& faces, const Vec3& origin) {
  Sheet column;
  column.faces = faces, column.column = true;
  double volume = 0;
  for (int f : faces) {
    Vec3 centre = Vec3::Zero();
    for (const FaceSample& s : centreSamples(cad.faces(f + 1), sides.faces[f].area))
      centre += s.area * s.point, volume += s.area * (s.point - origin).dot(s.normal) / 3;
    column.area += sides.faces[f].area, column.centre += centre;
  }
  column.centre /= std::max(column.area, 1e-30);
  column.volume = volume;
  return column;
}

// Whether the faces are a small feature: all narrower than half the wall (narrowLateral, counted by
// findSmallFeatures) and within a box less than two walls across (a nub, a corner's chip; not a thin tall pin).
bool smallFeature(const CadSolid& cad, const WallSides& sides, const std::vector<int>& faces) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (int f : faces) {
    if (!narrowLateral(sides, f)) return false;
    builder.Add(all, cad.faces(f + 1));
  }
  Bnd_OBB box;  // oriented: the same box for the part turned
  BRepBndLib::AddOBB(all, box);
  return std::sqrt(box.SquareExtent()) < kSmallFeatureWalls * sides.thickness;
}

Vec3 edgeMiddle(const TopoDS_Shape& edge) {
  BRepAdaptor_Curve curve(TopoDS::Edge(edge));
  const gp_Pnt p = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
  return {p.X(), p.Y(), p.Z()};
}

// Whether a join's faces are one sheet: on one side (the wall runs on through a bend), or on the two sides of a knife
// edge (a tapered end: one face the other's across the wall). A boss merged into a wall, drafted or only 0.2-0.3 into
// it, meets the wall's face in an air wedge of 20-28 degrees, an edge BRepOffset_Analyse takes for convex (a folded
// join, SheetJoin::folded): it stands on the wall, and joined it made the box and the boss one sheet (Gmsh failed to
// make its patches, or 206-265 hexes inverted). [in] sides, j.
bool runsOn(const WallSides& sides, const SheetJoin& j) {
  const FaceSide &a = sides.faces[j.a], &b = sides.faces[j.b];
  const bool knife = a.opposite == j.b || b.opposite == j.a;
  return j.folded ? knife : a.side == b.side || knife;
}

// Joins to the largest sheet (roots of `uf` over the wall faces, by area) every sheet whose wall faces all lie on the
// planes of its wall faces on their sides: the plate's disc inside a tube fused onto a plate that was not bored, cut
// off from the plate by the tube's feet only. (Not two other sheets: a rib's segments either side of a crossing rib
// lie on one pair of planes, and mergeCrossingRibs decides which runs through.) [in] cad, sides; [in,out] uf.
void joinCoplanarSheets(const CadSolid& cad, const WallSides& sides, UnionFind& uf) {
  const double tolerance = 1e-6 * cad.diagonal;
  std::map<int, std::vector<std::pair<int, std::optional<gp_Pln>>>> sheets;  // root -> its faces and their planes
  std::map<int, double> area;
  for (int f = 0; f < static_cast<int>(sides.faces.size()); ++f)
    if (sides.faces[f].side != Side::Lateral) {
      sheets[uf.find(f)].emplace_back(f, planeOf(cad.faces(f + 1), tolerance));
      area[uf.find(f)] += sides.faces[f].area;
    }
  if (sheets.size() < 2) return;
  const int largest = std::max_element(area.begin(), area.end(), [](const auto& a, const auto& b) {
                        return a.second < b.second;
                      })->first;
  const auto& base = sheets[largest];
  for (const auto& [root, faces] : sheets)
    if (root != largest && std::all_of(faces.begin(), faces.end(), [&](const auto& face) {
          return face.second && std::any_of(base.begin(), base.end(), [&](const auto& other) {
                   return other.second && sides.faces[other.first].side == sides.faces[face.first].side &&
                          samePlane(*face.second, *other.second, tolerance, kSamePlaneAngle);
                 });
        }))
      uf.unite(root, largest);
}

}  // namespace

namespace {

// A thickness step (thicknessSteps): its side (a lateral face), the thinner wall's face and the thicker one's.
struct Step {
  int side = -1, thin = -1, thick = -1;
};

std::vector<Step> stepsOf(const CadSolid& cad, const WallSides& sides, double highest) {
  const int n = static_cast<int>(sides.faces.size());
  auto isWall = [&](int f) { return sides.faces[f].side != Side::Lateral; };
  struct Meeting {
    int wall = -1, edge = -1;
  };
  auto normal = [&](const Meeting& m) {  // the wall's outward normal at the middle of the edge
    return normalAtEdge(TopoDS::Face(cad.faces(m.wall + 1)), TopoDS::Edge(cad.edges(m.edge + 1)));
  };
  std::vector<std::vector<Meeting>> concave(n), convex(n);  // per lateral face, the walls it meets so, and where
  for (const FacePairEdge& e : sharpEdges(cad))
    if (const auto [wall, side] = isWall(e.a) ? std::pair(e.a, e.b) : std::pair(e.b, e.a);
        isWall(wall) && !isWall(side))
      (e.concave ? concave : convex)[side].push_back({wall, e.edge});
  std::vector<Step> steps;
  for (int r = 0; r < n; ++r)
    for (const Meeting& a : concave[r])
      for (const Meeting& b : convex[r]) {
        const FaceSide &thin = sides.faces[a.wall], &thick = sides.faces[b.wall], &side = sides.faces[r];
        if (thin.side == thick.side && side.width < highest * thin.thickness &&
            thick.thickness > thin.thickness + 0.5 * side.width && normal(a).dot(normal(b)) > kStepCos)
          steps.push_back({r, a.wall, b.wall});
      }
  return steps;
}

// A sheet that stands on one column's top alone (a pin's narrower part on its shoulder: it meets no other sheet in a
// concave edge, and the column's faces only where they face up the column, within kMaxColumnDraft of its axis, the
// outward normal of the wall it stands on at its feet) is part of that column, whose ledge it stands on
// (column_piece.hpp): its faces join the column's, its area and volume are added. The base sheet (the first) stays.
// [in] cad; [in] concave: its concave edges (concaveEdges); [in,out] sheets: findSheets's, the columns last.
void joinSheetsOnColumns(const CadSolid& cad, const std::vector<FacePairEdge>& concave, std::vector<Sheet>& sheets) {
  if (std::none_of(sheets.begin(), sheets.end(), [](const Sheet& s) { return s.column; })) return;
  std::vector<int> owner(cad.faces.Extent(), -1);
  for (std::size_t s = 0; s < sheets.size(); ++s)
    for (int f : sheets[s].faces) owner[f] = static_cast<int>(s);
  auto normal = [&](int face, int edge) {
    return normalAtEdge(TopoDS::Face(cad.faces(face + 1)), TopoDS::Edge(cad.edges(edge + 1)));
  };
  std::vector<std::set<int>> meets(sheets.size());
  for (const FacePairEdge& c : concave)
    if (const int a = owner[c.a], b = owner[c.b]; a >= 0 && b >= 0 && a != b) meets[a].insert(b), meets[b].insert(a);
  // per column, the sum of the outward normals of the walls it stands on (of the sheets that meet others too)
  std::vector<Vec3> axis(sheets.size(), Vec3::Zero());
  for (const FacePairEdge& c : concave)
    if (const int a = owner[c.a], b = owner[c.b]; a >= 0 && b >= 0 && sheets[a].column != sheets[b].column) {
      const int wall = sheets[a].column ? b : a;
      if (wall == 0 || meets[wall].size() > 1) axis[sheets[a].column ? a : b] += normal(wall == a ? c.a : c.b, c.edge);
    }
  auto onTop = [&](int s, int column) {  // every concave edge of s with the column on a face of it facing up
    const Vec3 up = axis[column].normalized();
    return std::all_of(concave.begin(), concave.end(), [&](const FacePairEdge& c) {
      const int a = owner[c.a], b = owner[c.b];
      if (!((a == s && b == column) || (a == column && b == s))) return true;
      return normal(a == column ? c.a : c.b, c.edge).dot(up) >= std::cos(kMaxColumnDraft);
    });
  };
  std::vector<char> joined(sheets.size(), 0);
  for (std::size_t s = 1; s < sheets.size(); ++s) {
    if (sheets[s].column || meets[s].size() != 1) continue;
    const int c = *meets[s].begin();
    if (!sheets[c].column || axis[c].isZero() || !onTop(static_cast<int>(s), c)) continue;
    Sheet& column = sheets[c];
    column.faces.insert(column.faces.end(), sheets[s].faces.begin(), sheets[s].faces.end());
    std::sort(column.faces.begin(), column.faces.end());
    column.centre = (column.area * column.centre + sheets[s].area * sheets[s].centre) / (column.area + sheets[s].area);
    column.area += sheets[s].area, column.volume += sheets[s].volume;
    joined[s] = 1;
  }
  std::vector<Sheet> kept;
  for (std::size_t s = 0; s < sheets.size(); ++s)
    if (!joined[s]) kept.push_back(std::move(sheets[s]));
  sheets = std::move(kept);
}

// standingColumns with the solid's concave edges given (concaveEdges). [in] cad, sides, concave.
std::vector<Sheet> standingColumnsAt(const CadSolid& cad, const WallSides& sides,
                                     const std::vector<FacePairEdge>& concave) {
  const int n = static_cast<int>(sides.faces.size());
  auto isWall = [&](int f) { return sides.faces[f].side != Side::Lateral; };
  std::vector<char> candidate(n, 0);  // lateral, no cut face, meets no wall in a smooth or convex edge
  for (int f = 0; f < n; ++f) candidate[f] = !isWall(f) && !isCutFace(cad, f);
  for (const SheetJoin& j : sides.sheetJoins)
    if (isWall(j.a) != isWall(j.b)) candidate[isWall(j.a) ? j.b : j.a] = 0;
  UnionFind uf(n);
  const std::vector<std::set<int>> next = faceNeighbours(cad);
  for (int f = 0; f < n; ++f)
    for (int g : next[f])
      if (candidate[f] && candidate[g]) uf.unite(f, g);
  std::map<int, Vec3> foot;  // per group root standing on a wall: a point of its first concave edge with one
  for (const FacePairEdge& c : concave)
    if (isWall(c.a) != isWall(c.b))
      if (const int f = isWall(c.a) ? c.b : c.a; candidate[f])
        foot.emplace(uf.find(f), edgeMiddle(cad.edges(c.edge + 1)));
  // or through a fillet at its foot (smooth with a wall, concave, of a radius below the wall's thickness), which the
  // pipeline removes before the cut (foot_fillets.hpp)
  for (const SheetJoin& j : sides.sheetJoins)
    if (const int f = isWall(j.a) ? j.b : j.a; j.smooth && isWall(j.a) != isWall(j.b))
      if (const std::optional<double> r = filletRadius(cad.faces(f + 1)); r && *r < sides.thickness)
        for (int g : next[f])
          if (candidate[g])
            foot.emplace(uf.find(g), faceCentre(cad.faces(f + 1), sides.faces[f].area) / sides.faces[f].area);
  std::vector<Sheet> columns;
  for (const auto& [root, at] : foot) {
    std::vector<int> faces;
    for (int f = 0; f < n; ++f)
      if (candidate[f] && uf.find(f) == root) faces.push_back(f);
    if (smallFeature(cad, sides, faces)) continue;
    Sheet column = columnOf(cad, sides, faces, at);
    // at the wall's level (a bore's floor) or below it (a dent: a drill point's cone)
    if (column.volume <= kStandsOut * column.area * sides.thickness) continue;
    columns.push_back(std::move(column));
  }
  std::stable_sort(columns.begin(), columns.end(), [](const Sheet& a, const Sheet& b) { return a.area > b.area; });
  return columns;
}

}  // namespace

std::vector<std::pair<int, int>> thicknessSteps(const CadSolid& cad, const WallSides& sides, double highest) {
  std::vector<std::pair<int, int>> steps;
  for (const Step& s : stepsOf(cad, sides, highest))
    steps.emplace_back(std::min(s.thin, s.thick), std::max(s.thin, s.thick));
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

std::vector<char> thicknessStepSides(const CadSolid& cad, const WallSides& sides) {
  std::vector<char> side(sides.faces.size(), 0);
  for (const Step& s : stepsOf(cad, sides, kStepWalls)) side[s.side] = 1;
  return side;
}

std::string sheetPlace(const CadSolid& cad, const Sheet& s) {
  std::ostringstream out;
  const Vec3 c = s.centre / cad.unit;
  out << "(" << c.x() << ", " << c.y() << ", " << c.z() << ")";
  return out.str();
}

Sheet sheetOf(const CadSolid& cad, const WallSides& sides, const std::vector<int>& faces) {
  Sheet s;
  for (int f : faces) {
    s.faces.push_back(f);
    s.area += sides.faces[f].area;
    s.volume += 0.5 * sides.faces[f].area * sides.faces[f].thickness;
    s.centre += faceCentre(cad.faces(f + 1), sides.faces[f].area);
  }
  s.centre /= std::max(s.area, 1e-30);
  return s;
}

std::vector<Sheet> findSheets(const CadSolid& cad, const WallSides& sides) {
  const int n = static_cast<int>(sides.faces.size());
  auto isWall = [&](int f) { return f >= 0 && sides.faces[f].side != Side::Lateral; };
  UnionFind uf(n);
  for (const SheetJoin& j : sides.sheetJoins)
    if (isWall(j.a) && isWall(j.b) && runsOn(sides, j)) uf.unite(j.a, j.b);
  for (int f = 0; f < n; ++f)
    if (isWall(f) && isWall(sides.faces[f].opposite)) uf.unite(f, sides.faces[f].opposite);
  for (const auto& [a, b] : thicknessSteps(cad, sides)) uf.unite(a, b);
  joinCoplanarSheets(cad, sides, uf);
  std::map<int, std::vector<int>> byRoot;
  for (int f = 0; f < n; ++f)
    if (isWall(f)) byRoot[uf.find(f)].push_back(f);
  std::vector<Sheet> sheets;
  for (const auto& [root, faces] : byRoot) sheets.push_back(sheetOf(cad, sides, faces));
  std::stable_sort(sheets.begin(), sheets.end(), [](const Sheet& a, const Sheet& b) { return a.area > b.area; });
  if (sheets.empty()) return sheets;
  const std::vector<FacePairEdge> concave = concaveEdges(cad);
  const std::vector<Sheet> columns = standingColumnsAt(cad, sides, concave);
  sheets.insert(sheets.end(), columns.begin(), columns.end());
  joinSheetsOnColumns(cad, concave, sheets);
  return sheets;
}

std::vector<Sheet> standingColumns(const CadSolid& cad, const WallSides& sides) {
  return standingColumnsAt(cad, sides, concaveEdges(cad));
}

std::vector<int> wallSheetOfFaces(const std::vector<Sheet>& sheets, std::size_t faces) {
  std::vector<int> sheet(faces, -1);
  for (std::size_t s = 0; s < sheets.size(); ++s)
    for (int f : sheets[s].faces) sheet[f] = static_cast<int>(s);
  return sheet;
}

void keepFirstSheet(const std::vector<Sheet>& sheets, WallSides& sides) {
  for (std::size_t s = 1; s < sheets.size(); ++s)
    for (int f : sheets[s].faces) sides.faces[f].side = Side::Lateral;
}

}  // namespace hexlayer
