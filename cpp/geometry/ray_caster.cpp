#include "geometry/ray_caster.hpp"

#include <BRepBndLib.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <ElCLib.hxx>
#include <ElSLib.hxx>
#include <IntAna_IntConicQuad.hxx>
#include <IntAna_IntLinTorus.hxx>
#include <IntAna_Quadric.hxx>
#include <Precision.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
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

// A plane, cylinder, cone, sphere or torus: IntCurveSurface_Inter intersects a line with it in closed form.
bool isElementary(GeomAbs_SurfaceType type) {
  return type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone || type == GeomAbs_Sphere ||
         type == GeomAbs_Torus;
}

// Cells per parameter direction of a SurfaceGrid: four per C2 piece of the surface (a B-spline's knot span), 16 to 96.
int gridCells(int pieces) { return std::clamp(4 * pieces, 16, 96); }

std::vector<double> spaced(double first, double last, int cells) {
  std::vector<double> t(cells + 1);
  for (int k = 0; k <= cells; ++k) t[k] = first + (last - first) * k / cells;
  t[cells] = last;
  return t;
}

// Newton's method on S(u, v) - (o + w d) = 0 from the given (u, v, w); false if it does not settle (|F| below
// `close`) within 30 steps or its Jacobian [S_u S_v -d] is singular. [in,out] u, v, w.
bool settle(const BRepAdaptor_Surface& s, const gp_Lin& line, double close, double& u, double& v, double& w) {
  const Vec3 o = toVec(line.Location()), d(line.Direction().X(), line.Direction().Y(), line.Direction().Z());
  for (int step = 0, settled = 0; step < 30; ++step) {
    gp_Pnt p;
    gp_Vec su, sv;
    s.D1(u, v, p, su, sv);
    const Vec3 f = toVec(p) - (o + w * d);
    if (f.norm() <= close && ++settled == 2) return true;  // one more step once settled: to the rounding
    Eigen::Matrix3d j;
    j << su.X(), sv.X(), -d.x(), su.Y(), sv.Y(), -d.y(), su.Z(), sv.Z(), -d.z();
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(j);
    if (!lu.isInvertible()) return false;
    const Vec3 x = lu.solve(-f);
    u += x.x(), v += x.y(), w += x.z();
  }
  return false;
}

}  // namespace

RayCaster::RayCaster(const CadSolid& cad, double tolerance)
    : boxes_(faceBoxes(cad, tolerance)), tolerance_(tolerance), diagonal_(cad.diagonal), tree_(boxes_) {
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    const TopoDS_Face& face = TopoDS::Face(cad.faces(f));
    faces_.push_back(std::make_unique<IntCurvesFace_Intersector>(face, tolerance));
    auto elementary = std::make_unique<ElementaryFace>();
    elementary->surface.Initialize(face, true);  // as the intersector's: within the face's parameter bounds
    elementary->type = elementary->surface.GetType();
    if (elementary->type == GeomAbs_Plane) elementary->plane = elementary->surface.Plane();
    elementary_.push_back(isElementary(elementary->type) ? std::move(elementary) : nullptr);
  }
  grids_.resize(faces_.size());
}

RayCaster::SurfaceGrid& RayCaster::surfaceGrid(int f) {
  std::unique_ptr<SurfaceGrid>& grid = grids_[f];
  if (grid) return *grid;
  grid = std::make_unique<SurfaceGrid>();
  SurfaceGrid& g = *grid;
  g.surface.Initialize(faces_[f]->Face(), true);
  const BRepAdaptor_Surface& s = g.surface;
  g.us = spaced(s.FirstUParameter(), s.LastUParameter(), gridCells(s.NbUIntervals(GeomAbs_C2)));
  g.vs = spaced(s.FirstVParameter(), s.LastVParameter(), gridCells(s.NbVIntervals(GeomAbs_C2)));
  const int nu = static_cast<int>(g.us.size()), nv = static_cast<int>(g.vs.size());
  std::vector<Vec3> corner(nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) corner[i * nv + j] = toVec(s.Value(g.us[i], g.vs[j]));
  std::vector<Box> boxes;
  for (int i = 0; i + 1 < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) {
      const Vec3 &a = corner[i * nv + j], &b = corner[(i + 1) * nv + j], &c = corner[i * nv + j + 1],
                 &d = corner[(i + 1) * nv + j + 1];
      Box box;
      for (const Vec3* p : {&a, &b, &c, &d}) box.add(*p);
      double strays = 0;  // from the bilinear patch of the corners
      for (const auto& [x, y] : {std::pair(0.5, 0.5), {0.5, 0.0}, {0.5, 1.0}, {0.0, 0.5}, {1.0, 0.5}}) {
        const Vec3 p = toVec(s.Value(g.us[i] + x * (g.us[i + 1] - g.us[i]), g.vs[j] + y * (g.vs[j + 1] - g.vs[j])));
        const Vec3 bilinear = (1 - x) * (1 - y) * a + x * (1 - y) * b + (1 - x) * y * c + x * y * d;
        strays = std::max(strays, (p - bilinear).norm());
        box.add(p);
      }
      const Vec3 grow = Vec3::Constant(2 * strays + tolerance_);
      box.lo -= grow, box.hi += grow;
      boxes.push_back(box);
    }
  g.cells = std::make_unique<BoxTree>(boxes);
  g.boundary = faceUvBoundary(faces_[f]->Face(), diagonal_);
  // Its margin is at least 1e-5 x the diagonal in 3D: far above the intersector's tolerance, as boundary(PlaneFace&)
  // asks (there in (u, v), lengths on a plane).
  if (10 * tolerance_ > 1e-5 * diagonal_) g.boundary.reset();
  return g;
}

