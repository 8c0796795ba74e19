#include "geometry/cad_faces.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass_FClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <ElSLib.hxx>
#include <Extrema_GenLocateExtPS.hxx>
#include <OSD_ThreadPool.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Torus.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/threads.hpp"
#include "geometry/bnd_box.hpp"

namespace hexlayer {
namespace {

const double kEps = Precision::Confusion();  // BRepExtrema_DistShapeShape's default precision

gp_Pnt point(const Vec3& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

// The box BRepBndLib gives a vertex made at p (its tolerance Precision::Confusion()).
Bnd_Box vertexBox(const gp_Pnt& p) {
  Bnd_Box box;
  box.Add(p);
  box.Enlarge(Precision::Confusion());
  return box;
}

// For every face, the faces that share a vertex with it (itself excluded), ascending.
std::vector<std::vector<int>> vertexNeighbours(const CadSolid& cad) {
  TopTools_IndexedDataMapOfShapeListOfShape facesOfVertex;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_VERTEX, TopAbs_FACE, facesOfVertex);
  std::vector<std::vector<int>> neighbours(cad.faces.Extent());
  for (int v = 1; v <= facesOfVertex.Extent(); ++v) {
    std::vector<int> around;
    for (const TopoDS_Shape& f : facesOfVertex(v)) around.push_back(cad.faces.FindIndex(f) - 1);
    for (int a : around)
      for (int b : around)
        if (a != b && a >= 0 && b >= 0) neighbours[a].push_back(b);
  }
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return neighbours;
}

// The box BRepExtrema_DistShapeShape gives a sub-shape (BRepBndLib::Add; a vertex: its point and tolerance).
Bnd_Box extremaBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box;
}

// The parameters in [lo, hi] at which a cos t + b sin t is extreme (atan2(b, a) + k pi), and lo and hi: where a
// function of t with no other stationary points in the range has its least and greatest value.
std::vector<double> extremeParameters(double a, double b, double lo, double hi) {
  std::vector<double> t{lo, hi};
  const double first = std::atan2(b, a);
  for (double k = std::ceil((lo - first) / M_PI); first + k * M_PI <= hi; ++k) t.push_back(first + k * M_PI);
  return t;
}

// The box of a ring torus (major radius above the minor) over the face's parameter rectangle, from its extreme points:
// along an axis e, x(u, v) = e.C + (R + r cos v) g(u) + r (e.Z) sin v with g(u) = (e.X) cos u + (e.Y) sin u, so
// (R + r cos v > 0) it is extreme in u where g is or at the ends, and at each such u in v where g(u) cos v + (e.Z)
// sin v is or at the ends (extremeParameters). Exact where BndLib's optimization of a torus takes 20 ms; enlarged by
// Precision::Confusion(), as BRepBndLib::AddOptimal's. [in] face: on a torus. Returns its box; void if the torus is
// not a ring.
Bnd_Box ringTorusBox(const TopoDS_Face& face, const gp_Torus& torus) {
  Bnd_Box box;
  if (!(torus.MajorRadius() > torus.MinorRadius())) return box;
  double u1, u2, v1, v2;
  BRepTools::UVBounds(face, u1, u2, v1, v2);
  const gp_Ax3& frame = torus.Position();
  for (const gp_Dir& e : {gp::DX(), gp::DY(), gp::DZ()})
    for (double u : extremeParameters(frame.XDirection().Dot(e), frame.YDirection().Dot(e), u1, u2)) {
      const double g = std::cos(u) * frame.XDirection().Dot(e) + std::sin(u) * frame.YDirection().Dot(e);
      for (double v : extremeParameters(g, frame.Direction().Dot(e), v1, v2))
        box.Add(ElSLib::TorusValue(u, v, frame, torus.MajorRadius(), torus.MinorRadius()));
    }
  box.Enlarge(Precision::Confusion());
  return box;
}

// The face's box from its exact geometry (not its triangulation): a ring torus's from its extreme points
// (ringTorusBox), any other's BRepBndLib::AddOptimal's. [in] face.
Bnd_Box exactFaceBox(const TopoDS_Face& face) {
  const BRepAdaptor_Surface surface(face);
  if (surface.GetType() == GeomAbs_Torus)
    if (Bnd_Box box = ringTorusBox(face, surface.Torus()); !box.IsVoid()) return box;
  Bnd_Box box;
  BRepBndLib::AddOptimal(face, box, false, false);
  return box;
}

// Distance from p to the trimmed face as BRepExtrema_DistShapeShape gives it, built for this query.
double exactDistance(const TopoDS_Face& face, const gp_Pnt& p) {
  BRepExtrema_DistShapeShape nearest(BRepBuilderAPI_MakeVertex(p).Vertex(), face);
  if (!nearest.IsDone() || nearest.NbSolution() == 0) return std::numeric_limits<double>::infinity();
  return nearest.Value();
}

// A freeform face's seeds (CadFaces::Face): its triangulation's nodes and their (u, v), in a grid (BoxGrid, each node
// a point box) of cells about as wide as the triangles. [in,out] f: its face and exact box read, seeds set.
void addSeeds(CadFaces::Face& f) {
  if (BRepAdaptor_Surface(f.face, false).GetType() <= GeomAbs_Torus || f.exactBox.IsVoid()) return;
  TopLoc_Location place;
  const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(f.face, place);
  if (mesh.IsNull() || !mesh->HasUVNodes() || mesh->NbNodes() == 0) return;
  f.seedGrid = std::make_unique<BoxGrid>(std::sqrt(f.exactBox.SquareExtent() / mesh->NbNodes()));
  for (int i = 1; i <= mesh->NbNodes(); ++i) {
    const gp_Pnt q = mesh->Node(i).Transformed(place.Transformation());
    f.seeds.push_back({Vec3(q.X(), q.Y(), q.Z()), mesh->UVNode(i)});
    f.seedGrid->insert(i - 1, f.seeds.back().point, f.seeds.back().point);
  }
}

}  // namespace

