#include "bubbles/bubble_packing.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepLProp_CLProps.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_QuasiUniformAbscissa.hxx>
#include <GeomLProp_CLProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/point_grid.hpp"
#include "core/threads.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/face_sampling.hpp"
#include "geometry/sheet_edges.hpp"
#include "geometry/uv_boundary.hpp"

namespace hexlayer {

double bubbleForce(double w) {
  if (w < 0 || w > 1.5) return 0;
  return 1.25 * w * w * w - 2.375 * w * w + 1.125;
}

namespace {

constexpr double kLeastGapDiameter = 0.8;       // x the face's thickness: the least diameter a narrow air gap asks for
constexpr double kSmallestFaceThickness = 0.1;  // a face's thickness for its bubbles, at least, of the part's
// A seam of a wall is packed at the wall's bubble size where a face beside it is narrower than this x the wall (a ring
// half the wall wide round a hole): wider faces keep their curved edges' nodes (a boss's foot circle on the plate).
constexpr double kNarrowSeamFace = 0.75;

// Largest principal curvature of the face over a few samples.
double maxFaceCurvature(const TopoDS_Shape& face, const std::vector<FaceSample>& samples) {
  BRepAdaptor_Surface surface(TopoDS::Face(face));
  if (surface.GetType() == GeomAbs_Plane) return 0;
  BRepLProp_SLProps props(surface, 2, 1e-9);
  double k = 0;
  const size_t stride = std::max<size_t>(1, samples.size() / 50);
  for (size_t i = 0; i < samples.size(); i += stride) {
    props.SetParameters(samples[i].u, samples[i].v);
    if (props.IsCurvatureDefined()) k = std::max({k, std::abs(props.MaxCurvature()), std::abs(props.MinCurvature())});
  }
  return k;
}

double maxEdgeCurvature(const BRepAdaptor_Curve& curve) {
  if (curve.GetType() == GeomAbs_Line) return 0;
  BRepLProp_CLProps props(curve, 2, 1e-9);
  double k = 0;
  for (int i = 0; i <= 20; ++i) {
    props.SetParameter(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / 20.0);
    if (props.IsTangentDefined()) k = std::max(k, props.Curvature());
  }
  return k;
}

// Largest bubble diameter on a wall facing the solid across a narrow air gap (a hem folded back over its sheet, the
// legs of a narrow U): the gap, so that the Delaunay tets join the wall's nodes to those across the wall, not to those
// across the gap (the sampling must be finer than the gap for the tets to follow the medial surface, §4), but not below
// kLeastGapDiameter x the wall's thickness (the nodes would come nearer to the rim than half the wall).
// [in] gap: FaceSide::airGap; [in] thickness: the face's.
double gapLimit(double gap, double thickness) { return std::max(gap, kLeastGapDiameter * thickness); }

// Largest bubble diameter that still follows a curve or surface of this curvature.
double curvatureLimit(double curvature, const BubbleOptions& o) {
  return curvature > 0 ? o.maxTurnAngle / curvature : std::numeric_limits<double>::infinity();
}

struct Packing {
  std::vector<SurfaceNode> nodes;
  std::vector<double> diameter;
  double largest = 0;  // the largest diameter
  PointGrid grid;
  explicit Packing(double cell) : grid(cell) {}
  void add(const SurfaceNode& n, double d) {
    grid.insert(static_cast<int>(nodes.size()), n.point);
    nodes.push_back(n);
    diameter.push_back(d);
    largest = std::max(largest, d);
  }
  // A search radius, at most `cap`, that finds every node j closer than share x (d + diameter[j]) to
  // a point: the nodes it leaves out are too far for any diameter.
  double reach(double d, double share, double cap) const { return std::min(cap, share * (d + largest) * (1 + 1e-9)); }
  // Whether a node of one side near p passes the test: bubbles on the top and on the bottom wall
  // are packed apart (§4); across the wall (closer than a bubble diameter) they must not push each
  // other away.
  template <class Pred>
  bool anyNearOnSide(const Vec3& p, double radius, Side side, Pred&& pred) const {
    return grid.anyNear(p, radius, [&](int j, const Vec3& q) { return nodes[j].side == side && pred(j, q); });
  }
};

// Side of a vertex or edge: the side of the top/bottom faces around it (Lateral if none).
Side sideAround(const TopTools_ListOfShape& faces, const CadSolid& cad, const WallSides& sides) {
  for (const TopoDS_Shape& f : faces) {
    const Side s = sides.faces[cad.faces.FindIndex(f) - 1].side;
    if (s != Side::Lateral) return s;
  }
  return Side::Lateral;
}

double diameterAround(const TopTools_ListOfShape& faces, const CadSolid& cad, const std::vector<double>& faceDiameter) {
  double d = std::numeric_limits<double>::infinity();
  for (const TopoDS_Shape& f : faces) d = std::min(d, faceDiameter[cad.faces.FindIndex(f) - 1]);
  return d;
}

// The edges (0-based) inside a wall where the CAD system split one surface into faces (sheet_edges oneSurfaceAcross: a
// tube's wall in quarters, a plate's top cut in two): no feature of the wall, packed by the faces' bubbles across
// them as if the faces were one, not along them, nor their vertices. Not where the pipeline split a face (mixed_faces,
// butt_joints: pieces of one input face, the line a step in thickness or a joint), nor along a cut face (a junction
// piece's foot, whose rim the footprint follows), nor from a concave edge's end (a long wall's face split above a low
// wall standing on it: the line on from its top, where the hexes turn). [in] cad, sides.
std::set<int> oneSurfaceSeams(const CadSolid& cad, const WallSides& sides) {
  std::vector<int> candidates;
  for (const SheetJoin& j : sides.sheetJoins)
    if (sides.faces[j.a].side != Side::Lateral && sides.faces[j.a].side == sides.faces[j.b].side &&
        inputFaceOf(cad, j.a) != inputFaceOf(cad, j.b) && !isCutFace(cad, j.a) && !isCutFace(cad, j.b) &&
        oneSurfaceAcross(cad, j))
      candidates.push_back(j.edge);
  if (candidates.empty()) return {};  // most parts: no edge analysis for the concave edges
  auto vertices = [&](int e) {
    TopoDS_Vertex first, last;
    TopExp::Vertices(TopoDS::Edge(cad.edges(e + 1)), first, last);
    return std::array<int, 2>{cad.vertices.FindIndex(first), cad.vertices.FindIndex(last)};  // 0: none
  };
  std::set<int> junctionVertices;  // the vertices of concave edges (where a wall stands on another)
  for (const FacePairEdge& c : concaveEdges(cad))
    for (int v : vertices(c.edge))
      if (v > 0) junctionVertices.insert(v);
  std::set<int> seams;
  for (int e : candidates) {
    const std::array<int, 2> ends = vertices(e);
    if (!junctionVertices.count(ends[0]) && !junctionVertices.count(ends[1])) seams.insert(e);
  }
  return seams;
}

// Whether edge e (0-based) is packed: it bounds a top or bottom face, is no degenerate edge nor one of `seams`.
bool packedEdge(const CadSolid& cad, const WallSides& sides, const TopTools_ListOfShape& faces, int e,
                const std::set<int>& seams) {
  return sideAround(faces, cad, sides) != Side::Lateral && !BRep_Tool::Degenerated(TopoDS::Edge(cad.edges(e + 1))) &&
         !seams.count(e);
}

// A bubble on every vertex of a top or bottom face but those on seams only (oneSurfaceSeams: none of their edges
// packed).
void packVertices(const CadSolid& cad, const WallSides& sides, const std::vector<double>& faceDiameter,
                  const std::set<int>& seams, Packing& pack) {
  TopTools_IndexedDataMapOfShapeListOfShape vertexFaces, vertexEdges, edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_VERTEX, TopAbs_FACE, vertexFaces);
  if (!seams.empty()) {  // the maps for onSeamsOnly
    TopExp::MapShapesAndAncestors(cad.solid, TopAbs_VERTEX, TopAbs_EDGE, vertexEdges);
    TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  }
  auto onSeamsOnly = [&](const TopoDS_Shape& vertex) {
    const TopTools_ListOfShape& edges = vertexEdges.FindFromKey(vertex);
    return std::none_of(edges.cbegin(), edges.cend(), [&](const TopoDS_Shape& e) {
      return packedEdge(cad, sides, edgeFaces.FindFromKey(e), cad.edges.FindIndex(e) - 1, seams);
    });
  };
  for (int v = 1; v <= cad.vertices.Extent(); ++v) {
    if (!seams.empty() && onSeamsOnly(cad.vertices(v))) continue;
    const TopTools_ListOfShape& faces = vertexFaces.FindFromKey(cad.vertices(v));
    SurfaceNode n;
    n.side = sideAround(faces, cad, sides);
    if (n.side == Side::Lateral) continue;
    n.point = toVec(BRep_Tool::Pnt(TopoDS::Vertex(cad.vertices(v))));
    n.vertex = v - 1;
    pack.add(n, diameterAround(faces, cad, faceDiameter));
  }
}

// Whether an edge is a seam inside a wall beside a narrow face: two faces of one side meeting in a smooth edge, one
// narrower than kNarrowSeamFace x the wall (a wall face split into a ring round a hole, a boss's bore bottom over a
// hole through the plate). Its curve is no feature of the wall the nodes must follow: packed as densely as a curved
// rim, it crowds one wall with nodes the other does not have, and the tets between the two make the chordal surface's
// rim round the hole ragged. [in] faces: the edge's; [in] cad, sides.
bool seamInWall(const TopTools_ListOfShape& faces, const CadSolid& cad, const WallSides& sides) {
  if (faces.Extent() != 2) return false;
  const int a = cad.faces.FindIndex(faces.First()) - 1, b = cad.faces.FindIndex(faces.Last()) - 1;
  if (a == b || sides.faces[a].side == Side::Lateral || sides.faces[a].side != sides.faces[b].side) return false;
  if (std::min(sides.faces[a].width, sides.faces[b].width) >= kNarrowSeamFace * sides.thickness) return false;
  return std::any_of(sides.sheetJoins.begin(), sides.sheetJoins.end(), [&](const SheetJoin& j) {
    return j.smooth && ((j.a == a && j.b == b) || (j.a == b && j.b == a));
  });
}

// 1D packing: with one diameter along the edge, the bubble system's equilibrium is equal
// arc-length spacing between the two vertex bubbles, which is placed directly. Not along `seams`.
void packEdges(const CadSolid& cad, const WallSides& sides, const std::vector<double>& faceDiameter,
               const BubbleOptions& o, const std::set<int>& seams, Packing& pack) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= cad.edges.Extent(); ++e) {
    const TopoDS_Edge edge = TopoDS::Edge(cad.edges(e));
    const TopTools_ListOfShape& faces = edgeFaces.FindFromKey(edge);
    const Side side = sideAround(faces, cad, sides);
    if (!packedEdge(cad, sides, faces, e - 1, seams)) continue;
    const BRepAdaptor_Curve curve(edge);
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const double bend = seamInWall(faces, cad, sides) ? 0.0 : maxEdgeCurvature(curve);  // a seam is no feature
    const double diameter = std::min(curvatureLimit(bend, o), diameterAround(faces, cad, faceDiameter));
    const int intervals = std::max(1, static_cast<int>(std::lround(length / diameter)));
    if (intervals < 2) continue;
    const GCPnts_QuasiUniformAbscissa split(curve, intervals + 1);
    for (int i = 2; i <= split.NbPoints() - 1; ++i) {
      SurfaceNode n;
      n.point = toVec(curve.Value(split.Parameter(i)));
      n.side = side;
      n.edge = e - 1;
      pack.add(n, diameter);
    }
  }
}