RayCaster::SurfaceHits RayCaster::surfaceHits(int f, const gp_Lin& line, double wMin, double wMax,
                                              std::vector<RayHit>& hits) {
  SurfaceGrid& g = surfaceGrid(f);
  if (!g.boundary) return SurfaceHits::kUndecided;
  const Vec3 from = toVec(line.Location()), dir(line.Direction().X(), line.Direction().Y(), line.Direction().Z());
  const int nv = static_cast<int>(g.vs.size()) - 1;
  std::vector<RayHit> found;
  bool undecided = false;
  g.cells->traverse([&](const Box& b) { return rayEntersBox(from, dir, b, wMin, wMax) < INFINITY; },
                    [&](int cell) {
                      const int i = cell / nv, j = cell % nv;
                      double u = 0.5 * (g.us[i] + g.us[i + 1]), v = 0.5 * (g.vs[j] + g.vs[j + 1]);
                      double w = ElCLib::Parameter(line, g.surface.Value(u, v));
                      if (!settle(g.surface, line, 1e-3 * tolerance_, u, v, w)) return undecided = true;
                      const double du = 1e-9 * (g.us[i + 1] - g.us[i]), dv = 1e-9 * (g.vs[j + 1] - g.vs[j]);
                      // a neighbour's hit is its own
                      if (u < g.us[i] - du || u > g.us[i + 1] + du || v < g.vs[j] - dv || v > g.vs[j + 1] + dv)
                        return false;
                      if (w < wMin || w > wMax || !inBounds(g.surface, u, v)) return false;
                      gp_Pnt at;
                      gp_Vec su, sv;
                      g.surface.D1(u, v, at, su, sv);
                      const gp_Vec normal = su.Crossed(sv);
                      // grazing, or near the boundary: the intersector's to decide
                      if (std::abs(normal.Dot(gp_Vec(line.Direction()))) < 0.1 * normal.Magnitude())
                        return undecided = true;
                      const UvBoundary::Side side = g.boundary->side(u, v);
                      if (side == UvBoundary::Side::Undecided) return undecided = true;
                      if (side == UvBoundary::Side::Inside)
                        found.push_back({w, f, toVec(ElCLib::Value(w, line)), u, v, transition(g.surface, line, u, v)});
                      return false;
                    });
  if (undecided) return SurfaceHits::kUndecided;
  std::sort(found.begin(), found.end(), before);
  for (std::size_t k = 0; k < found.size(); ++k)  // a hit on the side two cells share: once
    if (k == 0 || found[k].w - found[k - 1].w > tolerance_) hits.push_back(found[k]);
  return SurfaceHits::kDone;
}

double RayCaster::onBand(const ElementaryFace& face) const {
  const double largest = largestTolerance(face.surface.Face());
  return std::max({tolerance_, face.surface.UResolution(largest), face.surface.VResolution(largest)});
}

