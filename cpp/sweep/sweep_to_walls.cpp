#include "sweep/sweep_to_walls.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "core/threads.hpp"

namespace hexlayer {
namespace {

constexpr double kMinReach = 0.25, kMaxReach = 4;  // a wall hit counts between these multiples of r
// Walls whose normals at the line's ends are within the first angle of parallel give the line their own direction
// (the bisector of their normals), those beyond the second keep the chordal normal, with a blend between.
const double kParallelWalls = std::cos(5 * M_PI / 180), kAskewWalls = std::cos(10 * M_PI / 180);
const double kMinTurn = std::cos(1e-4), kMaxTurn = std::cos(30 * M_PI / 180);  // of the line, to cast it again

// The line through q along n, its ends where it meets the walls (or rim faces) within reach, else q -+ r n;
// [out] topNormal, bottomNormal: the outward normals of the faces met (zero where none is).
SweepLine castAlong(WallRays& rays, const Vec3& q, const Vec3& n, double r, Vec3& topNormal, Vec3& bottomNormal) {
  SweepLine line = radiusSweepLine(q, n, r);
  topNormal = bottomNormal = Vec3::Zero();
  auto keep = [&](const std::optional<FacePoint>& hit, const Vec3& normal, Vec3& end, int& face, Vec3& endNormal) {
    if (hit && (hit->point - q).norm() > kMinReach * r) end = hit->point, face = hit->face, endNormal = normal;
  };
  Vec3 normal;
  const std::optional<FacePoint> top = rays.cast(Side::Top, q, n, kMaxReach * r, true, 0, &normal);
  keep(top, normal, line.top, line.topFace, topNormal);
  const std::optional<FacePoint> bottom = rays.cast(Side::Bottom, q, -n, kMaxReach * r, true, 0, &normal);
  keep(bottom, normal, line.bottom, line.bottomFace, bottomNormal);
  return line;
}

bool onWalls(const WallRays& rays, const SweepLine& line) {
  return line.topFace >= 0 && line.bottomFace >= 0 && rays.sideOf(line.topFace) == Side::Top &&
         rays.sideOf(line.bottomFace) == Side::Bottom;
}

// The direction the walls give a line ending on both (the bisector of their outward normals, §3's π_t, π_b as a
// medial surface's normal would meet them), blended into n as the walls turn from parallel to askew; n if the
// line does not end on both walls.
Vec3 wallsDirection(const WallRays& rays, const SweepLine& line, const Vec3& n, const Vec3& topNormal,
                    const Vec3& bottomNormal) {
  if (!onWalls(rays, line)) return n;
  const double parallel = -topNormal.dot(bottomNormal);
  const double w = std::clamp((parallel - kAskewWalls) / (kParallelWalls - kAskewWalls), 0.0, 1.0);
  const Vec3 d = w * (topNormal - bottomNormal).normalized() + (1 - w) * n;
  return d.norm() > 0 ? Vec3(d.normalized()) : n;
}

}  // namespace

SweepLine castSweepLine(WallRays& rays, const Vec3& q, const Vec3& n, double r) {
  Vec3 topNormal, bottomNormal;
  return castAlong(rays, q, n, r, topNormal, bottomNormal);
}

SweepLine aimSweepLine(WallRays& rays, const Vec3& q, const Vec3& n, double r) {
  Vec3 topNormal, bottomNormal;
  const SweepLine line = castAlong(rays, q, n, r, topNormal, bottomNormal);
  // A chordal normal askew to parallel walls (top and bottom bubbles that do not face each other tilt the tets'
  // top-bottom edges) shears the hexes: such a line is cast again along the walls' own direction.
  const Vec3 d = wallsDirection(rays, line, n, topNormal, bottomNormal);
  const double turn = d.dot(n);
  if (turn > kMinTurn || turn < kMaxTurn) return line;
  const SweepLine again = castAlong(rays, q, d, r, topNormal, bottomNormal);
  return onWalls(rays, again) ? again : line;
}

SweepResult sweepToWalls(const QuadMesh& quads, const ChordalLocator& locator, const CadSolid& cad,
                         const WallSides& sides, int layers) {
  std::deque<WallRays> rays;
  for (int t = 0; t < threadCount(); ++t) rays.emplace_back(cad, sides);
  return sweepQuads(
      quads, locator, layers,
      [&](const Vec3& q, const Vec3& n, double r) { return castSweepLine(rays[threadIndex()], q, n, r); },
      [&](const Vec3& q, const Vec3& n, double r) { return aimSweepLine(rays[threadIndex()], q, n, r); });
}

}  // namespace hexlayer
