// The sweep line ending on the CAD walls (sweep/sweep_to_walls.hpp; π_t, π_b of §3).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_rays.hpp"
#include "geometry/wall_sides.hpp"
#include "sweep/sweep.hpp"
#include "sweep/sweep_to_walls.hpp"

using namespace hexlayer;

// castSweepLine (sweep_to_walls.hpp) on a 40 x 30 x 2 box from its mid-plane: with a radius of 1 the line ends
// on the walls (Face6 at z = 2, Face5 at z = 0); with a radius of 0.2 the walls (1 away) lie beyond 4 radii, so
// the line keeps the radius function's ends (q -+ 0.2 n, no face); tilted out through the rim near x = 40, the
// top end is on the rim face (Face2, x = 40) where the line leaves.
TEST(SweepToWalls, SweepLineEndsOnTheWallsWithinReach) {
  const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 30, 2).Solid());
  const WallSides sides = classifyWallSides(cad);
  WallRays rays(cad, sides);
  const Vec3 q(20, 15, 1);
  const SweepLine wide = castSweepLine(rays, q, Vec3::UnitZ(), 1);
  EXPECT_NEAR((wide.top - Vec3(20, 15, 2)).norm(), 0, 1e-9);
  EXPECT_NEAR((wide.bottom - Vec3(20, 15, 0)).norm(), 0, 1e-9);
  EXPECT_EQ(wide.topFace, 5);
  EXPECT_EQ(wide.bottomFace, 4);
  const SweepLine narrow = castSweepLine(rays, q, Vec3::UnitZ(), 0.2);
  EXPECT_NEAR((narrow.top - Vec3(20, 15, 1.2)).norm(), 0, 1e-12);
  EXPECT_NEAR((narrow.bottom - Vec3(20, 15, 0.8)).norm(), 0, 1e-12);
  EXPECT_EQ(narrow.topFace, -1);
  EXPECT_EQ(narrow.bottomFace, -1);
  const SweepLine out = castSweepLine(rays, Vec3(39.8, 15, 1), Vec3(1, 0, 1).normalized(), 1);
  EXPECT_NEAR((out.top - Vec3(40, 15, 1.2)).norm(), 0, 1e-9);
  EXPECT_EQ(out.topFace, 1) << "Face2, x = 40";
}
