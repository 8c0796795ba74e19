#include "geometry/wall_rays.hpp"

#include <gp_Lin.hxx>

namespace hexlayer {

WallRays::WallRays(const CadSolid& cad, const WallSides& sides) : cad_(cad), sides_(sides) {
  rays_.Load(cad.solid, 1e-7 * cad.diagonal);
}

std::optional<FacePoint> WallRays::cast(Side side, const Vec3& from, const Vec3& dir, double maxDistance) {
  rays_.PerformNearest(gp_Lin(gp_Pnt(from.x(), from.y(), from.z()), gp_Dir(dir.x(), dir.y(), dir.z())), 0, maxDistance);
  if (!rays_.IsDone() || rays_.NbPnt() == 0) return std::nullopt;
  const int face = cad_.faces.FindIndex(rays_.Face(1)) - 1;
  if (face < 0 || sides_.faces[face].side != side) return std::nullopt;
  const gp_Pnt& p = rays_.Pnt(1);
  return FacePoint{Vec3(p.X(), p.Y(), p.Z()), face};
}

}  // namespace hexlayer
