#include "geometry/mixed_faces.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepFeat_SplitShape.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <ElCLib.hxx>
#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
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
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "core/threads.hpp"
#include "core/triangle_tree.hpp"
#include "geometry/face_sampling.hpp"

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
constexpr double kFlushFar = 1.5;     // a flush rim's sample: farther than this many walls from every face across
constexpr double kFlushRay = 4;       // a flush rim's sample: its inward ray runs along a wall farther than this
constexpr double kFlushShare = 0.5;   // a flush rim piece: at least this share of its area so far
// A wall face thinner over a part of it (a box's wall whose outer half is cut away over its top: a lid's lip) is split
// where the thickness steps: each piece then gets bubbles for its own thickness (bubble_packing.cpp).
constexpr double kThinPart = 0.1;       // the thin piece: at least this share of the face's crossing sample area
constexpr double kThinStep = 0.75;      // the thin piece's thickest (90th percentile) below this x the other's thinnest
constexpr double kThinMisplaced = 0.1;  // at most this share of the thin piece's area on the wrong side of the line
constexpr double kAcrossShare = 0.02;   // of a wall face's crossing ray area: the least a face across it takes

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

// The pieces of a face's samples below the band, in it (the rim) and above it. [in] marks, band.
std::array<Piece, 3> bandPieces(const std::vector<RayMark>& marks, const Band& band) {
  std::array<Piece, 3> p;  // below, rim, above
  for (const RayMark& m : marks) {
    Piece& in = p[band.holds(m) ? 1 : band.coord(m) < band.from ? 0 : 2];
    in.area += m.area, in.crossing += m.crossing ? m.area : 0, in.normal += m.area * m.normal;
  }
  return p;
}

// The band [from, to) of the face's parameter as its rim piece, the rest (below `from`, at or above `to`; one of
// them may be empty) as wall pieces, if they part the samples so. The rim must turn away from each wall next to
// it: a wall's normal is taken over a band beside the line as wide (in the parameter) as the rim piece, so a
// curved wall's band along a flat rim is not taken for a rim.
std::optional<Candidate> tryBand(const std::vector<RayMark>& marks, bool alongV, double from, double to,
                                 double thickness, int face) {
  const Band band{alongV, from, to};
  const auto [below, rim, above] = bandPieces(marks, band);
  Piece besideBelow, besideAbove;
  double first = to, last = from;  // the rim samples' extent in the parameter
  for (const RayMark& m : marks)
    if (band.holds(m)) first = std::min(first, band.coord(m)), last = std::max(last, band.coord(m));
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

// The faces across a wall face's wall (those its crossing rays hit, each for at least kAcrossShare of their area: a
// ray or two from a corner that hit the wall beside it are no face across) as triangles (face_sampling.hpp).
TriangleTree facesAcross(const CadSolid& cad, const FaceSide& fs) {
  std::map<int, double> hit;  // face -> crossing ray area
  double crossing = 0;
  for (const RayMark& m : fs.marks)
    if (m.crossing) hit[m.hitFace] += m.area, crossing += m.area;
  std::vector<Triangle> triangles;
  for (const auto& [g, area] : hit) {
    if (area < kAcrossShare * crossing) continue;
    for (const Triangle2d& t : faceTriangles(TopoDS::Face(cad.faces(g + 1)))) triangles.push_back(spaceTriangle(t));
  }
  return TriangleTree(std::move(triangles));
}

// A flat wall face's samples that lie on the end of another wall flush with it (a box's lower end wall, whose
// outer face runs on up the ends of the higher side walls): their rays run along that other wall and cross none,
// and they are farther than kFlushFar walls from the faces across this face's wall (facesAcross), where its own
// samples, and those of a corner it makes with another wall, are nearer. [in] cad, fs: a face and its samples; f:
// its index; [in] thickness. Per sample: whether it lies so.
std::vector<char> flushSamples(const CadSolid& cad, const FaceSide& fs, int f, double thickness) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(cad.faces(f + 1)));
  const TriangleTree across = facesAcross(cad, fs);
  std::vector<char> flush(fs.marks.size(), 0);
  for (std::size_t k = 0; k < fs.marks.size(); ++k) {
    const RayMark& m = fs.marks[k];
    if (m.crossing || (m.hitFace >= 0 && m.length <= kFlushRay * thickness)) continue;
    const gp_Pnt p = surface->Value(m.u, m.v);
    flush[k] = !across.anyWithin(Vec3(p.X(), p.Y(), p.Z()), kFlushFar * thickness);
  }
  return flush;
}

