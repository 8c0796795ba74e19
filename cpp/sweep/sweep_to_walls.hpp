// The sweep (§7) with its lines ending on the CAD walls: π_b, π_t of §3 for every quad node, instead of the
// radius function's q ∓ r n̄ (sweep.hpp), so that the hexes' wall faces lie on the part's walls.
#pragma once
#include "chordal/chordal_locator.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_rays.hpp"
#include "geometry/wall_sides.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "sweep/sweep.hpp"

namespace hexlayer {

// [in,out] rays: the caster (it keeps state: one per thread); [in] q, n, r: the chordal point, its unit
// direction and radius. Each end is where the ray along ±n first meets the top (bottom) wall, or a rim face
// the line leaves through first (an oblique or rounded rim overhanging the wall), if that lies between
// kMinReach and kMaxReach radii away; else the radius function's end q ± r n (face -1).
SweepLine castSweepLine(WallRays& rays, const Vec3& q, const Vec3& n, double r);

// castSweepLine, but a line that ends on both walls where they are parallel within 5° is cast again along their own
// direction (the bisector of their outward normals there; blended into n as they open to 10°), if that turns it by
// 1e-4 rad to 30° and it still ends on both walls: top and bottom bubbles that do not face each other (a part
// turned in space, walls split differently) tilt the chordal normal, and the hexes would shear.
SweepLine aimSweepLine(WallRays& rays, const Vec3& q, const Vec3& n, double r);

// [in] quads, locator: the quad mesh and the chordal surface it lies on; [in] cad, sides; [in] layers.
// sweepQuads with every line aimed by aimSweepLine, then untangled with castSweepLine, in parallel (a ray caster
// per thread).
SweepResult sweepToWalls(const QuadMesh& quads, const ChordalLocator& locator, const CadSolid& cad,
                         const WallSides& sides, int layers);

}  // namespace hexlayer