struct FaceBubble {
  double u, v;
  Vec3 point;
};

// Greedy first fill: candidates (a fine even sampling of the face) become bubbles where no
// bubble is closer than `spacing` x stable distance.
std::vector<FaceBubble> seedFace(const std::vector<FaceSample>& candidates, double d, Side side, const Packing& pack) {
  std::vector<FaceBubble> seeds;
  PointGrid own(d);
  for (const FaceSample& c : candidates) {
    const auto tooClose = [&](int j, const Vec3& q) {
      return (q - c.point).norm() < 0.85 * 0.5 * (d + pack.diameter[j]);
    };
    if (own.anyNear(c.point, 0.85 * d, [](int, const Vec3&) { return true; }) ||  // most candidates: the face's own
        pack.anyNearOnSide(c.point, pack.reach(d, 0.85 * 0.5, 2 * d), side, tooClose))
      continue;
    own.insert(static_cast<int>(seeds.size()), c.point);
    seeds.push_back({c.u, c.v, c.point});
  }
  return seeds;
}

// One thread's OpenCASCADE tools on a face (neither is safe to share between threads: a B-spline
// surface's adaptor caches its last span), and the face's quick test, shared.
struct FaceTools {
  FaceTools(const TopoDS_Face& face, const UvBoundary* quick) : surface(face), inside(face, 1e-9), quick(quick) {
    BRepTools::UVBounds(face, bounds[0], bounds[1], bounds[2], bounds[3]);
  }
  BRepAdaptor_Surface surface;
  BRepTopAdaptor_FClass2d inside;
  const UvBoundary* quick;
  double bounds[4] = {0, 0, 0, 0};  // the face's parameter bounds: u1, u2, v1, v2
  // Strictly inside the face: the quick test where it decides (beyond a margin of the edges, where FClass2d's answer,
  // exact outside its polygons' sag, is the same) within the face's parameter bounds (FClass2d moves a point beyond
  // them by a period on a periodic surface), else FClass2d.
  bool within(double u, double v) {
    const bool inBounds = u > bounds[0] && u < bounds[1] && v > bounds[2] && v < bounds[3];
    const UvBoundary::Side side = inBounds ? quick->side(u, v) : UvBoundary::Side::Undecided;
    if (side != UvBoundary::Side::Undecided) return side == UvBoundary::Side::Inside;
    return inside.Perform(gp_Pnt2d(u, v)) == TopAbs_IN;
  }
};

