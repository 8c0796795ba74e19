#include "geometry/wall_sides.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "core/union_find.hpp"
#include "geometry/bend_rounds.hpp"
#include "geometry/boundary_triangles.hpp"
#include "geometry/face_sampling.hpp"
#include "geometry/ray_caster.hpp"
#include "geometry/sheet_edges.hpp"

namespace hexlayer {
namespace {

constexpr int kRaysPerFace = 150;
constexpr double kMaxSlenderness = 0.25;  // wall thickness over the part's diagonal
// The same for a junction piece (a solid with a cut face): the part it was cut from passed kMaxSlenderness; a short
// thick rib or a block standing against a wall (a tab 2.5 walls thick, 3 long) is chunky by itself once cut off at its
// foot. A piece whose wall is about as thick as its other sides are long (a cube: 1 / sqrt(3)) is still refused.
constexpr double kMaxPieceSlenderness = 0.45;
// Wall faces facing a wall on their own side, as a share of the wall area, above which the sheet branches.
constexpr double kMaxJunctionAreaShare = 0.02;
// A ray crosses the wall when its middle is farther than this share of its half-length from every boundary
// point: 1/1.3 takes walls inclined to each other by up to about 40 degrees (a taper, a wedge) and leaves
// out rim faces that meet the walls more steeply (a 45 degree chamfer or oblique cut, a plane cutting a shell).
constexpr double kMiddleClearance = 1 / 1.3;
constexpr double kMinSplitShare = 0.25;  // a wall split into pieces: the least share of a piece's rays crossing it
constexpr double kAirGapReach = 1.5;     // x the wall's thickness: the air gaps looked for (wider ones are no matter)
// A face is a wall face when the rays crossing the wall stand for at least this share of its area, and it
// is at least this share of the wall wide (2 x area / perimeter).
constexpr double kMinWallShare = 0.5, kMinWallWidth = 0.25;
// A face beyond a knife edge at most this many walls wide across the edge is an oblique rim: its last hexes
// are sheared by the cut, to a scaled Jacobian of about 1 / this (the cosine of the cut's tilt) at worst.
constexpr double kMaxObliqueRim = 3.2;
// A rim-like face tangent to a wall face whose rays land where that wall's do, at the wall's thickness within this
// share, carries the wall on (wallExtensions).
constexpr double kExtensionThickness = 0.15;
// Of the part's diagonal: a face's samples this near another face's surface lie on it (a face split on its surface).
constexpr double kOnSurface = 1e-6;
constexpr int kSurfaceSamples = 8;  // of a face's ray samples, checked to lie on the other face's surface
// A wall's extension faces the way the wall does within this angle (mean normals): a piece of the same plane or of a
// gently curved wall, not a piece of a round that turns away from it.
constexpr double kExtensionTurn = 10 * M_PI / 180;
// A cut face (a piece's foot) turning less than this from a wall face it meets (their normals at the edge) carries that
// wall's side on (lapFeet).
constexpr double kLapTurn = 60 * M_PI / 180;

struct Ray {
  double length;
  int hitFace;
  double weight;
};

// The rays' weighted median length; 0 without rays.
double weightedMedian(const std::vector<Ray>& rays) {
  std::vector<std::pair<double, double>> weighted;
  weighted.reserve(rays.size());
  for (const Ray& r : rays) weighted.emplace_back(r.length, r.weight);
  return weightedQuantile(std::move(weighted), 0.5);
}

double edgeLength(const TopoDS_Shape& edge) {
  BRepAdaptor_Curve curve(TopoDS::Edge(edge));
  return GCPnts_AbscissaPoint::Length(curve);
}

Vec3 edgeMiddle(const TopoDS_Shape& edge) {
  BRepAdaptor_Curve curve(TopoDS::Edge(edge));
  const gp_Pnt p = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
  return {p.X(), p.Y(), p.Z()};
}

// The inward rays of one face's samples: where each first meets the boundary again.
struct FaceRays {
  std::vector<Ray> all;            // every ray that hit
  std::vector<Ray> crossing;       // the rays that cross the wall (crossesWall)
  double sampledArea = 0;          // of all samples, hit or not
  std::vector<RayMark> marks;      // every sample
  Vec3 meanNormal = Vec3::Zero();  // area-weighted outward normal
  double airGap = 0;               // the narrowest gap in front of the wall (airGapAhead), 0: none
};

// Whether the inward ray from p (unit direction `inward`, first hit at `length`) crosses the wall from
// one side to the other: the middle of the ray is then about as far from every boundary point as from
// its two ends, like the centre of the wall's inscribed ball. A ray from a rim runs along the wall and
// its middle lies near the walls (a flat rim, the outer part of a round rim); a ray from a rim face that
// meets the walls at more than about 40 degrees (a chamfer, a rim cut obliquely) starts close to the wall
// it leaves. Decided per sample, so a face that is partly wall and partly rim is measured as it is.
bool crossesWall(const BoundaryTriangles& boundary, const Vec3& p, const Vec3& inward, double length) {
  return boundary.noTriangleWithin(p + 0.5 * length * inward, kMiddleClearance * 0.5 * length);
}

// How far the solid is in front of a wall sample, across the air (a hem folded back over its sheet, the legs of a
// narrow U, a slot between two walls): the outward ray's first hit within kAirGapReach x the wall's thickness there.
// [in] rays; [in] p, outward: the sample and its unit normal; [in] thickness: its inward ray's length; [in] skip.
// Returns the distance, 0 if none.
double airGapAhead(RayCaster& rays, const Vec3& p, const Vec3& outward, double thickness, double skip) {
  const std::optional<RayHit> hit = rays.nearest(p, outward, skip, kAirGapReach * thickness);
  return hit ? hit->w : 0;
}

// Hits nearer than this share of the part's diagonal are the sample's own face.
double raySkip(const CadSolid& cad) { return 1e-5 * cad.diagonal; }

// The inward ray of a mark (its sample): the face it first meets and how far, none beyond twice the part's diagonal.
// [in,out] m; [in] rays, cad.
void castMark(RayMark& m, RayCaster& rays, const CadSolid& cad) {
  const std::optional<RayHit> hit = rays.nearest(m.point, -m.normal, raySkip(cad), 2 * cad.diagonal);
  m.hitFace = hit ? hit->face : -1, m.length = hit ? hit->w : 0;
}

// Whether a mark's ray crosses the wall, and if so the air gap in front of its sample (airGapAhead, unless `gap` is
// given: the same ray's, measured before). [in,out] m; [in] boundary, rays, cad; [in] gap.
void markCrossing(RayMark& m, const BoundaryTriangles& boundary, RayCaster& rays, const CadSolid& cad,
                  std::optional<double> gap = std::nullopt) {
  m.crossing = m.hitFace >= 0 && crossesWall(boundary, m.point, -m.normal, m.length);
  m.airGap = !m.crossing ? 0 : gap ? *gap : airGapAhead(rays, m.point, m.normal, m.length, raySkip(cad));
}

// A face's rays from its marks (every sample, in order). [in] marks.
FaceRays raysOfMarks(std::vector<RayMark> marks) {
  FaceRays out;
  for (const RayMark& m : marks) {
    out.meanNormal += m.area * m.normal;
    out.sampledArea += m.area;
    if (m.hitFace < 0) continue;
    const Ray ray{m.length, m.hitFace, m.area};
    out.all.push_back(ray);
    if (!m.crossing) continue;
    out.crossing.push_back(ray);
    if (m.airGap > 0) out.airGap = out.airGap > 0 ? std::min(out.airGap, m.airGap) : m.airGap;
  }
  out.marks = std::move(marks);
  return out;
}

// Casts rays from the face's samples inward and records how far the boundary is and which face it is; from the
// samples whose ray crosses the wall, outward too (airGapAhead).
FaceRays castInwardRays(const CadSolid& cad, const BoundaryTriangles& boundary, RayCaster& rays, int f) {
  const TopoDS_Shape& face = cad.faces(f + 1);
  const double spacing = std::sqrt(std::max(triangulatedArea(face), 1e-30) / kRaysPerFace);
  std::vector<RayMark> marks;
  for (const FaceSample& s : sampleFace(face, spacing)) {
    RayMark m{s.u, s.v, s.area, s.point, s.normal};
    castMark(m, rays, cad);
    markCrossing(m, boundary, rays, cad);
    marks.push_back(m);
  }
  return raysOfMarks(std::move(marks));
}

// The rays of a face left as it was by a split, from its marks before: a ray that hit a face left as it was hits it
// still (renumbered), one that hit a face split is cast again; whether each crosses the wall is asked again (the
// split faces' triangles are new), the air gap in front kept where it was measured. [in] cad; [in] marks: before;
// [in] faceNow: per face before, its index in cad if left as it was, else -1; [in] boundary, rays.
FaceRays reusedRays(const CadSolid& cad, std::vector<RayMark> marks, const std::vector<int>& faceNow,
                    const BoundaryTriangles& boundary, RayCaster& rays) {
  for (RayMark& m : marks) {
    const std::optional<double> gap = m.crossing ? std::optional<double>(m.airGap) : std::nullopt;
    if (m.hitFace >= 0 && faceNow[m.hitFace] >= 0)
      m.hitFace = faceNow[m.hitFace];
    else if (m.hitFace >= 0)
      castMark(m, rays, cad);
    markCrossing(m, boundary, rays, cad, gap);
  }
  return raysOfMarks(std::move(marks));
}

int dominantHit(const std::vector<Ray>& rays) {
  std::map<int, double> weight;
  for (const Ray& r : rays) weight[r.hitFace] += r.weight;
  int best = -1;
  double bestWeight = 0;
  for (const auto& [face, w] : weight)
    if (w > bestWeight) best = face, bestWeight = w;
  return best;
}

// Whether face f lies on face g's surface (the untrimmed one: a plane, a cylinder, any), as a face split into two
// does: up to kSurfaceSamples of its ray samples within kOnSurface of it. [in] cad, w, f, g.
bool onSurfaceOf(const CadSolid& cad, const WallSides& w, int f, int g) {
  const std::vector<RayMark>& marks = w.faces[f].marks;
  if (marks.empty()) return false;
  const BRepAdaptor_Surface surface(TopoDS::Face(cad.faces(f + 1)));
  const Handle(Geom_Surface) other = BRep_Tool::Surface(TopoDS::Face(cad.faces(g + 1)));
  const std::size_t step = std::max<std::size_t>(1, marks.size() / kSurfaceSamples);
  for (std::size_t k = 0; k < marks.size(); k += step) {
    GeomAPI_ProjectPointOnSurf onOther(surface.Value(marks[k].u, marks[k].v), other);
    if (onOther.NbPoints() == 0 || onOther.LowerDistance() > kOnSurface * cad.diagonal) return false;
  }
  return true;
}

// Lateral faces f beside a wall face g in a smooth edge (a sheet join: a wall face split there), at least a quarter
// wall wide, facing as g does (kExtensionTurn), for which also(f, g), and on g's surface. [in] cad, w; [in]
// meanNormal: per face; [in] also. Returns the faces, ascending.
template <class Also>
std::vector<int> smoothWallNeighbours(const CadSolid& cad, const WallSides& w, const std::vector<Vec3>& meanNormal,
                                      Also also) {
  std::set<int> found;
  for (const SheetJoin& j : w.sheetJoins)
    for (auto [f, g] : {std::pair{j.a, j.b}, std::pair{j.b, j.a}}) {
      const FaceSide &fs = w.faces[f], &wall = w.faces[g];
      if (!j.smooth || fs.side != Side::Lateral || wall.side == Side::Lateral ||
          fs.width < kMinWallWidth * fs.thickness || angleBetween(meanNormal[f], meanNormal[g]) > kExtensionTurn ||
          !also(f, g))
        continue;
      if (onSurfaceOf(cad, w, f, g)) found.insert(f);
    }
  return {found.begin(), found.end()};
}

// Lateral faces that are pieces of a wall split along a line: on the surface of a wall face they meet in a smooth edge,
// facing as it does (kExtensionTurn), at least a quarter wall wide, a quarter of their rays crossing the wall
// (kMinSplitShare), and the two faces' rays together crossing it as a wall's do (kMinWallShare). A wall split a wall or
// two from where it bends sharply into another (a wall standing on a flange's end, split just under it) leaves a strip
// whose rays near the bend run into the other wall: about half of them cross. [in] cad; [in] w: the first
// classification; [in] meanNormal: per face. Returns the faces, ascending.
std::vector<int> splitWallPieces(const CadSolid& cad, const WallSides& w, const std::vector<Vec3>& meanNormal) {
  return smoothWallNeighbours(cad, w, meanNormal, [&](int f, int g) {
    const FaceSide &fs = w.faces[f], &wall = w.faces[g];
    const double together =
        (fs.wallShare * fs.area + wall.wallShare * wall.area) / std::max(fs.area + wall.area, 1e-300);
    return fs.wallShare >= kMinSplitShare && together >= kMinWallShare;
  });
}

// Lateral cut faces (a piece's feet) that lie along the piece's wall: meeting a wall face in an edge where it turns
// less than kLapTurn, and a quarter of their rays crossing the wall (kMinSplitShare) or turning less than that from
// every wall face they meet (a boss merged into a box's wall, cut off along the wall: its flat face to face with the
// wall carries its outer side on; where the flat is wider than its bore, the rays from the flat's ends run along the
// boss to its far side; its foot on a round filling the box's inside corner, going on from the flat, has few rays
// crossing). A foot across a wall (a rib's, a boss's on the floor) meets its walls square. Faces found count as walls
// for the next. [in] cad, w. Returns the faces, ascending.
std::vector<int> lapFeet(const CadSolid& cad, const WallSides& w) {
  std::set<int> found;
  std::map<int, std::vector<double>> turns;  // per lateral cut face: its turns to the wall faces it meets
  for (std::size_t before = 1; found.size() != before;) {
    before = found.size();
    turns.clear();
    for (const SheetJoin& j : w.sheetJoins)
      for (auto [f, g] : {std::pair{j.a, j.b}, std::pair{j.b, j.a}})
        if (isCutFace(cad, f) && w.faces[f].side == Side::Lateral && !found.count(f) && j.edge >= 0 &&
            (w.faces[g].side != Side::Lateral || found.count(g))) {
          const TopoDS_Edge& edge = TopoDS::Edge(cad.edges(j.edge + 1));
          const Vec3 nf = normalAtEdge(TopoDS::Face(cad.faces(f + 1)), edge);
          const Vec3 ng = normalAtEdge(TopoDS::Face(cad.faces(g + 1)), edge);
          if (!nf.isZero() && !ng.isZero()) turns[f].push_back(angleBetween(nf, ng));
        }
    for (const auto& [f, t] : turns)
      if (*std::min_element(t.begin(), t.end()) < kLapTurn &&
          (w.faces[f].wallShare >= kMinSplitShare || *std::max_element(t.begin(), t.end()) < kLapTurn))
        found.insert(f);
  }
  return {found.begin(), found.end()};
}

// Lateral faces that are a short wall's: flat, at least a quarter wall wide (kMinWallWidth, as every wall face), a
// quarter of their rays crossing the wall (kMinSplitShare) to a flat wall face whose normal is opposite theirs (within
// kExtensionTurn), at about its thickness (kExtensionThickness). A wall about two thicknesses high between the floor it
// stands on and a ledge (a lid's lip cut out of its top) has fewer than half its rays crossing: those from the floor's
// end and near the ledge run along a wall; taken for a rim, the wall's inner face and its lip became a sheet standing
// on the floor (exit 4). A rim face turns away from the wall faces its rays reach (a chamfer, an oblique cut) or is not
// flat (a round). [in] cad; [in] w: the first classification; [in] meanNormal: per face. Returns the faces, ascending.
std::vector<int> shortWallFaces(const CadSolid& cad, const WallSides& w, const std::vector<Vec3>& meanNormal) {
  std::vector<int> found;
  for (int f = 0; f < static_cast<int>(w.faces.size()); ++f) {
    const FaceSide& fs = w.faces[f];
    if (fs.side != Side::Lateral || fs.wallShare < kMinSplitShare || fs.width < kMinWallWidth * fs.thickness ||
        fs.opposite < 0)
      continue;
    const FaceSide& across = w.faces[fs.opposite];
    if (across.side == Side::Lateral || angleBetween(meanNormal[f], -meanNormal[fs.opposite]) > kExtensionTurn ||
        std::abs(fs.thickness - across.thickness) > kExtensionThickness * across.thickness)
      continue;
    // both flat: a curved face's mean normal says little of where it faces (a bore's, all round, is about zero and
    // points anywhere: of a boss's two flat sides, one was taken for a wall and the other not)
    if (planeOf(cad.faces(f + 1), kOnSurface * cad.diagonal) &&
        planeOf(cad.faces(fs.opposite + 1), kOnSurface * cad.diagonal))
      found.push_back(f);
  }
  return found;
}

// Lateral faces that carry a wall on: on the surface of a wall face they meet in a smooth edge (a wall face split
// there), facing as it does (kExtensionTurn), narrower than the wall is thick, their rays landing mostly on the face
// that wall's rays cross to or on a face on its surface (split there too), at the wall's thickness
// (kExtensionThickness), though most pass a rim on the way and do not count as crossing the wall: a narrow ring of a
// plate round a hole (a boss's bore bottom over a hole through the plate, a top face split round a hole). A rim's
// round meets a wall in a smooth edge too, but off its surface; the part of a round split off as a rim (mixed_faces)
// lies on the wall part's surface but turns away from it. [in] cad; [in] w: the first classification; [in] landing:
// per face, the face most of its rays land on; [in] meanNormal: per face, its area-weighted normal. Returns the faces,
// ascending.
std::vector<int> wallExtensions(const CadSolid& cad, const WallSides& w, const std::vector<int>& landing,
                                const std::vector<Vec3>& meanNormal) {
  return smoothWallNeighbours(cad, w, meanNormal, [&](int f, int g) {
    const FaceSide& fs = w.faces[f];
    const int lands = landing[f], across = w.faces[g].opposite;
    return lands >= 0 && lands != f && across >= 0 && fs.width < w.thickness &&
           !(std::abs(fs.thickness - w.thickness) > kExtensionThickness * w.thickness) &&
           (lands == across || onSurfaceOf(cad, w, lands, across));
  });
}

// Union-find whose links carry a parity: 0 = same side, 1 = opposite sides.
struct ParityUnionFind {
  std::vector<int> parent, parity;
  explicit ParityUnionFind(int n) : parent(n), parity(n, 0) { std::iota(parent.begin(), parent.end(), 0); }
  std::pair<int, int> find(int a) {
    int p = 0;
    while (parent[a] != a) p ^= parity[a], a = parent[a];
    return {a, p};
  }
  // Returns false when the constraint contradicts the ones before.
  bool unite(int a, int b, int relation) {
    auto [ra, pa] = find(a);
    auto [rb, pb] = find(b);
    if (ra == rb) return (pa ^ pb) == relation;
    parent[std::max(ra, rb)] = std::min(ra, rb);
    parity[std::max(ra, rb)] = pa ^ pb ^ relation;
    return true;
  }
};

// Total length of the edges faces a and b (0-based) share.
double sharedEdgeLength(const CadSolid& cad, int a, int b) {
  TopTools_IndexedMapOfShape edgesOfA;
  TopExp::MapShapes(cad.faces(a + 1), TopAbs_EDGE, edgesOfA);
  double length = 0;
  TopTools_IndexedMapOfShape edgesOfB;
  TopExp::MapShapes(cad.faces(b + 1), TopAbs_EDGE, edgesOfB);
  for (int e = 1; e <= edgesOfB.Extent(); ++e)
    if (edgesOfA.Contains(edgesOfB(e))) length += edgeLength(edgesOfB(e));
  return length;
}

// The smaller face of each knife edge, when it is at most kMaxObliqueRim walls wide across the edge.
std::vector<int> obliqueRimFaces(const CadSolid& cad, const WallSides& w) {
  std::vector<int> rims;
  for (const SheetJoin& k : w.knifeEdges) {
    const int face = w.faces[k.a].area <= w.faces[k.b].area ? k.a : k.b;
    const double across = w.faces[face].area / std::max(sharedEdgeLength(cad, k.a, k.b), 1e-30);
    if (across <= kMaxObliqueRim * w.thickness && std::find(rims.begin(), rims.end(), face) == rims.end())
      rims.push_back(face);
  }
  std::sort(rims.begin(), rims.end());
  return rims;
}

// thicknessEverywhere: the area-weighted median ray length over all faces, the part's thickness
// where no face is a wall face.
void requireThin(const WallSides& w, const CadSolid& cad, double thicknessEverywhere) {
  std::ostringstream msg;
  const double thickness = w.thickness > 0 ? w.thickness : thicknessEverywhere;
  const double slenderness = thickness / cad.diagonal;
  const bool piece = std::any_of(cad.cutInput.begin(), cad.cutInput.end(), [](char cut) { return cut != 0; });
  const double most = piece ? kMaxPieceSlenderness : kMaxSlenderness;
  if (w.thickness > 0 && w.sheetAreaShare >= 0.5 && slenderness <= most) return;
  msg << "not a thin section: measured thickness " << thickness / cad.unit << " over part size (diagonal) "
      << cad.diagonal / cad.unit << " = " << slenderness << " (a thin " << (piece ? "junction piece" : "section")
      << " has at most " << most << ")";
  if (w.thickness > 0)
    msg << ", top+bottom area share " << w.sheetAreaShare << " (at least 0.5)";
  else
    msg << ", and no face's inward rays cross a wall (their middles are nearer another face than their ends)";
  throw geometryError(msg.str());
}

// Where the wall faces that face a wall on their own side meet other wall faces: the junction lines.
std::vector<Vec3> junctionPoints(const CadSolid& cad, const WallSides& w, const std::vector<int>& faces) {
  std::vector<Vec3> points;
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> walls;
    bool junction = false;
    for (const TopoDS_Shape& f : edgeFaces(e)) {
      const int i = cad.faces.FindIndex(f) - 1;
      if (w.faces[i].side == Side::Lateral) continue;
      walls.push_back(i);
      junction |= std::find(faces.begin(), faces.end(), i) != faces.end();
    }
    if (junction && walls.size() >= 2 && walls[0] != walls[1]) points.push_back(edgeMiddle(edgeFaces.FindKey(e)));
  }
  return points;
}

Error junctionError(const CadSolid& cad, const WallSides& w, const std::vector<int>& faces) {
  const std::vector<Vec3> at = junctionPoints(cad, w, faces);
  std::ostringstream msg;
  msg << "non-manifold chordal surface: the wall branches (a rib, T-junction or boss): ";
  for (std::size_t k = 0; k < faces.size() && k < 4; ++k) msg << (k ? ", " : "") << inputFaceName(cad, faces[k]);
  msg << (faces.size() == 1 ? " faces" : " face") << " a wall on its own side";
  if (!at.empty()) msg << "; junction" << (at.size() > 1 ? "s" : "") << " at";
  for (std::size_t k = 0; k < at.size() && k < 4; ++k) {
    const Vec3 p = at[k] / cad.unit;  // in the input's units
    msg << (k ? "," : "") << " (" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  }
  if (at.size() > 4) msg << " and " << at.size() - 4 << " more";
  return geometryError(msg.str());
}

// A relation between two faces' sides: 0 the same side, 1 opposite sides.
struct SideRelation {
  int a, b, relation;
  double weight;        // area of the rays that tie them (joins: 0, decided by their rank)
  bool smooth = false;  // a smooth edge, which no other relation may undo
  bool folded = false;  // a knife edge or a crevice (SheetJoin::folded): ties no sides
};

// Per face, its group of wall faces that are one surface split into faces (oneSurfaceAcross: a pin's round written
// as two halves, a cylinder in quarters): the smallest face index of the group. Rays crossing from one face of
// a group to another cross a bar the surface wraps round, as a whole pin's round face meets itself: no wall. [in] cad,
// w: its sheetJoins and sides.
std::vector<int> oneSurfaceGroups(const CadSolid& cad, const WallSides& w) {
  UnionFind groups(w.faces.size());
  for (const SheetJoin& j : w.sheetJoins)
    if (w.faces[j.a].side != Side::Lateral && w.faces[j.b].side != Side::Lateral && oneSurfaceAcross(cad, j))
      groups.unite(j.a, j.b);
  std::vector<int> group(w.faces.size());
  for (std::size_t f = 0; f < group.size(); ++f) group[f] = groups.find(static_cast<int>(f));
  return group;
}

// The relations in the order they are trusted: smooth edges (a wall runs on through a bend's tangent edge),
// then faces facing each other across the wall, most ray area first (not two faces of one surface:
// oneSurfaceGroups), then convex sharp edges (a sharp bend; the knife edge of a tapered end, where the two faces
// face each other instead, gives way).
std::vector<SideRelation> rankedRelations(const CadSolid& cad, const WallSides& w,
                                          const std::vector<std::map<int, double>>& across) {
  auto isWall = [&](int f) { return w.faces[f].side != Side::Lateral; };
  const std::vector<int> group = oneSurfaceGroups(cad, w);
  std::vector<SideRelation> smooth, opposite, convex;
  for (const SheetJoin& j : w.sheetJoins)  // not across concave edges: a rib's walls are not the sheet's side
    if (isWall(j.a) && isWall(j.b)) (j.smooth ? smooth : convex).push_back({j.a, j.b, 0, 0, j.smooth, j.folded});
  std::map<std::pair<int, int>, double> pairs;
  for (int f = 0; f < static_cast<int>(across.size()); ++f)
    for (const auto& [g, area] : across[f])
      if (group[g] != group[f] && isWall(f) && isWall(g)) pairs[std::minmax(f, g)] += area;
  for (const auto& [fg, area] : pairs) opposite.push_back({fg.first, fg.second, 1, area});
  std::stable_sort(opposite.begin(), opposite.end(),
                   [](const SideRelation& x, const SideRelation& y) { return x.weight > y.weight; });
  std::vector<SideRelation> all = std::move(smooth);
  all.insert(all.end(), opposite.begin(), opposite.end());
  all.insert(all.end(), convex.begin(), convex.end());
  return all;
}

// Same side across shared edges, opposite sides across the wall; returns (group, parity) per face.
// Walls facing a wall on their own side (the sheet branches) go into w.ownSideFaces.
std::vector<std::pair<int, int>> solveSides(const CadSolid& cad, WallSides& w,
                                            const std::vector<std::map<int, double>>& across) {
  const int n = static_cast<int>(w.faces.size());
  ParityUnionFind uf(n);
  std::vector<double> against(n, 0.0);  // per face, the ray area of its relations across the wall that failed
  for (const SideRelation& r : rankedRelations(cad, w, across)) {
    if (r.folded) {  // a knife edge where the rays put its faces on the two sides; else a crevice: no tie
      if (const std::pair<int, int> fa = uf.find(r.a), fb = uf.find(r.b);
          fa.first == fb.first && fa.second != fb.second)
        w.knifeEdges.push_back({r.a, r.b, false});
      continue;
    }
    if (uf.unite(r.a, r.b, r.relation)) continue;
    if (r.relation == 1)
      against[r.a] += r.weight, against[r.b] += r.weight;
    else if (!r.smooth)
      w.knifeEdges.push_back({r.a, r.b, false});
    else
      throw geometryError("top and bottom cannot be told apart: " + inputFaceName(cad, r.a) + " and " +
                          inputFaceName(cad, r.b) + " share a smooth edge but lie on opposite sides of the wall");
  }
  double junctionArea = 0, wallArea = 0;
  for (int f = 0; f < n; ++f)
    if (w.faces[f].side != Side::Lateral) wallArea += w.faces[f].area, junctionArea += 0.5 * against[f];
  if (junctionArea > kMaxJunctionAreaShare * wallArea)
    for (int f = 0; f < n; ++f)
      if (against[f] > 0) w.ownSideFaces.push_back(f);
  std::vector<std::pair<int, int>> rootParity(n);
  for (int f = 0; f < n; ++f) rootParity[f] = uf.find(f);
  return rootParity;
}

}  // namespace