// A face with its boxes, vertices, edges (indices into the solid's), parameter bounds and UvBoundary.
CadFaces::Face CadFaces::makeFace(const CadSolid& cad, int index, const Bnd_Box* known) {
  Face f;
  f.face = TopoDS::Face(cad.faces(index + 1));
  f.tolerance = BRep_Tool::Tolerance(f.face);
  f.exactBox = known ? *known : exactFaceBox(f.face);
  f.box = f.exactBox;
  f.box.Enlarge(f.tolerance);
  f.extremaBox = extremaBox(f.face);
  TopTools_IndexedMapOfShape vertices, edges;
  TopExp::MapShapes(f.face, TopAbs_VERTEX, vertices);
  TopExp::MapShapes(f.face, TopAbs_EDGE, edges);
  for (int v = 1; v <= vertices.Extent(); ++v) f.vertices.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertices(v))));
  for (int e = 1; e <= edges.Extent(); ++e) f.edges.push_back(cad.edges.FindIndex(edges(e)) - 1);
  BRepTools::UVBounds(f.face, f.uvBounds[0], f.uvBounds[1], f.uvBounds[2], f.uvBounds[3]);
  f.boundary = faceUvBoundary(f.face, cad.diagonal);  // a foot point near the boundary is classified exactly
  addSeeds(f);
  return f;
}