// Bubble i after one relaxation step: moved along the net bubble force of the others where they
// were, then back onto the face through the surface's first derivatives; none if pushed off the face.
std::optional<FaceBubble> relaxedBubble(std::size_t i, double d, const Packing& pack, const PointGrid& own,
                                        const std::vector<FaceBubble>& bubbles, FaceTools& tools) {
  const Vec3 x = bubbles[i].point;
  Vec3 force = Vec3::Zero();
  auto push = [&](const Vec3& q, double stable) {
    const Vec3 r = x - q;
    const double len = r.norm();
    if (len > 1e-12) force += bubbleForce(len / stable) * r / len;
  };
  // Nodes beyond 1.5 x their stable distance add exactly zero (the sum starts at +0 and is never
  // -0, so leaving them out changes no bit).
  pack.grid.forEachNear(x, pack.reach(d, 1.5 * 0.5, 1.5 * d * 2),
                        [&](int j, const Vec3& q) { push(q, 0.5 * (d + pack.diameter[j])); });
  own.forEachNear(x, 1.5 * d, [&](int j, const Vec3& q) {
    if (j != static_cast<int>(i)) push(q, d);
  });
  Vec3 step = 0.15 * d * force;
  if (step.norm() > 0.25 * d) step *= 0.25 * d / step.norm();
  gp_Pnt p;
  gp_Vec du, dv;
  tools.surface.D1(bubbles[i].u, bubbles[i].v, p, du, dv);
  Eigen::Matrix<double, 3, 2> J;
  J << du.X(), dv.X(), du.Y(), dv.Y(), du.Z(), dv.Z();
  const Eigen::Vector2d duv = (J.transpose() * J).ldlt().solve(J.transpose() * step);
  FaceBubble b{bubbles[i].u + duv.x(), bubbles[i].v + duv.y(), Vec3::Zero()};
  if (!duv.allFinite() || !tools.within(b.u, b.v)) return std::nullopt;
  b.point = toVec(tools.surface.Value(b.u, b.v));
  return b;
}

