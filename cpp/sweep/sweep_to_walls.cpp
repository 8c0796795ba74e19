#include "sweep/sweep_to_walls.hpp"

#include <deque>
#include <optional>

#include "core/threads.hpp"

namespace hexlayer {
namespace {

constexpr double kMinReach = 0.25, kMaxReach = 4;  // a wall hit counts between these multiples of r

}  // namespace

SweepLine castSweepLine(WallRays& rays, const Vec3& q, const Vec3& n, double r) {
  SweepLine line = radiusSweepLine(q, n, r);
  auto keep = [&](const std::optional<FacePoint>& hit, Vec3& end, int& face) {
    if (hit && (hit->point - q).norm() > kMinReach * r) end = hit->point, face = hit->face;
  };
  keep(rays.cast(Side::Top, q, n, kMaxReach * r, true), line.top, line.topFace);
  keep(rays.cast(Side::Bottom, q, -n, kMaxReach * r, true), line.bottom, line.bottomFace);
  return line;
}

SweepResult sweepToWalls(const QuadMesh& quads, const ChordalLocator& locator, const CadSolid& cad,
                         const WallSides& sides, int layers) {
  std::deque<WallRays> rays;
  for (int t = 0; t < threadCount(); ++t) rays.emplace_back(cad, sides);
  return sweepQuads(quads, locator, layers, [&](const Vec3& q, const Vec3& n, double r) {
    return castSweepLine(rays[threadIndex()], q, n, r);
  });
}

}  // namespace hexlayer