CadFaces::CadFaces(const CadSolid& cad, FaceBoxes* boxes)
    : keepsFirstVertex_(OSD_ThreadPool::DefaultPool()->NbThreads() > 1) {
  for (int e = 1; e <= cad.edges.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(cad.edges(e));
    edges_.push_back({edge, extremaBox(edge), BRep_Tool::Degenerated(edge)});
  }
  std::vector<std::vector<int>> neighbours = vertexNeighbours(cad);
  const int count = cad.faces.Extent();
  faces_.resize(count);
  std::vector<const Bnd_Box*> known(count, nullptr);  // read while the faces are made, kept after
  for (int i = 0; boxes && i < count; ++i) known[i] = boxes->find(TopoDS::Face(cad.faces(i + 1)));
  ParallelErrors errors;  // a face's exact box takes milliseconds (a torus' 20): the faces on every thread
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < count; ++i) errors.run([&] { faces_[i] = makeFace(cad, i, known[i]); });
  errors.rethrow();
  for (int i = 0; boxes && i < count; ++i)
    if (!known[i]) boxes->keep(faces_[i].face, faces_[i].exactBox);
  for (int i = 0; i < count; ++i) {
    faces_[i].neighbours = std::move(neighbours[i]);
    faces_[i].name = inputFaceName(cad, i);
    std::vector<Box> boxes;
    for (int e : faces_[i].edges)
      if (!edges_[e].box.IsVoid()) boxes.push_back(boxOf(edges_[e].box));
    if (boxes.size() == faces_[i].edges.size()) faces_[i].edgeTree = std::make_unique<BoxTree>(boxes);
  }
}

CadFaces::~CadFaces() = default;

CadFaceProbe::CadFaceProbe(const CadFaces& faces)
    : faces_(faces), surfaces_(faces.count()), curves_(faces.edgeCount()), explorers_(faces.count()) {}

// The face's surface and its extrema tool, set up as BRepExtrema_ExtPF::Initialize does.
CadFaceProbe::Surface& CadFaceProbe::surface(int face) {
  if (surfaces_[face]) return *surfaces_[face];
  const CadFaces::Face& f = faces_.face(face);
  surfaces_[face] = std::make_unique<Surface>();
  Surface& s = *surfaces_[face];
  s.adaptor.Initialize(f.face, false);
  if (s.adaptor.GetType() == GeomAbs_OtherSurface) return s;
  const double tolerance = std::min(BRep_Tool::Tolerance(f.face), Precision::Confusion());
  const double tolU = std::max(s.adaptor.UResolution(tolerance), Precision::PConfusion());
  const double tolV = std::max(s.adaptor.VResolution(tolerance), Precision::PConfusion());
  s.tolU = tolU, s.tolV = tolV;
  s.extrema.SetFlag(Extrema_ExtFlag_MINMAX);
  s.extrema.SetAlgo(Extrema_ExtAlgo_Tree);  // its grid sorted once, not walked per query
  s.extrema.Initialize(s.adaptor, f.uvBounds[0], f.uvBounds[1], f.uvBounds[2], f.uvBounds[3], tolU, tolV);
  return s;
}

// The edge's point-curve extrema tool, built at the edge's first query.
BRepExtrema_ExtPC& CadFaceProbe::curve(int edge) {
  if (!curves_[edge]) {
    curves_[edge] = std::make_unique<BRepExtrema_ExtPC>();
    curves_[edge]->Initialize(faces_.edge(edge).edge);
  }
  return *curves_[edge];
}

// BRepExtrema's state of a foot point (u, v) on the face: from the face's UvBoundary, or near its
// boundary from BRepClass_FaceClassifier with the face's tolerance, as BRepExtrema_ExtPF classifies (its
// Perform(face, point, tolerance): a BRepClass_FaceExplorer with the default gap tolerance and no boxes).
TopAbs_State CadFaceProbe::classify(int face, double u, double v) {
  const CadFaces::Face& f = faces_.face(face);
  switch (f.boundary->side(u, v)) {
    case UvBoundary::Side::Inside:
      return TopAbs_IN;
    case UvBoundary::Side::Outside:
      return TopAbs_OUT;
    default:
      break;
  }
  // ON within the tolerance of an edge (CheckOn): the classifier's answer without its walk over every edge of the face.
  if (f.boundary->onLineOrCircle(u, v, onEdgeBand(f.tolerance))) return TopAbs_ON;
  std::unique_ptr<BRepClass_FaceExplorer>& explorer = explorers_[face];
  if (!explorer) {
    explorer = std::make_unique<BRepClass_FaceExplorer>(f.face);
    explorer->SetMaxTolerance(0.1);
    explorer->SetUseBndBox(false);
  }
  BRepClass_FClassifier classifier;
  classifier.Perform(*explorer, gp_Pnt2d(u, v), f.tolerance);
  return classifier.State();
}