// One relaxation step of every face bubble at once (each from where the others were: in parallel,
// one FaceTools per thread); bubbles pushed out of the face are dropped.
void relaxFace(double d, const Packing& pack, std::vector<FaceBubble>& bubbles,
               std::vector<std::unique_ptr<FaceTools>>& tools) {
  PointGrid own(d);
  for (size_t i = 0; i < bubbles.size(); ++i) own.insert(static_cast<int>(i), bubbles[i].point);
  std::vector<std::optional<FaceBubble>> next(bubbles.size());
  ParallelErrors errors;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(bubbles.size()); ++i)
    errors.run([&] { next[i] = relaxedBubble(i, d, pack, own, bubbles, *tools[threadIndex()]); });
  errors.rethrow();
  std::vector<FaceBubble> moved;
  for (const auto& b : next)
    if (b) moved.push_back(*b);
  bubbles.swap(moved);
}

void addFaceNode(const Vec3& point, int face, Side side, double d, Packing& pack) {
  SurfaceNode n;
  n.point = point;
  n.side = side;
  n.face = face;
  pack.add(n, d);
}

void packFaces(const CadSolid& cad, const WallSides& sides, const std::vector<double>& faceDiameter,
               const BubbleOptions& o, Packing& pack) {
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    const Side side = sides.faces[f].side;
    if (side == Side::Lateral) continue;
    const TopoDS_Face face = TopoDS::Face(cad.faces(f + 1));
    const double d = faceDiameter[f];
    const std::vector<FaceSample> candidates = sampleFace(face, 0.2 * d);
    std::vector<FaceBubble> bubbles = seedFace(candidates, d, side, pack);
    const std::unique_ptr<UvBoundary> quick = faceUvBoundary(face, cad.diagonal);
    std::vector<std::unique_ptr<FaceTools>> tools;
    for (int t = 0; t < threadCount(); ++t) tools.push_back(std::make_unique<FaceTools>(face, quick.get()));
    for (int step = 0; step < o.relaxationSteps; ++step) relaxFace(d, pack, bubbles, tools);
    // Population control: a bubble that ended too close to another is removed ...
    PointGrid own(d);
    for (size_t i = 0; i < bubbles.size(); ++i) {
      const Vec3& p = bubbles[i].point;
      const auto tooClose = [&](int j, const Vec3& q) { return (q - p).norm() < 0.5 * 0.5 * (d + pack.diameter[j]); };
      const bool crowded = pack.grid.anyNear(p, pack.reach(d, 0.5 * 0.5, d), tooClose) ||
                           own.anyNear(p, 0.5 * d, [](int, const Vec3&) { return true; });
      if (crowded) continue;
      own.insert(static_cast<int>(i), bubbles[i].point);
      addFaceNode(bubbles[i].point, f, side, d, pack);
    }
    // ... and a gap the relaxation opened (bubbles pushed off the face) gets new bubbles: a hole in
    // the nodes would let the Delaunay tets bridge it through the air instead of spanning the wall.
    for (const FaceBubble& b : seedFace(candidates, d, side, pack)) addFaceNode(b.point, f, side, d, pack);
  }
}

}  // namespace

