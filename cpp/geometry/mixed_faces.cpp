#include "geometry/mixed_faces.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepFeat_SplitShape.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

namespace hexlayer {
namespace {

constexpr int kMaxSplitRounds = 3;  // rounds of splitting faces that are partly wall, partly rim

constexpr double kWallPiece = 0.7;    // the wall piece: at least this share of its sample area crosses the wall
constexpr double kRimPiece = 0.5;     // the rim piece: less than this share (a rim face's bound, wall_sides.cpp)
constexpr double kRimTurn = 45;       // degrees between the two pieces' mean normals
constexpr double kMinRimArea = 0.1;   // the rim piece at least this many squared wall thicknesses
constexpr double kOneWay = 0.5;       // a piece's mean normal at least this long per area (a half-round: 2 / pi)
constexpr std::size_t kMinMarks = 8;  // samples a face needs to be split
constexpr int kLines = 64;            // parameter lines tried per direction, besides the surface's knots
constexpr double kKnotSlack = 0.05;   // a knot is taken if it misplaces at most this share more of the area

// The knots of the face's surface along u (alongV lines sit on them) or v: where a B-spline skin joins a flat
// to a round, its curvature jumps at a knot.
std::vector<double> knots(const TopoDS_Face& face, bool u) {
  Handle(Geom_Surface) s = BRep_Tool::Surface(face);
  if (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = trimmed->BasisSurface();
  std::vector<double> out;
  if (auto b = Handle(Geom_BSplineSurface)::DownCast(s)) {
    const int n = u ? b->NbUKnots() : b->NbVKnots();
    for (int i = 1; i <= n; ++i) out.push_back(u ? b->UKnot(i) : b->VKnot(i));
  } else if (auto e = Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(s)) {
    if (auto c = Handle(Geom_BSplineCurve)::DownCast(e->BasisCurve()); c && u)
      for (int i = 1; i <= c->NbKnots(); ++i) out.push_back(c->Knot(i));
  }
  return out;
}

struct Piece {
  double area = 0, crossing = 0;
  Vec3 normal = Vec3::Zero();
  double share() const { return area > 0 ? crossing / area : 0; }
};

// A rim piece: the band [from, to) of the face's u (alongV: its lines run along v) or v.
struct Band {
  bool alongV;
  double from, to;
  double coord(const RayMark& m) const { return alongV ? m.u : m.v; }
  bool holds(const RayMark& m) const { return coord(m) >= from && coord(m) < to; }
};

struct Candidate {
  double misplaced;  // sample area on the wrong side of the lines (non-crossing in a wall piece, crossing in the rim
                     // piece)
  std::vector<FaceSplit> splits;  // one line, or two round a rim piece between two wall pieces
  Band rim;
};

double angleDegrees(const Vec3& a, const Vec3& b) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI;
}

// The band [from, to) of the face's parameter as its rim piece, the rest (below `from`, at or above `to`; one of
// them may be empty) as wall pieces, if they part the samples so. The rim must turn away from each wall next to
// it: a wall's normal is taken over a band beside the line as wide (in the parameter) as the rim piece, so a
// curved wall's band along a flat rim is not taken for a rim.
std::optional<Candidate> tryBand(const std::vector<RayMark>& marks, bool alongV, double from, double to,
                                 double thickness, int face) {
  const Band band{alongV, from, to};
  Piece below, above, rim, besideBelow, besideAbove;
  double first = to, last = from;  // the rim samples' extent in the parameter
  for (const RayMark& m : marks) {
    Piece& p = band.holds(m) ? rim : band.coord(m) < from ? below : above;
    p.area += m.area, p.crossing += m.crossing ? m.area : 0, p.normal += m.area * m.normal;
    if (band.holds(m)) first = std::min(first, band.coord(m)), last = std::max(last, band.coord(m));
  }
  const double width = std::max(last - first, 0.0);
  for (const RayMark& m : marks) {
    if (band.coord(m) < from && band.coord(m) >= from - width)
      besideBelow.area += m.area, besideBelow.normal += m.area * m.normal;
    if (band.coord(m) >= to && band.coord(m) < to + width)
      besideAbove.area += m.area, besideAbove.normal += m.area * m.normal;
  }
  if (rim.share() >= kRimPiece || rim.area < kMinRimArea * thickness * thickness ||
      rim.normal.norm() < kOneWay * rim.area)
    return {};
  if (below.area + above.area <= 0) return {};
  Candidate c{rim.crossing, {}, band};
  for (const auto& [wall, beside, at] : {std::tuple{below, besideBelow, from}, std::tuple{above, besideAbove, to}}) {
    if (wall.area <= 0) continue;
    // Each piece must face one way (a band round a tube faces every way), and the two ways differ.
    if (wall.share() < kWallPiece || beside.area <= 0 || beside.normal.norm() < kOneWay * beside.area) return {};
    if (angleDegrees(beside.normal, rim.normal) < kRimTurn) return {};
    c.misplaced += wall.area - wall.crossing;
    c.splits.push_back({face, alongV, at});
  }
  return c;
}

// The largest turn (degrees) from a rim sample's normal to the normal of the wall sample nearest to it in the
// face's parameters. A rim turns away from its wall (a half-round by 180 degrees); a curved wall's band whose rays
// leave through an oblique rim face does not (a sphere's by a few degrees), though its mean normal may.
double largestTurn(const std::vector<RayMark>& marks, const Candidate& c) {
  double largest = 0;
  for (const RayMark& m : marks) {
    if (!c.rim.holds(m)) continue;
    const RayMark* nearest = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (const RayMark& w : marks)
      if (const double d = std::hypot(w.u - m.u, w.v - m.v); !c.rim.holds(w) && d < best) best = d, nearest = &w;
    if (nearest) largest = std::max(largest, angleDegrees(m.normal, nearest->normal));
  }
  return largest;
}

void keepBetter(std::optional<Candidate>& best, std::optional<Candidate> c) {
  if (c && (!best || c->misplaced < best->misplaced)) best = std::move(c);
}

std::optional<std::vector<FaceSplit>> bestSplit(const CadSolid& cad, const FaceSide& fs, double thickness, int f) {
  const TopoDS_Face face = TopoDS::Face(cad.faces(f + 1));
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  std::optional<Candidate> best, bestKnot;
  for (const bool alongV : {true, false}) {
    const double lo = alongV ? u0 : v0, hi = alongV ? u1 : v1;
    const double past = hi + (hi - lo);  // beyond every sample: a band to the face's end
    for (int i = 1; i < kLines; ++i) {
      const double at = lo + (hi - lo) * i / kLines;
      keepBetter(best, tryBand(fs.marks, alongV, at, past, thickness, f));
      keepBetter(best, tryBand(fs.marks, alongV, lo - (hi - lo), at, thickness, f));
    }
    std::vector<double> inner;
    for (double k : knots(face, alongV))
      if (k > lo && k < hi) inner.push_back(k);
    for (std::size_t i = 0; i < inner.size(); ++i) {
      keepBetter(bestKnot, tryBand(fs.marks, alongV, inner[i], past, thickness, f));
      keepBetter(bestKnot, tryBand(fs.marks, alongV, lo - (hi - lo), inner[i], thickness, f));
      for (std::size_t j = i + 1; j < inner.size(); ++j)  // a skin over a wall, its rim and the other wall
        keepBetter(bestKnot, tryBand(fs.marks, alongV, inner[i], inner[j], thickness, f));
    }
  }
  if (bestKnot && (!best || bestKnot->misplaced <= best->misplaced + kKnotSlack * fs.area)) best = bestKnot;
  if (!best || largestTurn(fs.marks, *best) < kRimTurn) return std::nullopt;
  return best->splits;
}

}  // namespace

std::vector<FaceSplit> findMixedFaces(const CadSolid& cad, const WallSides& sides) {
  std::vector<FaceSplit> splits;
  for (int f = 0; f < static_cast<int>(sides.faces.size()); ++f) {
    const FaceSide& fs = sides.faces[f];
    if (fs.marks.size() < kMinMarks || fs.wallShare < kRimPiece) continue;  // a rim face
    if (std::optional<std::vector<FaceSplit>> s = bestSplit(cad, fs, sides.thickness, f))
      splits.insert(splits.end(), s->begin(), s->end());
  }
  return splits;
}

CadSolid splitFaces(const CadSolid& cad, const std::vector<FaceSplit>& splits) {
  try {
    BRepFeat_SplitShape split(cad.solid);
    for (const FaceSplit& s : splits) {
      const TopoDS_Face face = TopoDS::Face(cad.faces(s.face + 1));
      double u0, u1, v0, v1;
      BRepTools::UVBounds(face, u0, u1, v0, v1);
      const Handle(Geom2d_Line) line = s.alongV ? new Geom2d_Line(gp_Pnt2d(s.at, 0), gp_Dir2d(0, 1))
                                                : new Geom2d_Line(gp_Pnt2d(0, s.at), gp_Dir2d(1, 0));
      BRepBuilderAPI_MakeEdge edge(line, BRep_Tool::Surface(face), s.alongV ? v0 : u0, s.alongV ? v1 : u1);
      if (!edge.IsDone()) return {};
      TopoDS_Edge e = edge.Edge();
      BRepLib::BuildCurves3d(e);
      split.Add(e, face);
    }
    split.Build();
    if (!split.IsDone()) return {};
    TopExp_Explorer solids(split.Shape(), TopAbs_SOLID);
    if (!solids.More()) return {};
    CadSolid out = prepareSolid(TopoDS::Solid(solids.Current()), 1);
    out.unit = cad.unit;
    out.inputFace.assign(out.faces.Extent(), -1);
    for (int f = 1; f <= cad.faces.Extent(); ++f) {
      const int kept = out.faces.FindIndex(cad.faces(f));
      if (kept > 0) out.inputFace[kept - 1] = inputFaceOf(cad, f - 1);
      for (const TopoDS_Shape& piece : split.Modified(cad.faces(f)))
        if (const int i = out.faces.FindIndex(piece); i > 0) out.inputFace[i - 1] = inputFaceOf(cad, f - 1);
    }
    if (std::find(out.inputFace.begin(), out.inputFace.end(), -1) != out.inputFace.end()) return {};
    return out;
  } catch (const Standard_Failure&) {
    return {};
  }
}

std::size_t splitMixedFaces(CadSolid& cad, WallSides& sides) {
  std::size_t split = 0;
  for (int round = 0; round < kMaxSplitRounds; ++round) {  // a skin over a wall, its rim and the other wall: twice
    const std::vector<FaceSplit> splits = findMixedFaces(cad, sides);
    if (splits.empty()) break;
    CadSolid pieces = splitFaces(cad, splits);
    if (pieces.faces.Extent() == 0) break;
    cad = std::move(pieces);
    sides = classifyWallSides(cad);
    split += splits.size();
  }
  return split;
}

}  // namespace hexlayer