// The distance BRepExtrema_DistanceSS finds from p to the inside of the face: the nearest extremum of
// those on the face (IN or ON), if one within kEps of it is IN; nullopt if none is.
std::optional<double> CadFaceProbe::faceDistance(int face, const gp_Pnt& p) {
  Surface& s = surface(face);
  if (s.adaptor.GetType() == GeomAbs_OtherSurface) return std::nullopt;
  if (const std::optional<double> on = footNearSeed(face, p)) return on;
  s.extrema.Perform(p);
  if (!s.extrema.IsDone()) return std::nullopt;
  // The extrema nearest first: those farther than kEps beyond the nearest on the face need no classifying.
  std::vector<std::pair<double, int>> byDistance;  // square distance, extremum
  for (int i = 1; i <= s.extrema.NbExt(); ++i) byDistance.emplace_back(s.extrema.SquareDistance(i), i);
  std::sort(byDistance.begin(), byDistance.end());
  std::optional<double> nearest;  // of the extrema on the face (IN or ON)
  bool inside = false;            // one within kEps of it is IN
  for (const auto& [square, i] : byDistance) {
    if (nearest && !(std::sqrt(square) - *nearest < kEps)) break;
    double u = 0, v = 0;
    s.extrema.Point(i).Parameter(u, v);
    const TopAbs_State state = classify(face, u, v);
    if (state != TopAbs_IN && state != TopAbs_ON) continue;
    if (!nearest) nearest = std::sqrt(square);
    inside |= state == TopAbs_IN;
  }
  if (nearest && inside) return nearest;
  return std::nullopt;
}

// The distance from p to a freeform face that p lies on (nearer than the face's tolerance, as the nodes the sweep puts
// on it): the foot found by Newton's method from the nearest seed, inside the face. The global search (Extrema_ExtPS,
// 0.1 ms a point on a B-spline face) would find a distance as small, below the tolerance too. nullopt elsewhere.
std::optional<double> CadFaceProbe::footNearSeed(int face, const gp_Pnt& p) {
  const CadFaces::Face& f = faces_.face(face);
  if (!f.seedGrid) return std::nullopt;
  const Vec3 at(p.X(), p.Y(), p.Z());
  const int seed = f.seedGrid->nearest(at, [&](int k, double) { return (f.seeds[k].point - at).squaredNorm(); });
  if (seed < 0) return std::nullopt;
  const Surface& s = surface(face);
  Extrema_GenLocateExtPS local(s.adaptor, s.tolU, s.tolV);
  local.Perform(p, f.seeds[seed].uv.X(), f.seeds[seed].uv.Y());
  if (!local.IsDone()) return std::nullopt;
  const double distance = std::sqrt(local.SquareDistance());
  if (!(distance < f.tolerance)) return std::nullopt;
  double u = 0, v = 0;
  local.Point().Parameter(u, v);
  if (classify(face, u, v) != TopAbs_IN) return std::nullopt;
  return distance;
}

