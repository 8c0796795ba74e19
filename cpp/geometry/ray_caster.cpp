#include "geometry/ray_caster.hpp"

#include <BRepBndLib.hxx>
#include <ElCLib.hxx>
#include <ElSLib.hxx>
#include <IntAna_IntConicQuad.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>

#include "geometry/bnd_box.hpp"

namespace hexlayer {

namespace {

// Face f's box, grown by the tolerance and by the box's rounding.
Box faceBox(const TopoDS_Shape& face, double tolerance) {
  Bnd_Box b;
  BRepBndLib::Add(face, b, false);  // from the surface, not the triangulation (which may lie inside it)
  b.Enlarge(tolerance);
  return boxOf(b);
}

std::vector<Box> faceBoxes(const CadSolid& cad, double tolerance) {
  std::vector<Box> boxes;
  for (int f = 1; f <= cad.faces.Extent(); ++f) boxes.push_back(faceBox(cad.faces(f), tolerance));
  return boxes;
}

// Directions of the inside test's rays: no two in a plane with a coordinate axis, so that rays from points of a
// grid do not run along the faces of a part drawn on the axes.
const Vec3 kInsideRays[] = {Vec3(0.5774, 0.5919, 0.5629), Vec3(-0.7071, 0.4082, 0.5774), Vec3(0.2673, -0.8018, 0.5345)};

// The count of faces the ray crosses, if every hit is clean.
std::optional<int> cleanCrossings(const std::vector<RayHit>& hits, double tolerance) {
  for (std::size_t i = 0; i < hits.size(); ++i)
    if (hits[i].onBoundary || hits[i].transition == IntCurveSurface_Tangent ||
        (i > 0 && hits[i].w - hits[i - 1].w <= tolerance))
      return std::nullopt;
  return static_cast<int>(hits.size());
}

bool before(const RayHit& a, const RayHit& b) { return a.w < b.w || (a.w == b.w && a.face < b.face); }

// IntCurveSurface_Inter's tolerances (its TOLERANCE_ANGULAIRE and TOLTANGENCY).
constexpr double kAngular = 1e-8;
constexpr double kTangency = 1e-8;

// IntCurveSurface_Inter::AppendPoint's test of a hit's parameters: within the surface's bounds (the face's, the
// intersector's surface being restricted to them), up to kTangency.
bool inBounds(const BRepAdaptor_Surface& s, double u, double v) {
  return s.FirstUParameter() - u < kTangency && u - s.LastUParameter() < kTangency &&
         s.FirstVParameter() - v < kTangency && v - s.LastVParameter() < kTangency;
}

// IntCurveSurface_ComputeTransitions: In or Out by the sign of the cosine between the line and the surface's normal
// D1U x D1V at (u, v) (Tangent within kAngular), turned as IntCurvesFace_Intersector::InternalCall turns it on a
// reversed face.
IntCurveSurface_TransitionOnCurve transition(const BRepAdaptor_Surface& s, const gp_Lin& line, double u, double v) {
  gp_Pnt at;
  gp_Vec du, dv;
  s.D1(u, v, at, du, dv);
  const gp_Vec normal = du.Crossed(dv);
  const double norm = normal.Magnitude();
  if (norm <= kAngular) return IntCurveSurface_Tangent;
  gp_Vec tangent(line.Direction());
  tangent.Normalize();
  const double cosine = normal.Dot(tangent) / norm;
  if (std::abs(cosine) <= kAngular) return IntCurveSurface_Tangent;
  const bool in = (cosine < 0) != (s.Face().Orientation() == TopAbs_REVERSED);
  return in ? IntCurveSurface_In : IntCurveSurface_Out;
}

}  // namespace

RayCaster::RayCaster(const CadSolid& cad, double tolerance)
    : boxes_(faceBoxes(cad, tolerance)), tolerance_(tolerance), diagonal_(cad.diagonal), tree_(boxes_) {
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    const TopoDS_Face& face = TopoDS::Face(cad.faces(f));
    faces_.push_back(std::make_unique<IntCurvesFace_Intersector>(face, tolerance));
    auto plane = std::make_unique<PlaneFace>();
    plane->surface.Initialize(face, true);  // as the intersector's: within the face's parameter bounds
    const GeomAbs_SurfaceType type = plane->surface.GetType();
    analytic_.push_back(type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone ||
                        type == GeomAbs_Sphere || type == GeomAbs_Torus);
    if (type == GeomAbs_Plane) plane->plane = plane->surface.Plane();
    planes_.push_back(type == GeomAbs_Plane ? std::move(plane) : nullptr);
  }
}