// The face's parameter lines through its vertices: where a flush rim leaves the wall, the face's outline turns.
// [in] uvs: its vertices' parameters (vertexParameters); [in] u: the u lines, else the v lines.
std::vector<double> parameterLines(const std::vector<gp_Pnt2d>& uvs, bool u) {
  std::vector<double> out;
  for (const gp_Pnt2d& uv : uvs) out.push_back(u ? uv.X() : uv.Y());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The band of a flat wall face beyond one of its vertices' parameter lines that holds a flush rim: mostly
// (kFlushShare) flush samples (flushSamples) and no more crossing ones than a rim (kRimPiece), the rest of the face a
// wall (kWallPiece); of those the line that misplaces the least sample area (crossing in the rim, not in the wall).
// [in] cad, fs, f, thickness. Returns the split, or nothing.
std::optional<FaceSplit> flushRimSplit(const CadSolid& cad, const FaceSide& fs, int f, double thickness) {
  const TopoDS_Face face = TopoDS::Face(cad.faces(f + 1));
  std::vector<char> flush;  // measured when a band might hold a rim
  std::optional<Candidate> best;
  const std::vector<gp_Pnt2d> uvs = vertexParameters(face);
  for (const bool alongV : {true, false}) {
    const std::vector<double> lines = parameterLines(uvs, alongV);
    if (lines.size() < 3) continue;
    const double span = lines.back() - lines.front();
    for (std::size_t i = 1; i + 1 < lines.size(); ++i)
      for (const Band band :
           {Band{alongV, lines[i], lines.back() + span}, Band{alongV, lines.front() - span, lines[i]}}) {
        const auto [below, rim, above] = bandPieces(fs.marks, band);
        const Piece& wall = below.area > 0 ? below : above;
        if (rim.area < kMinRimArea * thickness * thickness || rim.share() >= kRimPiece || wall.share() < kRimPiece)
          continue;
        if (flush.empty()) flush = flushSamples(cad, fs, f, thickness);
        double flushArea = 0;
        for (std::size_t k = 0; k < fs.marks.size(); ++k)
          if (flush[k] && band.holds(fs.marks[k])) flushArea += fs.marks[k].area;
        if (flushArea < kFlushShare * rim.area) continue;
        const double at = band.from == lines[i] ? band.from : band.to;
        keepBetter(best, Candidate{rim.crossing + wall.area - wall.crossing, {{f, alongV, at}}, band});
      }
  }
  if (!best) return std::nullopt;
  return best->splits.front();
}

// The stretches [from, to] of a face's parameter line (its parameter along the line) to split the face along: the
// whole span over the face's bounds, or, where the line runs along a boundary edge somewhere (a flush rim's line
// continuing the wall's edge), only the stretches between its crossings with the boundary whose middle is inside.
// [in] face, line; [in] from, to: the line's span over the face's bounds.
std::vector<std::pair<double, double>> insideStretches(const TopoDS_Face& face, const Handle(Geom2d_Line) & line,
                                                       double from, double to) {
  std::vector<double> at{from, to};
  bool alongBoundary = false;
  const double tolerance = BRep_Tool::Tolerance(face);
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    double first, last;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, first, last);
    if (pcurve.IsNull()) continue;
    const Geom2dAPI_InterCurveCurve meet(line, new Geom2d_TrimmedCurve(pcurve, first, last), tolerance);
    for (int i = 1; i <= meet.NbPoints(); ++i) at.push_back(ElCLib::Parameter(line->Lin2d(), meet.Point(i)));
    for (int i = 1; i <= meet.NbSegments(); ++i) {
      Handle(Geom2d_Curve) a, b;
      meet.Segment(i, a, b);
      at.push_back(ElCLib::Parameter(line->Lin2d(), a->Value(a->FirstParameter())));
      at.push_back(ElCLib::Parameter(line->Lin2d(), a->Value(a->LastParameter())));
      alongBoundary = true;
    }
  }
  if (!alongBoundary) return {{from, to}};
  std::sort(at.begin(), at.end());
  BRepTopAdaptor_FClass2d inside(face, tolerance);
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < at.size(); ++i)
    if (at[i] >= from && at[i + 1] <= to && at[i + 1] - at[i] > 10 * tolerance &&
        inside.Perform(line->Value(0.5 * (at[i] + at[i + 1]))) == TopAbs_IN)
      out.emplace_back(at[i], at[i + 1]);
  return out;
}

