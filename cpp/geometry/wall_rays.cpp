#include "geometry/wall_rays.hpp"

#include <gp_Lin.hxx>

namespace hexlayer {

WallRays::WallRays(const CadSolid& cad, const WallSides& sides) : cad_(cad), sides_(sides) {
  rays_.Load(cad.solid, 1e-7 * cad.diagonal);
}

std::optional<FacePoint> WallRays::cast(Side side, const Vec3& from, const Vec3& dir, double maxDistance, bool orRim,
                                        double minDistance) {
  rays_.PerformNearest(gp_Lin(gp_Pnt(from.x(), from.y(), from.z()), gp_Dir(dir.x(), dir.y(), dir.z())), minDistance,
                       maxDistance);
  if (!rays_.IsDone() || rays_.NbPnt() == 0) return std::nullopt;
  const int face = cad_.faces.FindIndex(rays_.Face(1)) - 1;
  if (face < 0 || (sides_.faces[face].side != side && !(orRim && sides_.faces[face].side == Side::Lateral)))
    return std::nullopt;
  const gp_Pnt& p = rays_.Pnt(1);
  return FacePoint{Vec3(p.X(), p.Y(), p.Z()), face};
}

std::optional<FacePoint> WallRays::nearestOnLine(Side side, const Vec3& p, const Vec3& dir, double reach) {
  rays_.Perform(gp_Lin(gp_Pnt(p.x(), p.y(), p.z()), gp_Dir(dir.x(), dir.y(), dir.z())), -reach, reach);
  if (!rays_.IsDone()) return std::nullopt;
  std::optional<FacePoint> best;
  double bestAlong = reach;
  for (int i = 1; i <= rays_.NbPnt(); ++i) {
    const int face = cad_.faces.FindIndex(rays_.Face(i)) - 1;
    if (face < 0 || sides_.faces[face].side != side || std::abs(rays_.WParameter(i)) > bestAlong) continue;
    bestAlong = std::abs(rays_.WParameter(i));
    const gp_Pnt& q = rays_.Pnt(i);
    best = FacePoint{Vec3(q.X(), q.Y(), q.Z()), face};
  }
  return best;
}

}  // namespace hexlayer