const UvBoundary* RayCaster::boundary(PlaneFace& face) const {
  if (!face.boundary) face.boundary = faceUvBoundary(face.surface.Face(), diagonal_);
  // The intersector classifies with max(tolerance, the edges' tolerances): the band left undecided must hold it (the
  // margin is at least 1e-5 x the diagonal, the tolerance 1e-7 x the diagonal as WallRays, the tet filter and the
  // side classification cast: a factor 100).
  return face.boundary->margin() >= 10 * tolerance_ ? face.boundary.get() : nullptr;
}

// IntCurvesFace_Intersector::Perform on a plane, as OpenCASCADE 7.6 computes it: IntAna_IntConicQuad's line-plane
// point and parameter (IntCurveSurface_Inter::PerformConicSurf, AppendIntAna), ElSLib's (u, v) of it, the bounds and
// the transition of AppendPoint, the point on the line at w; the classification of (u, v) on the face by its
// UvBoundary where that decides (IntCurvesFace_Intersector::InternalCall's keeps IN and ON).
RayCaster::PlaneHit RayCaster::planeHit(int f, const gp_Lin& line, double wMin, double wMax,
                                        std::vector<RayHit>& hits) {
  PlaneFace& face = *planes_[f];
  const IntAna_IntConicQuad meet(line, face.plane, kAngular);
  if (!meet.IsDone() || meet.IsParallel() || meet.IsInQuadric() || meet.NbPoints() != 1) return PlaneHit::kNone;
  const double w = meet.ParamOnConic(1);
  double u = 0, v = 0;
  ElSLib::Parameters(face.plane, meet.Point(1), u, v);
  if (!inBounds(face.surface, u, v) || w < wMin || w > wMax) return PlaneHit::kNone;
  const UvBoundary* quick = boundary(face);
  const UvBoundary::Side side = quick ? quick->side(u, v) : UvBoundary::Side::Undecided;
  if (side == UvBoundary::Side::Outside) return PlaneHit::kNone;
  // ON an edge (kept) if within the classifier's tolerance of it
  if (side == UvBoundary::Side::Undecided && !(quick && quick->onLineOrCircle(u, v, onEdgeBand(tolerance_))))
    return PlaneHit::kUndecided;
  const gp_Pnt p = ElCLib::Value(w, line);
  hits.push_back({w, f, Vec3(p.X(), p.Y(), p.Z()), u, v, transition(face.surface, line, u, v)});
  return PlaneHit::kHit;
}

bool RayCaster::missesPlane(int f, const Vec3& from, const Vec3& dir, double wMin, double wMax) const {
  if (!planes_[f]) return false;
  const gp_Ax3& frame = planes_[f]->plane.Position();
  const Vec3 normal(frame.Direction().X(), frame.Direction().Y(), frame.Direction().Z());
  const Vec3 origin(frame.Location().X(), frame.Location().Y(), frame.Location().Z());
  const double across = normal.dot(dir.normalized());  // w as OpenCASCADE measures it: along the unit direction
  if (std::abs(across) < 1e-6) return false;           // (nearly) parallel: left to the intersector
  const double w = normal.dot(origin - from) / across;
  const double margin = 1e-6 * (std::abs(wMin) + std::abs(wMax) + std::abs(w)) + 1e-9;
  return w < wMin - margin || w > wMax + margin;
}