// The face's parameter line of a split, and the span of its parameter over the face's bounds.
struct SplitLine {
  Handle(Geom2d_Line) line;
  double from, to;
};
SplitLine splitLine(const TopoDS_Face& face, const FaceSplit& s) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  if (s.alongV) return {new Geom2d_Line(gp_Pnt2d(s.at, 0), gp_Dir2d(0, 1)), v0, v1};
  return {new Geom2d_Line(gp_Pnt2d(0, s.at), gp_Dir2d(1, 0)), u0, u1};
}

// The faces split along the lines (their stretches to split along, insideStretches): false if OpenCASCADE could not
// make an edge or split them. [in] cad, splits; [out] split: the splitter, its Shape the solid with the faces split.
bool splitAlongLines(const CadSolid& cad, const std::vector<FaceSplit>& splits, BRepFeat_SplitShape& split) {
  split.Init(cad.solid);
  for (const FaceSplit& s : splits) {
    const TopoDS_Face face = TopoDS::Face(cad.faces(s.face + 1));
    const auto [line, from, to] = splitLine(face, s);
    for (const auto& [a, b] : insideStretches(face, line, from, to)) {
      BRepBuilderAPI_MakeEdge edge(line, BRep_Tool::Surface(face), a, b);
      if (!edge.IsDone()) return false;
      TopoDS_Edge e = edge.Edge();
      BRepLib::BuildCurves3d(e);
      split.Add(e, face);
    }
  }
  split.Build();
  return split.IsDone();
}

// A flush rim's split line ends on the bend rounds beside it (the round of the corner the wall it leaves makes
// with another, running on up the rim): each is split there too, along its parameter line across it (the narrower
// way), so that the round's piece beside the rim is a rim and the rest stays a bend round. [in] cad, sides; [in]
// split: a flush rim's. Returns the rounds' splits.
std::vector<FaceSplit> splitsAcrossRounds(const CadSolid& cad, const WallSides& sides, const FaceSplit& split) {
  const TopoDS_Face face = TopoDS::Face(cad.faces(split.face + 1));
  const auto [line, from, to] = splitLine(face, split);
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  std::vector<FaceSplit> out;
  for (const auto& [a, b] : insideStretches(face, line, from, to))
    for (const double t : {a, b}) {
      const gp_Pnt end = surface->Value(line->Value(t).X(), line->Value(t).Y());
      const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(end).Vertex();
      for (int g : sides.bendRounds) {
        const TopoDS_Face round = TopoDS::Face(cad.faces(g + 1));
        BRepExtrema_DistShapeShape distance(vertex, round);
        if (!distance.IsDone() || distance.Value() > 10 * BRep_Tool::Tolerance(round)) continue;
        const Handle(Geom_Surface) roundSurface = BRep_Tool::Surface(round);
        GeomAPI_ProjectPointOnSurf on(end, roundSurface);
        if (on.NbPoints() == 0) continue;
        double u, v, u0, u1, v0, v1;
        on.LowerDistanceParameters(u, v);
        BRepTools::UVBounds(round, u0, u1, v0, v1);
        gp_Pnt p;
        gp_Vec du, dv;
        roundSurface->D1(u, v, p, du, dv);
        const bool acrossU = du.Magnitude() * (u1 - u0) < dv.Magnitude() * (v1 - v0);  // u runs across the round
        out.push_back(acrossU ? FaceSplit{g, false, v, true} : FaceSplit{g, true, u, true});
      }
    }
  return out;
}