// The distance BRepExtrema_DistanceSS finds from the vertex to the inside of the edge: the nearest
// extremum, if one within kEps of it is not at an end of the edge; nullopt if none is.
std::optional<double> CadFaceProbe::edgeDistance(int edge, const TopoDS_Vertex& vertex) {
  const CadFaces::Edge& e = faces_.edge(edge);
  if (e.degenerated) return std::nullopt;
  BRepExtrema_ExtPC& extrema = curve(edge);
  extrema.Perform(vertex);
  const int n = extrema.IsDone() ? extrema.NbExt() : 0;
  if (n == 0) return std::nullopt;
  double nearest = extrema.SquareDistance(1);
  for (int i = 2; i <= n; ++i) nearest = std::min(nearest, extrema.SquareDistance(i));
  nearest = std::sqrt(nearest);
  double first = 0, last = 0;
  BRep_Tool::Range(e.edge, first, last);
  for (int i = 1; i <= n; ++i) {
    const double t = extrema.Parameter(i);
    if (std::fabs(nearest - std::sqrt(extrema.SquareDistance(i))) < kEps &&
        std::fabs(t - first) >= Precision::PConfusion() && std::fabs(t - last) > Precision::PConfusion())
      return nearest;
  }
  return std::nullopt;
}

// The distance BRepExtrema_DistShapeShape keeps after comparing p with the face's vertices: the nearest,
// unless it is within kEps of the first vertex's and the vertex pairs were split over threads.
double CadFaceProbe::vertexDistance(const CadFaces::Face& f, const gp_Pnt& p) const {
  const double first = p.Distance(f.vertices[0]);
  double nearest = first;
  for (const gp_Pnt& v : f.vertices) nearest = std::min(nearest, p.Distance(v));
  const bool lowered = nearest < first - kEps || (!faces_.keepsFirstVertex() && std::fabs(nearest - first) < kEps);
  return lowered ? nearest : first;
}

// The smallest of `nearest` and the distances from p to the inside of those of the face's edges whose
// box is not farther than it (BRepExtrema's pruning: a farther edge cannot be nearer).
std::optional<double> CadFaceProbe::edgesDistance(const CadFaces::Face& f, const gp_Pnt& p, const Bnd_Box& pointBox,
                                                  std::optional<double> nearest) {
  TopoDS_Vertex vertex;
  auto visit = [&](int e) {
    const Bnd_Box& box = faces_.edge(e).box;
    if (box.IsVoid() || (nearest && pointBox.Distance(box) > *nearest + kEps)) return false;
    if (vertex.IsNull()) vertex = BRepBuilderAPI_MakeVertex(p).Vertex();
    if (const std::optional<double> d = edgeDistance(e, vertex)) nearest = std::min(nearest.value_or(*d), *d);
    return false;
  };
  if (!f.edgeTree || !nearest) {
    for (int e : f.edges) visit(e);
    return nearest;
  }
  // The least of the edges' distances is the same whichever edges farther than it are asked: only those whose boxes
  // may be within the distance so far (plus the point box's gap, 1e-7) are.
  const double reach = *nearest + kEps + 2 * Precision::Confusion();
  const Vec3 at(p.X(), p.Y(), p.Z());
  f.edgeTree->traverse([&](const Box& b) { return mayBeWithin(at, b, reach); },
                       [&](int k) { return visit(f.edges[k]); });
  return nearest;
}

// BRepExtrema_DistShapeShape's distance from p to the trimmed face: vertices, inside, edges.
double CadFaceProbe::distance(int face, const Vec3& at) {
  const CadFaces::Face& f = faces_.face(face);
  const gp_Pnt p = point(at);
  const Bnd_Box pointBox = vertexBox(p);
  std::optional<double> nearest;
  if (!f.vertices.empty()) nearest = vertexDistance(f, p);
  // BRepExtrema tries the face only if its box is near enough: the same answer if the box holds the foot point.
  if (const std::optional<double> inside = f.extremaBox.IsVoid() ? std::nullopt : faceDistance(face, p)) {
    if (pointBox.Distance(f.extremaBox) > *inside + kEps) return exactDistance(f.face, p);
    nearest = std::min(nearest.value_or(*inside), *inside);
  }
  return edgesDistance(f, p, pointBox, nearest).value_or(std::numeric_limits<double>::infinity());
}