double faceWidth(const TopoDS_Shape& face) {
  double perimeter = 0;  // a seam edge is met twice, as the face's boundary runs along it twice
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) perimeter += edgeLength(it.Current());
  return 2 * triangulatedArea(face) / std::max(perimeter, 1e-30);
}

Error ownSideError(const CadSolid& cad, const WallSides& w) { return junctionError(cad, w, w.ownSideFaces); }

WallSides classifyWallSides(const CadSolid& cad) { return classifyWallSides(cad, BoundaryTriangles(cad)); }

namespace {

// Every face's rays, the faces side by side, each thread with its own ray caster. [in] cad; [in] raysOf(rays, f):
// face f's rays. Returns them per face.
template <class FaceRaysOf>
std::vector<FaceRays> raysPerFace(const CadSolid& cad, FaceRaysOf raysOf) {
  const int n = cad.faces.Extent();
  std::vector<FaceRays> faceRays(n);
  ParallelErrors errors;
#pragma omp parallel
  {
    std::optional<RayCaster> rays;  // per thread (its intersectors keep state), built at its first face
#pragma omp for schedule(dynamic)
    for (int f = 0; f < n; ++f)
      errors.run([&] {
        if (!rays) rays.emplace(cad, 1e-7 * cad.diagonal);
        faceRays[f] = raysOf(*rays, f);
      });
  }
  errors.rethrow();
  return faceRays;
}

// The sides and the wall's thickness from every face's rays (classifyWallSides, below in wall_sides.hpp). [in] cad;
// [in] faceRays: per face.
WallSides sidesFromRays(const CadSolid& cad, std::vector<FaceRays> faceRays) {
  const int n = cad.faces.Extent();
  WallSides w;
  w.faces.resize(n);
  std::vector<Vec3> meanNormal(n);
  std::vector<std::map<int, double>> across(n);  // per face: ray area crossing the wall to each face
  std::vector<int> landing(n, -1);               // per face: where most of its rays land
  double totalArea = 0;
  for (int f = 0; f < n; ++f) {
    FaceSide& fs = w.faces[f];
    FaceRays& hits = faceRays[f];
    landing[f] = dominantHit(hits.all);
    meanNormal[f] = hits.meanNormal;
    fs.area = triangulatedArea(cad.faces(f + 1));
    fs.width = faceWidth(cad.faces(f + 1));
    double crossingArea = 0;
    for (const Ray& r : hits.crossing) crossingArea += r.weight, across[f][r.hitFace] += r.weight;
    fs.wallShare = crossingArea / std::max(hits.sampledArea, 1e-300);
    fs.thickness = weightedMedian(hits.crossing.empty() ? hits.all : hits.crossing);
    fs.opposite = dominantHit(hits.crossing);
    fs.airGap = hits.airGap;
    // Top = "wall" for now; a face narrower than a quarter of the wall (a sliver along a bend) carries no bubble.
    fs.side = fs.wallShare >= kMinWallShare && fs.width >= kMinWallWidth * fs.thickness ? Side::Top : Side::Lateral;
    fs.marks = std::move(hits.marks);
    if (!isCutFace(cad, f)) totalArea += fs.area;  // a cut through the part (a piece's foot) is not its surface
  }
  std::vector<Ray> wallThickness, everywhere;
  double wallArea = 0;
  for (const FaceSide& fs : w.faces)
    if (fs.thickness > 0) everywhere.push_back({fs.thickness, 0, fs.area});
  for (const FaceSide& fs : w.faces)
    if (fs.side != Side::Lateral) wallThickness.push_back({fs.thickness, 0, fs.area}), wallArea += fs.area;
  w.thickness = weightedMedian(wallThickness);
  w.sheetAreaShare = wallArea / std::max(totalArea, 1e-30);
  requireThin(w, cad, weightedMedian(everywhere));

  w.sheetJoins = sheetJoins(cad);
  w.bendRounds = findBendRounds(cad, w, across);
  for (int f : w.bendRounds) w.faces[f].side = Side::Top, w.faces[f].thickness = w.thickness;
  for (int f : wallExtensions(cad, w, landing, meanNormal)) w.faces[f].side = Side::Top;
  for (int f : splitWallPieces(cad, w, meanNormal)) w.faces[f].side = Side::Top;
  for (int f : shortWallFaces(cad, w, meanNormal)) w.faces[f].side = Side::Top;
  for (int f : lapFeet(cad, w)) w.faces[f].side = Side::Top;
  std::vector<std::pair<int, int>> rootParity = solveSides(cad, w, across);
  w.obliqueRims = obliqueRimFaces(cad, w);
  if (!w.obliqueRims.empty()) {  // sides again without them
    for (int f : w.obliqueRims) w.faces[f].side = Side::Lateral;
    w.knifeEdges.clear(), w.ownSideFaces.clear();
    rootParity = solveSides(cad, w, across);
  }
  // In each group of connected wall faces, the parity class that faces +z more is Top.
  std::map<int, double> up;
  for (int f = 0; f < n; ++f)
    if (w.faces[f].side != Side::Lateral)
      up[rootParity[f].first] += (rootParity[f].second == 0 ? 1 : -1) * meanNormal[f].z();
  for (int f = 0; f < n; ++f)
    if (w.faces[f].side != Side::Lateral)
      w.faces[f].side = ((rootParity[f].second == 0) == (up[rootParity[f].first] >= 0)) ? Side::Top : Side::Bottom;
  return w;
}

}  // namespace