// A crossing sample's parameter along a split line's normal (alongV: u) and its ray's length and area.
struct Thickness {
  double at, length, area;
};

// The piece of the samples on one side of `at` (below: coordinate < at): its (length, area) pairs.
std::vector<std::pair<double, double>> sideOf(const std::vector<Thickness>& samples, double at, bool below) {
  std::vector<std::pair<double, double>> out;
  for (const Thickness& t : samples)
    if ((t.at < at) == below) out.emplace_back(t.length, t.area);
  return out;
}

// If the samples below (or above) `at` are a thin piece and the rest a thick one (the thin piece at least kThinPart
// of the area and at most 1 - kThinPart, its 90th percentile under kThinStep x the thick piece's 10th: a step, not a
// taper), the sample area on the wrong side (thicker than halfway between the two pieces' medians in the thin piece,
// thinner in the thick one), if at most kThinMisplaced of the thin piece's area.
std::optional<double> thinPieceBy(const std::vector<Thickness>& samples, double total, double at, bool below) {
  const auto thin = sideOf(samples, at, below), thick = sideOf(samples, at, !below);
  double thinArea = 0;
  for (const auto& [length, area] : thin) thinArea += area;
  if (thinArea < kThinPart * total || thinArea > (1 - kThinPart) * total) return std::nullopt;
  if (!(weightedQuantile(thin, 0.9) < kThinStep * weightedQuantile(thick, 0.1))) return std::nullopt;
  const double halfway = 0.5 * (weightedQuantile(thin, 0.5) + weightedQuantile(thick, 0.5));
  double misplaced = 0;
  for (const auto& [length, area] : thin) misplaced += length > halfway ? area : 0;
  for (const auto& [length, area] : thick) misplaced += length < halfway ? area : 0;
  if (misplaced > kThinMisplaced * thinArea) return std::nullopt;
  return misplaced;
}

// A wall face whose samples part along a parameter line into a thin piece and a thick one (thinPieceBy): of the
// kLines lines per direction, one that misplaces the least area, the middle one of those that misplace as little on
// the same side of the same direction (the samples' rows leave a gap at the step). [in] cad, fs, f.
std::optional<FaceSplit> thinPartSplit(const CadSolid& cad, const FaceSide& fs, int f) {
  const TopoDS_Face face = TopoDS::Face(cad.faces(f + 1));
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  struct Line {
    double misplaced;
    bool alongV, below;
    double at;
  };
  std::vector<Line> lines;
  for (const bool alongV : {true, false}) {
    std::vector<Thickness> samples;
    double total = 0;
    for (const RayMark& m : fs.marks)
      if (m.crossing && m.length > 0) samples.push_back({alongV ? m.u : m.v, m.length, m.area}), total += m.area;
    const double lo = alongV ? u0 : v0, hi = alongV ? u1 : v1;
    for (const bool below : {true, false})
      for (int i = 1; i < kLines; ++i) {
        const double at = lo + (hi - lo) * i / kLines;
        if (const std::optional<double> misplaced = thinPieceBy(samples, total, at, below))
          lines.push_back({*misplaced, alongV, below, at});
      }
  }
  if (lines.empty()) return std::nullopt;
  const Line least = *std::min_element(lines.begin(), lines.end(),
                                       [](const Line& a, const Line& b) { return a.misplaced < b.misplaced; });
  std::vector<double> as;
  for (const Line& l : lines)
    if (l.misplaced == least.misplaced && l.alongV == least.alongV && l.below == least.below) as.push_back(l.at);
  return FaceSplit{f, least.alongV, as[as.size() / 2]};
}