std::vector<std::pair<double, int>> RayCaster::candidates(const Vec3& from, const Vec3& dir, double wMin,
                                                          double wMax) const {
  std::vector<std::pair<double, int>> found;
  tree_.traverse([&](const Box& b) { return rayEntersBox(from, dir, b, wMin, wMax) < INFINITY; },
                 [&](int f) {
                   if (const double w = rayEntersBox(from, dir, boxes_[f], wMin, wMax); w < INFINITY)
                     found.emplace_back(w, f);
                   return false;
                 });
  std::sort(found.begin(), found.end());
  return found;
}

void RayCaster::hitsOnFace(int f, const Vec3& from, const Vec3& dir, double wMin, double wMax,
                           std::vector<RayHit>& hits) {
  if (missesPlane(f, from, dir, wMin, wMax)) return;
  const gp_Lin line(gp_Pnt(from.x(), from.y(), from.z()), gp_Dir(dir.x(), dir.y(), dir.z()));
  if (planes_[f] && planeHit(f, line, wMin, wMax, hits) != PlaneHit::kUndecided) {
    ++closedForm_;
    return;
  }
  IntCurvesFace_Intersector& on = *faces_[f];
  on.Perform(line, wMin, wMax);
  for (int i = 1; on.IsDone() && i <= on.NbPnt(); ++i) {
    const gp_Pnt& p = on.Pnt(i);
    hits.push_back(
        {on.WParameter(i), f, Vec3(p.X(), p.Y(), p.Z()), on.UParameter(i), on.VParameter(i), on.Transition(i)});
  }
}

std::vector<RayHit> RayCaster::hitsOnFaces(const std::vector<std::pair<double, int>>& faces, const Vec3& from,
                                           const Vec3& dir, double wMin, double wMax) {
  std::vector<RayHit> hits;
  for (const auto& [enter, f] : faces) hitsOnFace(f, from, dir, wMin, wMax, hits);
  std::sort(hits.begin(), hits.end(), before);
  return hits;
}

std::vector<RayHit> RayCaster::all(const Vec3& from, const Vec3& dir, double wMin, double wMax) {
  return hitsOnFaces(candidates(from, dir, wMin, wMax), from, dir, wMin, wMax);
}

std::optional<RayHit> RayCaster::nearest(const Vec3& from, const Vec3& dir, double wMin, double wMax) {
  std::vector<RayHit> hits;
  double reach = wMax;  // no face entered beyond the nearest hit so far can hold a nearer one
  for (const auto& [enter, f] : candidates(from, dir, wMin, wMax)) {
    if (enter > reach) break;
    hitsOnFace(f, from, dir, wMin, reach, hits);
    for (const RayHit& h : hits) reach = std::min(reach, h.w);
  }
  if (hits.empty()) return std::nullopt;
  return *std::min_element(hits.begin(), hits.end(), before);
}

std::optional<bool> RayCaster::inside(const Vec3& p, double tolerance, double reach) {
  std::optional<bool> first;  // two clean rays must agree
  for (const Vec3& d : kInsideRays) {
    const Vec3 dir = d.normalized();
    const std::vector<std::pair<double, int>> faces = candidates(p, dir, -tolerance, reach);
    // On other surfaces OpenCASCADE's intersector searches a polyhedron, made to find the nearest hit, and may
    // miss one (a B-spline face's seam): such a ray counts nothing.
    if (std::any_of(faces.begin(), faces.end(), [&](const auto& f) { return !analytic_[f.second]; })) continue;
    const std::vector<RayHit> hits = hitsOnFaces(faces, p, dir, -tolerance, reach);
    if (!hits.empty() && std::abs(hits.front().w) <= tolerance) return false;  // on a face
    const std::optional<int> n = cleanCrossings(hits, tolerance);
    if (!n) continue;
    if (!first) {
      first = *n % 2 == 1;
      continue;
    }
    return *first == (*n % 2 == 1) ? first : std::nullopt;
  }
  return std::nullopt;
}

}  // namespace hexlayer
