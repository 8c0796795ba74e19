#include "geometry/boundary_triangles.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRep_Tool.hxx>
#include <Extrema_ExtPS.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>

#include "geometry/face_sampling.hpp"

namespace hexlayer {

namespace {

// Of the diagonal, for freeform faces (prepareSolid: 2e-3). At 1e-4 Watson's Delaunay took 1.5 s for the 80 000
// triangles of a curved shell's three B-spline faces, at 2e-4 0.48 s for 44 000, the same meshes of 176 sample parts
// and twins.
constexpr double kFineDeflection = 2e-4;

// The points where the face's surface is singular: the vertices of its degenerated edges (a
// sphere's or a cone's pole), with their tolerances.
std::vector<std::pair<gp_Pnt, double>> facePoles(const TopoDS_Face& face) {
  std::vector<std::pair<gp_Pnt, double>> poles;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
    if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) {
      const TopoDS_Vertex v = TopExp::FirstVertex(TopoDS::Edge(e.Current()));
      poles.emplace_back(BRep_Tool::Pnt(v), BRep_Tool::Tolerance(v));
    }
  return poles;
}

// Whether a corner of the triangle lies on a pole, where a point's parameter u is arbitrary.
bool touchesPole(const Triangle2d& t, const std::vector<std::pair<gp_Pnt, double>>& poles) {
  for (const auto& [pole, tolerance] : poles)
    for (const gp_Pnt& corner : t.xyz)
      if (corner.Distance(pole) <= tolerance) return true;
  return false;
}

// Distances from points to the nearest point of the surface, with its extrema tool set up once (its sample grid
// sorted as a tree: one built per point was most of the periodic shell's boundary triangles).
class SurfaceDistance {
 public:
  explicit SurfaceDistance(const BRepAdaptor_Surface& surface) : surface_(surface) {}
  // [in] p. Returns the distance, infinite if no nearest point is found.
  double operator()(const gp_Pnt& p) {
    if (!ready_) {
      extrema_.SetFlag(Extrema_ExtFlag_MIN);
      extrema_.SetAlgo(Extrema_ExtAlgo_Tree);
      extrema_.Initialize(surface_, surface_.FirstUParameter(), surface_.LastUParameter(), surface_.FirstVParameter(),
                          surface_.LastVParameter(), 1e-9, 1e-9);
      ready_ = true;
    }
    extrema_.Perform(p);
    double d2 = INFINITY;
    if (extrema_.IsDone())
      for (int i = 1; i <= extrema_.NbExt(); ++i) d2 = std::min(d2, extrema_.SquareDistance(i));
    return std::sqrt(d2);
  }

 private:
  const BRepAdaptor_Surface& surface_;
  Extrema_ExtPS extrema_;
  bool ready_ = false;  // the grid is built at the first point asked
};

// Largest distance between the face's triangles and the exact surface, at each triangle's corners,
// edge midpoints and centre: to the surface point at the same parameters, or, where that is farther than
// `near` (next to a pole, or on a freeform surface whose parameters run unevenly over the triangle) and
// the nearest surface point is nearer, to that.
double largestDeviation(const TopoDS_Face& face, const std::vector<Triangle2d>& mesh, double near) {
  static constexpr double kAt[7][3] = {
      {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}, {1.0 / 3, 1.0 / 3, 1.0 / 3}};
  const BRepAdaptor_Surface surface(face);
  SurfaceDistance distanceToSurface(surface);
  const std::vector<std::pair<gp_Pnt, double>> poles = facePoles(face);
  double worst = 0;
  for (const Triangle2d& t : mesh) {
    const bool pole = touchesPole(t, poles);
    for (const auto& w : kAt) {
      const gp_XY uv = w[0] * t.uv[0].XY() + w[1] * t.uv[1].XY() + w[2] * t.uv[2].XY();
      const gp_XYZ xyz = w[0] * t.xyz[0].XYZ() + w[1] * t.xyz[1].XYZ() + w[2] * t.xyz[2].XYZ();
      const double atParameters = (surface.Value(uv.X(), uv.Y()).XYZ() - xyz).Modulus();
      const bool uneven = pole || atParameters > near;
      worst = std::max(worst, uneven ? std::min(atParameters, distanceToSurface(xyz)) : atParameters);
    }
  }
  return worst;
}

// Whether every edge of the triangles (corners compared exactly) is shared by an even number of
// them: a closed surface, across which a ray's crossings alternate inside and outside.
bool closedSurface(const std::vector<Triangle>& triangles) {
  const auto before = [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  };
  std::vector<std::pair<Vec3, Vec3>> edges;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = t[k], &b = t[(k + 1) % 3];
      if (a != b) edges.push_back(before(a, b) ? std::make_pair(a, b) : std::make_pair(b, a));
    }
  const auto order = [&](const auto& e, const auto& f) {
    return before(e.first, f.first) || (e.first == f.first && before(e.second, f.second));
  };
  std::sort(edges.begin(), edges.end(), order);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if ((j - i) % 2) return false;
    i = j;
  }
  return true;
}