// Whether the face's crossing samples are far enough apart in thickness to hold a thin and a thick piece: with each
// piece at least kThinPart of the face and 90 % of it beyond the step, over 5 % of the face lies below the thin
// piece's 90th percentile and over 5 % above the thick one's 10th. A wall of one thickness (most) is let go here.
bool thicknessSpread(const FaceSide& fs) {
  std::vector<std::pair<double, double>> lengths;
  for (const RayMark& m : fs.marks)
    if (m.crossing && m.length > 0) lengths.emplace_back(m.length, m.area);
  return weightedQuantile(lengths, 0.05) < kThinStep * weightedQuantile(lengths, 0.95);
}

}  // namespace

std::vector<FaceSplit> findThinParts(const CadSolid& cad, const WallSides& sides) {
  return joinedInOrder(static_cast<int>(sides.faces.size()), [&](int f) {
    const FaceSide& fs = sides.faces[f];
    std::vector<FaceSplit> splits;
    if (fs.side == Side::Lateral || fs.marks.size() < kMinMarks || !thicknessSpread(fs)) return splits;
    if (std::optional<FaceSplit> s = thinPartSplit(cad, fs, f)) splits.push_back(*s);
    return splits;
  });
}

std::vector<FaceSplit> findMixedFaces(const CadSolid& cad, const WallSides& sides) {
  return joinedInOrder(static_cast<int>(sides.faces.size()), [&](int f) {
    const FaceSide& fs = sides.faces[f];
    if (fs.marks.size() < kMinMarks || fs.wallShare < kRimPiece) return std::vector<FaceSplit>{};  // a rim face
    if (std::optional<std::vector<FaceSplit>> s = bestSplit(cad, fs, sides.thickness, f)) return *s;
    if (fs.side == Side::Lateral || !isFlat(cad.faces(f + 1))) return std::vector<FaceSplit>{};
    std::vector<FaceSplit> splits;
    if (std::optional<FaceSplit> s = flushRimSplit(cad, fs, f, sides.thickness)) {
      splits.push_back(*s);
      const std::vector<FaceSplit> rounds = splitsAcrossRounds(cad, sides, *s);
      splits.insert(splits.end(), rounds.begin(), rounds.end());
    }
    return splits;
  });
}

namespace {

// One pass of splitFaces: the solid with the faces split (nothing if OpenCASCADE could not), each piece named after
// its input face (namedPieces). [in] cad, splits.
CadSolid splitOnce(const CadSolid& cad, const std::vector<FaceSplit>& splits) {
  try {
    BRepFeat_SplitShape split;
    return splitAlongLines(cad, splits, split) ? namedPieces(cad, split) : CadSolid{};
  } catch (const Standard_Failure&) {
    return {};
  }
}

// The face of `to` that face f of `from` became when other faces were split (the same input face, on the same
// surface), or -1. [in] from, to, f.
int sameFace(const CadSolid& from, const CadSolid& to, int f) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(from.faces(f + 1)));
  for (int g = 0; g < to.faces.Extent(); ++g)
    if (inputFaceOf(to, g) == inputFaceOf(from, f) && BRep_Tool::Surface(TopoDS::Face(to.faces(g + 1))) == surface)
      return g;
  return -1;
}

// How many faces of `in` lie on the surface of face f of `from` and come from its input face: its pieces.
int piecesOf(const CadSolid& from, int f, const CadSolid& in) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(from.faces(f + 1)));
  int pieces = 0;
  for (int g = 0; g < in.faces.Extent(); ++g)
    pieces +=
        inputFaceOf(in, g) == inputFaceOf(from, f) && BRep_Tool::Surface(TopoDS::Face(in.faces(g + 1))) == surface;
  return pieces;
}