const UvBoundary* RayCaster::boundary(ElementaryFace& face) const {
  if (face.boundaryMade) return face.boundary.get();
  face.boundaryMade = true;
  if (face.type == GeomAbs_Plane) {
    face.boundary = faceUvBoundary(face.surface.Face(), diagonal_);
    // The intersector classifies with max(tolerance, the edges' tolerances): the band left undecided must hold it (the
    // margin is at least 1e-5 x the diagonal, the tolerance 1e-7 x the diagonal as WallRays, the tet filter and the
    // side classification cast: a factor 100).
    if (face.boundary->margin() < 10 * tolerance_) face.boundary.reset();
  } else {  // u is an angle on a cylinder: the intersector's ON band is wider there than on a plane
    face.boundary = faceUvBoundary(face.surface.Face(), diagonal_, 10 * onBand(face));
  }
  return face.boundary.get();
}

namespace {

// IntCurveSurface_Inter's points of a line on an elementary surface (PerformConicSurf: IntAna's points, their (u, v)
// by ElSLib), as (w, u, v) before AppendPoint brings u and v into the surface's periods; nullopt where the intersector
// takes its general path (a cone of half-angle within 1e5 x Precision::Angular() of pi/2, a line IntAna_IntLinTorus
// fails on). [in] s: the face's surface; [in] line.
std::optional<std::vector<std::array<double, 3>>> conicSurfacePoints(const BRepAdaptor_Surface& s, const gp_Lin& line) {
  std::vector<std::array<double, 3>> points;
  auto append = [&](const IntAna_IntConicQuad& meet, auto parameters) {
    if (!meet.IsDone() || meet.IsParallel() || meet.IsInQuadric()) return;  // AppendIntAna: no point
    for (int i = 1; i <= meet.NbPoints(); ++i) {
      double u = 0, v = 0;
      parameters(meet.Point(i), u, v);
      points.push_back({meet.ParamOnConic(i), u, v});
    }
  };
  switch (s.GetType()) {
    case GeomAbs_Plane:
      append(IntAna_IntConicQuad(line, s.Plane(), kAngular),
             [&](const gp_Pnt& p, double& u, double& v) { ElSLib::Parameters(s.Plane(), p, u, v); });
      return points;
    case GeomAbs_Cylinder:
      append(IntAna_IntConicQuad(line, IntAna_Quadric(s.Cylinder())),
             [&](const gp_Pnt& p, double& u, double& v) { ElSLib::Parameters(s.Cylinder(), p, u, v); });
      return points;
    case GeomAbs_Sphere:
      append(IntAna_IntConicQuad(line, IntAna_Quadric(s.Sphere())),
             [&](const gp_Pnt& p, double& u, double& v) { ElSLib::Parameters(s.Sphere(), p, u, v); });
      return points;
    case GeomAbs_Cone: {
      const gp_Cone cone = s.Cone();
      if (std::abs(cone.SemiAngle()) >= M_PI / 2 - 1e5 * Precision::Angular()) return std::nullopt;
      append(IntAna_IntConicQuad(line, IntAna_Quadric(cone)),
             [&](const gp_Pnt& p, double& u, double& v) { ElSLib::Parameters(cone, p, u, v); });
      return points;
    }
    case GeomAbs_Torus: {
      const IntAna_IntLinTorus meet(line, s.Torus());
      if (!meet.IsDone()) return std::nullopt;
      for (int i = 1; i <= meet.NbPoints(); ++i) {
        double u = 0, v = 0;
        meet.ParamOnTorus(i, u, v);
        points.push_back({meet.ParamOnLine(i), u, v});
      }
      return points;
    }
    default:
      return std::nullopt;
  }
}

}  // namespace

// IntCurvesFace_Intersector::Perform on an elementary surface, as OpenCASCADE 7.6 computes it: the line's points on the
// surface (conicSurfacePoints), u and v brought into the surface's periods and kept within its bounds (AppendPoint),
// the transition, the point on the line at w; each point classified on the face by its UvBoundary where that decides
// (IntCurvesFace_Intersector::InternalCall keeps IN and ON, in [wMin, wMax]).
RayCaster::ElementaryHits RayCaster::elementaryHits(int f, const gp_Lin& line, double wMin, double wMax,
                                                    std::vector<RayHit>& hits) {
  ElementaryFace& face = *elementary_[f];
  const std::optional<std::vector<RayHit>> appended = surfacePoints(f, line);
  if (!appended) return ElementaryHits::kUndecided;
  std::vector<RayHit> found;
  for (const RayHit& hit : *appended) {  // InternalCall
    if (hit.w < wMin || hit.w > wMax) continue;
    const UvBoundary* quick = boundary(face);
    const UvBoundary::Side side = quick ? quick->side(hit.u, hit.v) : UvBoundary::Side::Undecided;
    if (side == UvBoundary::Side::Outside) continue;
    // ON an edge (kept) if within the classifier's tolerance of it
    if (side == UvBoundary::Side::Undecided && !(quick && quick->onLineOrCircle(hit.u, hit.v, onEdgeBand(tolerance_))))
      return ElementaryHits::kUndecided;
    found.push_back(hit);
  }
  hits.insert(hits.end(), found.begin(), found.end());
  return ElementaryHits::kDone;
}