WallSides classifyWallSides(const CadSolid& cad, const BoundaryTriangles& boundary) {
  return sidesFromRays(
      cad, raysPerFace(cad, [&](RayCaster& rays, int f) { return castInwardRays(cad, boundary, rays, f); }));
}

WallSides classifyWallSidesAfterSplit(const CadSolid& cad, const CadSolid& before, const WallSides& sidesBefore) {
  const BoundaryTriangles boundary(cad);
  std::vector<int> faceNow(before.faces.Extent(), -1), faceBefore(cad.faces.Extent(), -1);
  for (int g = 0; g < before.faces.Extent(); ++g) {
    const int f = cad.faces.FindIndex(before.faces(g + 1)) - 1;  // the same face (IsSame), the same way round
    if (f >= 0 && cad.faces(f + 1).Orientation() == before.faces(g + 1).Orientation())
      faceNow[g] = f, faceBefore[f] = g;
  }
  return sidesFromRays(cad, raysPerFace(cad, [&](RayCaster& rays, int f) {
                         return faceBefore[f] < 0
                                    ? castInwardRays(cad, boundary, rays, f)
                                    : reusedRays(cad, sidesBefore.faces[faceBefore[f]].marks, faceNow, boundary, rays);
                       }));
}

SmallFeatures findSmallFeatures(const CadSolid& cad, const WallSides& sides, double size) {
  SmallFeatures small;
  auto note = [&](int& count, const Vec3& at) {
    if (small.shortEdges + small.narrowFaces == 0) small.firstAt = at;
    ++count;
  };
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    bool onWall = false;
    for (const TopoDS_Shape& f : edgeFaces(e)) onWall |= sides.faces[cad.faces.FindIndex(f) - 1].side != Side::Lateral;
    if (onWall && edgeLength(edgeFaces.FindKey(e)) < size) note(small.shortEdges, edgeMiddle(edgeFaces.FindKey(e)));
  }
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    const FaceSide& face = sides.faces[f];  // a lateral face is about as wide as the wall is thick
    if (face.width >= size || (face.side == Side::Lateral && !narrowLateral(sides, f))) continue;
    TopExp_Explorer edge(cad.faces(f + 1), TopAbs_EDGE);
    note(small.narrowFaces, edge.More() ? edgeMiddle(edge.Current()) : Vec3::Zero());
  }
  return small;
}

