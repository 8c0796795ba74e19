// The two-way mapping π_t, π_b of the paper (§3): where a line through a point of the chordal
// surface meets the top (ω_t) or the bottom (ω_b) wall of the CAD solid.
#pragma once
#include <optional>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/ray_caster.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

class WallRays {
 public:
  WallRays(const CadSolid& cad, const WallSides& sides);
  // Where the ray from `from` along the unit vector `dir` first leaves the solid, if that is on
  // the `side` wall (or, with orRim, on a lateral face) and closer than maxDistance (a ray that leaves
  // through a lateral face, or a gap between faces, reaches no wall), with the face it hit; hits closer than
  // minDistance are passed by (a ray along a face it starts on). Not thread-safe (OpenCASCADE's intersector
  // keeps state).
  // [out] normal: if given, the hit face's outward unit normal at the hit.
  std::optional<FacePoint> cast(Side side, const Vec3& from, const Vec3& dir, double maxDistance, bool orRim = false,
                                double minDistance = 0, Vec3* normal = nullptr);

  // The side of face f (0-based), as classified.
  Side sideOf(int f) const { return sides_.faces[f].side; }

  // Where the line through p along the unit vector dir meets a face of the `side` wall nearest to p, on
  // either side of p and at most `reach` away; nullopt if it meets none there. Not thread-safe either.
  std::optional<FacePoint> nearestOnLine(Side side, const Vec3& p, const Vec3& dir, double reach);

 private:
  const CadSolid& cad_;
  const WallSides& sides_;
  RayCaster rays_;
};

}  // namespace hexlayer
