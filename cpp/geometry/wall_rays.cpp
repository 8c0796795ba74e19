#include "geometry/wall_rays.hpp"

#include <BRep_Tool.hxx>
#include <GeomAPI_IntCS.hxx>
#include <Geom_Line.hxx>
#include <gp_Lin.hxx>

#include <limits>

namespace hexlayer {

WallRays::WallRays(const CadSolid& cad, const WallSides& sides) : cad_(cad), sides_(sides) {
  rays_.Load(cad.solid, 1e-7 * cad.diagonal);
}

namespace {

// A ray that runs along a face is cast again from this share of its length inside that face.
constexpr double kNudge = 1e-4;
// A hit where the ray's direction is within this cosine of the face's tangent plane is along the face.
constexpr double kGrazing = 1e-6;

gp_Lin lineOf(const Vec3& from, const Vec3& dir) {
  return gp_Lin(gp_Pnt(from.x(), from.y(), from.z()), gp_Dir(dir.x(), dir.y(), dir.z()));
}

// The outward unit normal of hit i's face at the hit (zero where the surface has none, a pole).
Vec3 hitNormal(const IntCurvesFace_ShapeIntersector& rays, int i) {
  return outwardNormal(rays.Face(i), rays.UParameter(i), rays.VParameter(i));
}

// Hit i of a ray along dir crosses its face (in or out), it does not run along it: OpenCASCADE reports a line
// lying in a face as tangent points or as crossings at the start of the range cast, by the surface's kind.
bool crosses(const IntCurvesFace_ShapeIntersector& rays, int i, const Vec3& dir) {
  return rays.Transition(i) != IntCurveSurface_Tangent && std::abs(hitNormal(rays, i).dot(dir)) > kGrazing;
}

// The nearest hit of the ray that crosses a face (0: none) and, if the ray runs along a face before it, that
// face's inward normal there.
struct Crossing {
  int hit = 0;
  std::optional<Vec3> alongInward;
};

Crossing nearestCrossing(IntCurvesFace_ShapeIntersector& rays, const Vec3& from, const Vec3& dir, double minDistance,
                         double maxDistance) {
  rays.PerformNearest(lineOf(from, dir), minDistance, maxDistance);
  if (!rays.IsDone() || rays.NbPnt() == 0) return {};
  if (crosses(rays, 1, dir)) return {1, std::nullopt};
  const Vec3 inward = -hitNormal(rays, 1);
  rays.Perform(lineOf(from, dir), minDistance, maxDistance);  // rare: every hit, for the nearest crossing
  Crossing c{0, inward};
  for (int i = 1; i <= rays.NbPnt(); ++i)
    if (crosses(rays, i, dir) && (c.hit == 0 || rays.WParameter(i) < rays.WParameter(c.hit))) c.hit = i;
  return c;
}

// Where the line from `from` along dir meets the surface of `face` nearest to `near` (a hit of the line moved
// aside by kNudge), else `near`: the hit on the line itself.
Vec3 onLine(const TopoDS_Face& face, const Vec3& from, const Vec3& dir, const Vec3& near) {
  GeomAPI_IntCS meet(new Geom_Line(lineOf(from, dir)), BRep_Tool::Surface(face));
  Vec3 best = near;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 1; meet.IsDone() && i <= meet.NbPoints(); ++i) {
    const gp_Pnt& q = meet.Point(i);
    const Vec3 point(q.X(), q.Y(), q.Z());
    if (const double d = (point - near).norm(); d < nearest) nearest = d, best = point;
  }
  return best;
}

}  // namespace

std::optional<FacePoint> WallRays::cast(Side side, const Vec3& from, const Vec3& dir, double maxDistance, bool orRim,
                                        double minDistance) {
  Crossing c = nearestCrossing(rays_, from, dir, minDistance, maxDistance);
  // Along a face (a sweep line in a rim face), the faces it crosses at that face's edges may count it as outside
  // them: cast from just inside instead, and take the point where the line itself meets the face hit.
  const bool along = c.alongInward.has_value();
  if (along) c = nearestCrossing(rays_, from + kNudge * maxDistance * *c.alongInward, dir, minDistance, maxDistance);
  if (c.hit == 0) return std::nullopt;
  const int face = cad_.faces.FindIndex(rays_.Face(c.hit)) - 1;
  if (face < 0 || (sides_.faces[face].side != side && !(orRim && sides_.faces[face].side == Side::Lateral)))
    return std::nullopt;
  const gp_Pnt& p = rays_.Pnt(c.hit);
  const Vec3 hit(p.X(), p.Y(), p.Z());
  return FacePoint{along ? onLine(rays_.Face(c.hit), from, dir, hit) : hit, face};
}

std::optional<FacePoint> WallRays::nearestOnLine(Side side, const Vec3& p, const Vec3& dir, double reach) {
  rays_.Perform(lineOf(p, dir), -reach, reach);
  if (!rays_.IsDone()) return std::nullopt;
  std::optional<FacePoint> best;
  double bestAlong = reach;
  for (int i = 1; i <= rays_.NbPnt(); ++i) {
    const int face = cad_.faces.FindIndex(rays_.Face(i)) - 1;
    if (face < 0 || !crosses(rays_, i, dir) || sides_.faces[face].side != side ||
        std::abs(rays_.WParameter(i)) > bestAlong)
      continue;
    bestAlong = std::abs(rays_.WParameter(i));
    const gp_Pnt& q = rays_.Pnt(i);
    best = FacePoint{Vec3(q.X(), q.Y(), q.Z()), face};
  }
  return best;
}

}  // namespace hexlayer