// Three ray directions, each a coordinate axis tilted off the grid, the axis of the triangles'
// smallest extent first: rays leave a thin solid soon.
std::array<Vec3, 3> rayDirections(const std::vector<Triangle>& triangles) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const Triangle& t : triangles)
    for (const Vec3& v : t) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  std::array<int, 3> axes = {0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return hi[a] - lo[a] < hi[b] - lo[b]; });
  std::array<Vec3, 3> rays;
  for (int k = 0; k < 3; ++k) {
    Vec3 d = Vec3::Zero();
    d[axes[k]] = 1, d[axes[(k + 1) % 3]] = 0.0917, d[axes[(k + 2) % 3]] = 0.0533;
    rays[k] = d.normalized();
  }
  return rays;
}

// Whether a face of the solid is freeform (B-spline, Bezier, offset, swept): not a plane,
// cylinder, cone, sphere or torus.
bool hasFreeformFace(const CadSolid& cad) {
  for (int f = 1; f <= cad.faces.Extent(); ++f)
    if (BRepAdaptor_Surface(TopoDS::Face(cad.faces(f))).GetType() > GeomAbs_Torus) return true;
  return false;
}

// The faces whose triangles are tested: the solid's own (prepareSolid's triangulation), or, if
// some are freeform, those of a copy triangulated finer. Near freeform faces OpenCASCADE's
// classifier takes milliseconds a point, far more than the finer mesh that spares it most.
TopTools_IndexedMapOfShape triangulatedFaces(const CadSolid& cad) {
  if (!hasFreeformFace(cad)) return cad.faces;
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(cad.solid, false).Shape();  // without the solid's triangulation
  triangulateFaces(copy, kFineDeflection * cad.diagonal);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(copy, TopAbs_FACE, faces);
  return faces;
}

}  // namespace

BoundaryTriangles::BoundaryTriangles(const CadSolid& cad) {
  const TopTools_IndexedMapOfShape faces = triangulatedFaces(cad);
  std::vector<Triangle> triangles, uncut;
  bool cut = false;  // some face is cut through the part
  double deviation = 0;
  for (int f = 1; f <= faces.Extent(); ++f) {
    const TopoDS_Face face = TopoDS::Face(faces(f));
    const std::vector<Triangle2d> mesh = faceTriangles(face);
    if (mesh.empty()) return;
    deviation = std::max(deviation, largestDeviation(face, mesh, 2 * kFineDeflection * cad.diagonal));
    for (const Triangle2d& t : mesh) {
      triangles.push_back(spaceTriangle(t));
      if (isCutFace(cad, f - 1))
        cut = true;
      else
        uncut.push_back(triangles.back());
    }
  }
  if (triangles.empty() || !closedSurface(triangles)) return;
  // A triangle with two corners at one point (at a pole) is a segment along its neighbours' edges.
  const auto degenerate = [](const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; };
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(), degenerate), triangles.end());
  margin_ = 2 * deviation + largestTolerance(cad.solid) + 1e-6 * cad.diagonal;
  rays_ = rayDirections(triangles);
  if (cut) {
    uncut.erase(std::remove_if(uncut.begin(), uncut.end(), degenerate), uncut.end());
    uncut_.emplace(std::move(uncut));
  }
  tree_.emplace(std::move(triangles));
}

Containment BoundaryTriangles::classify(const Vec3& p) const {
  if (!tree_ || tree_->anyWithin(p, margin_)) return Containment::kUndecided;
  for (const Vec3& dir : rays_)
    if (const std::optional<int> n = tree_->crossings(p, dir))
      return *n % 2 ? Containment::kInside : Containment::kOutside;
  return Containment::kUndecided;
}

bool BoundaryTriangles::noTriangleWithin(const Vec3& p, double distance) const {
  if (uncut_) return !uncut_->anyWithin(p, distance);
  return !tree_ || !tree_->anyWithin(p, distance);
}

bool BoundaryTriangles::fartherThan(const Vec3& p, double distance) const {
  return tree_ && !tree_->anyWithin(p, distance + margin_);
}

}  // namespace hexlayer