std::vector<SurfaceNode> packBubbles(const CadSolid& cad, const WallSides& sides, const BubbleOptions& o) {
  if (!(o.diameterOverThickness > 0)) throw usageError("bubble diameter must be positive");
  std::vector<double> faceDiameter(cad.faces.Extent(), std::numeric_limits<double>::infinity());
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    if (sides.faces[f].side == Side::Lateral) continue;
    const TopoDS_Shape& face = cad.faces(f + 1);
    const double curvature = maxFaceCurvature(face, sampleFace(face, 0.1 * cad.diagonal));
    // Bubble diameter above the wall thickness (§4), small enough to follow the face's curvature, and not
    // below kSmallestFaceThickness x the part's wall: a face whose rays cross a sliver of the solid (the 0.002 mm
    // tunnels of a zero-radius bend) would ask for millions of bubbles.
    const double thickness = std::max(sides.faces[f].thickness, kSmallestFaceThickness * sides.thickness);
    faceDiameter[f] = std::min(o.diameterOverThickness * thickness, curvatureLimit(curvature, o));
    if (const double gap = sides.faces[f].airGap; gap > 0)
      faceDiameter[f] = std::min(faceDiameter[f], gapLimit(gap, thickness));
  }
  Packing pack(o.diameterOverThickness * sides.thickness);
  const std::set<int> seams = oneSurfaceSeams(cad, sides);
  packVertices(cad, sides, faceDiameter, seams, pack);
  packEdges(cad, sides, faceDiameter, o, seams, pack);
  packFaces(cad, sides, faceDiameter, o, pack);
  return pack.nodes;
}

}  // namespace hexlayer
