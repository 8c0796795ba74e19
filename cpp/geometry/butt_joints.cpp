#include "geometry/butt_joints.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Plane.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <set>

#include "geometry/mixed_faces.hpp"
#include "geometry/sheet_edges.hpp"
#include "geometry/sheet_junctions.hpp"

namespace hexlayer {
namespace {

constexpr double kPlanar = 1e-7;    // times the part's diagonal: a face this near a plane is planar
constexpr int kSectionSamples = 8;  // points along a section edge, less one, asked whether inside the face

// The edges where the plane crosses the face's inside: the section's edges with a point inside the face (one may run
// on along its boundary: the General Fuse merges that part with the boundary's edge), not those all along it.
// [in] cad, face, plane.
std::vector<TopoDS_Edge> sectionInside(const CadSolid& cad, int face, const gp_Pln& plane) {
  const TopoDS_Face f = TopoDS::Face(cad.faces(face + 1));
  BRepAlgoAPI_Section section(f, new Geom_Plane(plane));
  if (!section.IsDone()) return {};
  ShapeAnalysis_Surface uv(BRep_Tool::Surface(f));
  BRepTopAdaptor_FClass2d inside(f, BRep_Tool::Tolerance(f));
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer it(section.Shape(), TopAbs_EDGE); it.More(); it.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(it.Current()));
    for (int k = 1; k < kSectionSamples; ++k) {
      const double t = curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * k / kSectionSamples;
      if (inside.Perform(uv.ValueOfUV(curve.Value(t), kPlanar * cad.diagonal)) == TopAbs_IN) {
        edges.push_back(TopoDS::Edge(it.Current()));
        break;
      }
    }
  }
  return edges;
}

// Whether wall face b runs on past rim face c across their inside edge: the point a wall's thickness from the edge's
// middle, along b the way c faces, lies on b (a side wall above a lower end wall's top), not off it (a rim's round
// ending on the face of a wall as high). [in] cad, edge, c, b, thickness.
bool runsOnPast(const CadSolid& cad, int edge, int c, int b, double thickness) {
  const BRepAdaptor_Curve curve(TopoDS::Edge(cad.edges(edge + 1)));
  const gp_Pnt m = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
  const double tolerance = kPlanar * cad.diagonal;
  const TopoDS_Face rim = TopoDS::Face(cad.faces(c + 1)), wall = TopoDS::Face(cad.faces(b + 1));
  const gp_Pnt2d onRim = ShapeAnalysis_Surface(BRep_Tool::Surface(rim)).ValueOfUV(m, tolerance);
  ShapeAnalysis_Surface onWall(BRep_Tool::Surface(wall));
  const gp_Pnt2d at = onWall.ValueOfUV(m, tolerance);
  const Vec3 facing = outwardNormal(rim, onRim.X(), onRim.Y()), n = outwardNormal(wall, at.X(), at.Y());
  const Vec3 along = facing - facing.dot(n) * n;
  if (along.norm() < 1e-6) return false;
  const Vec3 q = toVec(m) + thickness * along.normalized();
  BRepTopAdaptor_FClass2d inside(wall, BRep_Tool::Tolerance(wall));
  return inside.Perform(onWall.ValueOfUV(gp_Pnt(q.x(), q.y(), q.z()), tolerance)) == TopAbs_IN;
}

}  // namespace

std::vector<ButtJoint> findButtJoints(const CadSolid& cad, const WallSides& sides) {
  const std::vector<FacePairEdge> concave = concaveEdges(cad);
  std::set<std::pair<int, int>> inside;  // face pairs sharing a sharp inside edge, both ways
  for (const FacePairEdge& c : concave) inside.emplace(c.a, c.b), inside.emplace(c.b, c.a);
  std::vector<Sheet> sheets = findSheets(cad, sides);  // the walls' (a column has none to butt)
  sheets.erase(std::remove_if(sheets.begin(), sheets.end(), [](const Sheet& s) { return s.column; }), sheets.end());
  const std::vector<int> sheet = wallSheetOfFaces(sheets, sides.faces.size());
  const std::vector<std::set<int>> beside = faceNeighbours(cad);
  const double tolerance = kPlanar * cad.diagonal;
  auto planar = [&](int f) { return planeOf(cad.faces(f + 1), tolerance).has_value(); };
  auto onPlaneOf = [&](int f, int g) {  // f is g, or lies on g's plane (a wall split where another ends)
    if (f == g) return true;
    const std::optional<gp_Pln> p = planeOf(cad.faces(f + 1), tolerance), q = planeOf(cad.faces(g + 1), tolerance);
    return p && q && samePlane(*q, *p, tolerance);
  };
  auto meetsPlaneOf = [&](int a, int b) {  // a meets b, or a face on b's plane, in a sharp inside edge
    return std::any_of(inside.lower_bound({a, -1}), inside.lower_bound({a + 1, -1}),
                       [&](const std::pair<int, int>& ab) { return onPlaneOf(ab.second, b); });
  };
  std::set<int> walls;  // A: a rim face C beside it meets B of its sheet in an inside edge, and A meets B in one too
  for (const FacePairEdge& e : concave)
    for (const auto& [c, b] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}})
      if (sheet[c] < 0 && sheet[b] >= 0 && runsOnPast(cad, e.edge, c, b, sides.thickness))
        for (int a : beside[c])
          if (a != b && sheet[a] == sheet[b] && meetsPlaneOf(a, b)) walls.insert(a);
  std::vector<ButtJoint> joints;
  for (int a : walls) {
    ButtJoint j{a, sides.faces[a].opposite, {}};
    if (j.outside < 0 || sheet[j.outside] != sheet[a] || !planar(j.outside)) continue;
    for (int b = 0; b < static_cast<int>(sheet.size()); ++b)
      if (b != a && sheet[b] == sheet[a] && inside.count({a, b})) j.bases.push_back(b);
    if (std::all_of(j.bases.begin(), j.bases.end(), planar)) joints.push_back(std::move(j));
  }
  return joints;
}

std::size_t splitButtJoints(CadSolid& cad, WallSides& sides) {
  const std::vector<ButtJoint> joints = findButtJoints(cad, sides);
  TopTools_ListOfShape arguments, tools;
  std::set<int> split;
  for (const ButtJoint& j : joints)
    for (int b : j.bases)
      for (const TopoDS_Edge& e : sectionInside(cad, j.outside, *planeOf(cad.faces(b + 1), kPlanar * cad.diagonal)))
        tools.Append(e), split.insert(j.outside);
  if (tools.IsEmpty()) return 0;
  CadSolid pieces;
  try {
    arguments.Append(cad.solid);
    BRepAlgoAPI_Splitter splitter;  // the General Fuse: the edges imprinted where they cross each other too
    splitter.SetArguments(arguments);
    splitter.SetTools(tools);
    splitter.Build();
    if (!splitter.IsDone()) return 0;
    pieces = namedPieces(cad, splitter);
    if (pieces.faces.Extent() <= cad.faces.Extent()) return 0;
  } catch (const Standard_Failure&) {
    return 0;
  }
  sides = classifyWallSidesAfterSplit(pieces, cad, sides);
  cad = std::move(pieces);
  return split.size();
}

}  // namespace hexlayer