// BRepExtrema_DistanceSS's vertex-face solution (the extremum of Extrema_ExtPS, set up as BRepExtrema_ExtPF does, and
// its point) where BRepExtrema_DistShapeShape keeps it alone: the face is tried (its box is within the distance, plus
// the precision, of p) and every vertex and edge solution is farther by more than the precision. On a plane (u, v)
// are lengths: every boundary point is at least hypot(distance, the foot point's clearance) from p.
std::optional<std::pair<double, gp_Pnt>> CadFaceProbe::planeFoot(int face, const gp_Pnt& p) {
  const CadFaces::Face& f = faces_.face(face);
  Surface& s = surface(face);
  if (s.adaptor.GetType() != GeomAbs_Plane || f.extremaBox.IsVoid()) return std::nullopt;
  s.extrema.Perform(p);
  if (!s.extrema.IsDone() || s.extrema.NbExt() != 1) return std::nullopt;
  double u = 0, v = 0;
  s.extrema.Point(1).Parameter(u, v);
  if (f.boundary->side(u, v) != UvBoundary::Side::Inside) return std::nullopt;
  const double distance = std::sqrt(s.extrema.SquareDistance(1));
  const double apart = f.boundary->clearance(u, v) * f.boundary->margin();
  if (std::hypot(distance, apart) - distance <= 10 * kEps) return std::nullopt;
  if (vertexBox(p).Distance(f.extremaBox) > distance + kEps) return std::nullopt;
  return std::make_pair(distance, s.extrema.Point(1).Value());
}

// The same on a face of any surface: the nearest extremum, inside the face by its UvBoundary, kept where the face's
// vertices and edges (those whose boxes are near enough) are all farther by more than 10 x the precision.
std::optional<std::pair<double, gp_Pnt>> CadFaceProbe::foot(int face, const gp_Pnt& p) {
  const CadFaces::Face& f = faces_.face(face);
  Surface& s = surface(face);
  if (s.adaptor.GetType() == GeomAbs_Plane) return planeFoot(face, p);
  if (s.adaptor.GetType() == GeomAbs_OtherSurface || f.extremaBox.IsVoid() || f.vertices.empty()) return std::nullopt;
  s.extrema.Perform(p);
  if (!s.extrema.IsDone() || s.extrema.NbExt() == 0) return std::nullopt;
  int nearest = 1;
  for (int i = 2; i <= s.extrema.NbExt(); ++i)
    if (s.extrema.SquareDistance(i) < s.extrema.SquareDistance(nearest)) nearest = i;
  double u = 0, v = 0;
  s.extrema.Point(nearest).Parameter(u, v);
  if (f.boundary->side(u, v) != UvBoundary::Side::Inside) return std::nullopt;
  const double distance = std::sqrt(s.extrema.SquareDistance(nearest));
  const Bnd_Box pointBox = vertexBox(p);
  if (pointBox.Distance(f.extremaBox) > distance + kEps) return std::nullopt;
  const double boundary = edgesDistance(f, p, pointBox, vertexDistance(f, p)).value_or(0);
  if (boundary - distance <= 10 * kEps) return std::nullopt;
  return std::make_pair(distance, s.extrema.Point(nearest).Value());
}

// True if p is in the face's box and nearer to the face than its tolerance.
bool CadFaceProbe::lies(int face, const Vec3& p) {
  return !faces_.face(face).box.IsOut(point(p)) && distance(face, p) < faces_.tolerance(face);
}

// The face p was put on and the faces around it that p lies on, with p's distance to the first.
FacesAtPoint CadFaceProbe::facesAt(int face, const Vec3& p) {
  FacesAtPoint at{{face}, distance(face, p)};
  for (int g : faces_.face(face).neighbours)
    if (lies(g, p)) at.faces.push_back(g);
  return at;
}

}  // namespace hexlayer