namespace {
constexpr double kMinCreaseTurn = 5 * M_PI / 180;  // radians: below it, a cut face goes on along its wall's surface
}  // namespace

std::vector<std::vector<Vec3>> lapCreases(const CadSolid& cad, const WallSides& sides, double step) {
  std::vector<std::vector<Vec3>> creases;
  if (cad.cutInput.empty()) return creases;
  TopTools_IndexedDataMapOfShapeListOfShape facesOf;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, facesOf);
  for (int e = 1; e <= cad.edges.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(cad.edges(e));
    if (!facesOf.Contains(edge) || BRep_Tool::Degenerated(edge)) continue;
    std::vector<int> faces;
    for (const TopoDS_Shape& f : facesOf.FindFromKey(edge))
      if (const int face = cad.faces.FindIndex(f) - 1; face >= 0) faces.push_back(face);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    if (faces.size() != 2 || isCutFace(cad, faces[0]) == isCutFace(cad, faces[1]) ||
        sides.faces[faces[0]].side == Side::Lateral || sides.faces[faces[1]].side == Side::Lateral)
      continue;
    const Vec3 a = normalAtEdge(TopoDS::Face(cad.faces(faces[0] + 1)), edge);
    const Vec3 b = normalAtEdge(TopoDS::Face(cad.faces(faces[1] + 1)), edge);
    if (a.isZero() || b.isZero() || angleBetween(a, b) < kMinCreaseTurn) continue;
    const BRepAdaptor_Curve curve(edge);
    const double first = curve.FirstParameter(), last = curve.LastParameter();
    const int n = std::max(1, static_cast<int>(std::ceil(GCPnts_AbscissaPoint::Length(curve) / step)));
    std::vector<Vec3>& crease = creases.emplace_back();
    for (int k = 0; k <= n; ++k) {
      const gp_Pnt p = curve.Value(first + (last - first) * k / n);
      crease.emplace_back(p.X(), p.Y(), p.Z());
    }
  }
  return creases;
}

}  // namespace hexlayer
