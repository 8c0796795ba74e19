#include "geometry/wall_rays.hpp"

#include <BRep_Tool.hxx>
#include <GeomAPI_IntCS.hxx>
#include <Geom_Line.hxx>
#include <gp_Lin.hxx>

#include <limits>

namespace hexlayer {

WallRays::WallRays(const CadSolid& cad, const WallSides& sides)
    : cad_(cad), sides_(sides), rays_(cad, 1e-7 * cad.diagonal) {}

namespace {

// A ray that runs along a face is cast again from this share of its length inside that face.
constexpr double kNudge = 1e-4;
// A hit where the ray's direction is within this cosine of the face's tangent plane is along the face.
constexpr double kGrazing = 1e-6;

gp_Lin lineOf(const Vec3& from, const Vec3& dir) {
  return gp_Lin(gp_Pnt(from.x(), from.y(), from.z()), gp_Dir(dir.x(), dir.y(), dir.z()));
}

// The outward unit normal of the hit's face at the hit (zero where the surface has none, a pole).
Vec3 hitNormal(const RayCaster& rays, const RayHit& h) { return outwardNormal(rays.face(h.face), h.u, h.v); }

// The hit of a ray along dir crosses its face (in or out), it does not run along it: OpenCASCADE reports a line
// lying in a face as tangent points or as crossings at the start of the range cast, by the surface's kind.
bool crosses(const RayCaster& rays, const RayHit& h, const Vec3& dir) {
  return h.transition != IntCurveSurface_Tangent && std::abs(hitNormal(rays, h).dot(dir)) > kGrazing;
}

// The nearest hit of the ray that crosses a face (none: nullopt) and, if the ray runs along a face before it,
// that face's inward normal there.
struct Crossing {
  std::optional<RayHit> hit;
  std::optional<Vec3> alongInward;
};

Crossing nearestCrossing(RayCaster& rays, const Vec3& from, const Vec3& dir, double minDistance, double maxDistance) {
  const std::optional<RayHit> first = rays.nearest(from, dir, minDistance, maxDistance);
  if (!first) return {};
  if (crosses(rays, *first, dir)) return {first, std::nullopt};
  Crossing c{std::nullopt, -hitNormal(rays, *first)};
  for (const RayHit& h : rays.all(from, dir, minDistance, maxDistance))  // rare: every hit, for the nearest crossing
    if (crosses(rays, h, dir)) return c.hit = h, c;
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
                                        double minDistance, Vec3* normal) {
  Crossing c = nearestCrossing(rays_, from, dir, minDistance, maxDistance);
  // Along a face (a sweep line in a rim face), the faces it crosses at that face's edges may count it as outside
  // them: cast from just inside instead, and take the point where the line itself meets the face hit.
  const bool along = c.alongInward.has_value();
  if (along) c = nearestCrossing(rays_, from + kNudge * maxDistance * *c.alongInward, dir, minDistance, maxDistance);
  if (!c.hit) return std::nullopt;
  const int face = c.hit->face;
  if (sides_.faces[face].side != side && !(orRim && sides_.faces[face].side == Side::Lateral)) return std::nullopt;
  if (normal) *normal = hitNormal(rays_, *c.hit);
  return FacePoint{along ? onLine(rays_.face(face), from, dir, c.hit->point) : c.hit->point, face};
}

std::optional<FacePoint> WallRays::nearestOnLine(Side side, const Vec3& p, const Vec3& dir, double reach) {
  std::optional<FacePoint> best;
  double bestAlong = reach;
  for (const RayHit& h : rays_.all(p, dir, -reach, reach)) {
    if (!crosses(rays_, h, dir) || sides_.faces[h.face].side != side || std::abs(h.w) > bestAlong) continue;
    bestAlong = std::abs(h.w);
    best = FacePoint{h.point, h.face};
  }
  return best;
}

}  // namespace hexlayer