std::optional<std::vector<RayHit>> RayCaster::surfacePoints(int f, const gp_Lin& line) const {
  const ElementaryFace& face = *elementary_[f];
  const BRepAdaptor_Surface& s = face.surface;
  const std::optional<std::vector<std::array<double, 3>>> points = conicSurfacePoints(s, line);
  if (!points) return std::nullopt;
  std::vector<RayHit> appended;
  for (auto [w, u, v] : *points) {  // AppendPoint
    if (s.IsUPeriodic() || face.type == GeomAbs_Cylinder || face.type == GeomAbs_Cone || face.type == GeomAbs_Sphere)
      u = ElCLib::InPeriod(u, s.FirstUParameter(), s.FirstUParameter() + s.UPeriod());
    if (s.IsVPeriodic()) v = ElCLib::InPeriod(v, s.FirstVParameter(), s.FirstVParameter() + s.VPeriod());
    if (!inBounds(s, u, v)) continue;
    const RayHit hit{w, f, toVec(ElCLib::Value(w, line)), u, v, transition(s, line, u, v)};
    // IntCurveSurface_Intersection::Append keeps one of two points within 1e-8 in u, v and w with the same transition
    // (a line tangent to a cylinder: IntAna's double root)
    if (std::none_of(appended.begin(), appended.end(), [&](const RayHit& a) {
          return std::abs(a.u - u) < 1e-8 && std::abs(a.v - v) < 1e-8 && std::abs(a.w - w) < 1e-8 &&
                 a.transition == hit.transition;
        }))
      appended.push_back(hit);
  }
  return appended;
}

bool RayCaster::classifiedPoints(int f, const gp_Lin& line, double wMin, double wMax, std::vector<RayHit>& hits) const {
  const std::optional<std::vector<RayHit>> points = surfacePoints(f, line);
  if (!points) return false;
  const double band = onBand(*elementary_[f]);
  for (const RayHit& hit : *points) {
    if (hit.w < wMin || hit.w > wMax) continue;
    const TopAbs_State state = BRepClass_FaceClassifier(faces_[f]->Face(), gp_Pnt2d(hit.u, hit.v), band).State();
    if (state == TopAbs_IN || state == TopAbs_ON) hits.push_back(hit);
  }
  return true;
}

bool RayCaster::missesPlane(int f, const Vec3& from, const Vec3& dir, double wMin, double wMax) const {
  if (!elementary_[f] || elementary_[f]->type != GeomAbs_Plane) return false;
  const gp_Ax3& frame = elementary_[f]->plane.Position();
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
  if (elementary_[f] && elementaryHits(f, line, wMin, wMax, hits) == ElementaryHits::kDone) {
    ++closedForm_;
    return;
  }
  if (!elementary_[f]) {
    if (surfaceHits(f, line, wMin, wMax, hits) == SurfaceHits::kDone) {
      ++gridAnswers_;
      return;
    }
    ++intersectorOnOtherSurfaces_;
  }
  IntCurvesFace_Intersector& on = *faces_[f];
  try {
    on.Perform(line, wMin, wMax);
  } catch (const Standard_Failure&) {
    // Its ON test near the boundary projects the point on every edge's 3D curve, and a degenerated edge (a sphere's
    // pole, a cone's apex) has none: Standard_NullObject. The face's points classified exactly instead, if it has
    // them in closed form.
    if (!elementary_[f] || !classifiedPoints(f, line, wMin, wMax, hits)) throw;
    return;
  }
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
    const long asked = intersectorOnOtherSurfaces_;
    std::vector<RayHit> hits;
    try {
      hits = hitsOnFaces(faces, p, dir, -tolerance, reach);
    } catch (const Standard_Failure&) {  // the intersector's ON test at a B-spline face's degenerated edge: no count
      continue;
    }
    // On other surfaces OpenCASCADE's intersector searches a polyhedron, made to find the nearest hit, and may
    // miss one (a B-spline face's seam): a ray that needed it counts nothing.
    if (intersectorOnOtherSurfaces_ != asked) continue;
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