// The splits of `from` whose face `to` still has whole (no more pieces on its surface than `from` had: OpenCASCADE
// leaves one of two faces whole where their lines end at one point of the edge they share, as round a box's inside
// corner), each with that face's index in `to`; only faces `to` has one piece of (found by sameFace).
std::vector<FaceSplit> leftWhole(const CadSolid& from, const CadSolid& to, const std::vector<FaceSplit>& splits) {
  std::vector<FaceSplit> whole;
  for (FaceSplit s : splits)
    if (piecesOf(from, s.face, to) == 1 && piecesOf(from, s.face, from) == 1)
      s.face = sameFace(from, to, s.face), whole.push_back(s);
  return whole;
}

}  // namespace

CadSolid namedPieces(const CadSolid& cad, BRepBuilderAPI_MakeShape& split) {
  TopExp_Explorer solids(split.Shape(), TopAbs_SOLID);
  if (!solids.More()) return {};
  CadSolid out = prepareSolid(TopoDS::Solid(solids.Current()), 1);
  out.unit = cad.unit, out.cutInput = cad.cutInput;
  out.inputFace.assign(out.faces.Extent(), -1);
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    const int kept = out.faces.FindIndex(cad.faces(f));
    if (kept > 0) out.inputFace[kept - 1] = inputFaceOf(cad, f - 1);
    for (const TopoDS_Shape& piece : split.Modified(cad.faces(f)))
      if (const int i = out.faces.FindIndex(piece); i > 0) out.inputFace[i - 1] = inputFaceOf(cad, f - 1);
  }
  if (std::find(out.inputFace.begin(), out.inputFace.end(), -1) != out.inputFace.end()) return {};
  return out;
}

CadSolid splitFaces(const CadSolid& cad, const std::vector<FaceSplit>& splits) {
  std::vector<FaceSplit> first, after;
  for (const FaceSplit& s : splits) (s.afterOthers ? after : first).push_back(s);
  CadSolid out = splitOnce(cad, first);
  if (after.empty() || out.faces.Extent() == 0) return out;
  for (FaceSplit& s : after) s.face = sameFace(cad, out, s.face);
  after.erase(std::remove_if(after.begin(), after.end(), [](const FaceSplit& s) { return s.face < 0; }), after.end());
  CadSolid more = splitOnce(out, after);
  return more.faces.Extent() > 0 ? more : out;
}

CadSolid splitThinParts(const CadSolid& cad, const std::vector<FaceSplit>& splits) {
  CadSolid out = splitOnce(cad, splits);
  for (std::size_t round = 0; round < splits.size() && out.faces.Extent() > 0; ++round) {
    const std::vector<FaceSplit> whole = leftWhole(cad, out, splits);
    if (whole.empty()) break;
    std::vector<FaceSplit> one;  // the first face left whole, with all of its lines
    for (const FaceSplit& s : whole)
      if (s.face == whole[0].face) one.push_back(s);
    CadSolid more = splitOnce(out, one);
    if (more.faces.Extent() == 0) break;
    out = std::move(more);
  }
  return out;
}

std::size_t splitMixedFaces(CadSolid& cad, WallSides& sides) {
  std::size_t split = 0;
  for (int round = 0; round < kMaxSplitRounds; ++round) {  // a skin over a wall, its rim and the other wall: twice
    const std::vector<FaceSplit> splits = findMixedFaces(cad, sides);
    if (splits.empty()) break;
    CadSolid pieces = splitFaces(cad, splits);
    if (pieces.faces.Extent() == 0) break;
    sides = classifyWallSidesAfterSplit(pieces, cad, sides);
    cad = std::move(pieces);
    split += splits.size();
  }
  if (const std::vector<FaceSplit> thin = findThinParts(cad, sides); !thin.empty()) {
    CadSolid pieces = splitThinParts(cad, thin);
    if (pieces.faces.Extent() > 0)
      sides = classifyWallSidesAfterSplit(pieces, cad, sides), cad = std::move(pieces), split += thin.size();
  }
  return split;
}

}  // namespace hexlayer
