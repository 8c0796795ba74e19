// The sweep line ending on the CAD walls (sweep/sweep_to_walls.hpp; π_t, π_b of §3).
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <string>

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

// aimSweepLine: a chordal normal askew to parallel walls (bubbles on the top and bottom that do not face each other)
// would shear the hexes: the line takes the walls' direction, up to a turn of 30°; beyond it, or where the walls are
// not parallel (a wedge opening at 12°), the chordal normal stays. Scaled by 1, 1e-3 and 1e3.
TEST(SweepToWalls, SweepLineTakesTheDirectionOfParallelWalls) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40 * s, 30 * s, 2 * s).Solid());
    const WallSides sides = classifyWallSides(cad);
    WallRays rays(cad, sides);
    const Vec3 q = Vec3(20, 15, 1) * s;
    for (double degrees : {3.0, 18.0, 27.0}) {
      const double a = degrees * M_PI / 180;
      const SweepLine line = aimSweepLine(rays, q, Vec3(std::sin(a), 0.3 * std::sin(a), std::cos(a)).normalized(), s);
      EXPECT_NEAR((line.top - Vec3(20, 15, 2) * s).norm(), 0, 1e-9 * s) << degrees;
      EXPECT_NEAR((line.bottom - Vec3(20, 15, 0) * s).norm(), 0, 1e-9 * s) << degrees;
    }
    const double a = 35 * M_PI / 180;
    const SweepLine askew = aimSweepLine(rays, q, Vec3(std::sin(a), 0, std::cos(a)), s);
    EXPECT_NEAR((askew.top - Vec3(20 + std::tan(a), 15, 2) * s).norm(), 0, 1e-9 * s) << "turned too far: kept";
  }
  // A wedge: bottom z = 0, top rising at 12° from the line x = 0 (thickness 2 + x tan 12°), 30 x 60.
  const double rise = std::tan(12 * M_PI / 180);
  BRepBuilderAPI_MakePolygon outline(gp_Pnt(0, 0, 0), gp_Pnt(30, 0, 0), gp_Pnt(30, 0, 2 + 30 * rise), gp_Pnt(0, 0, 2),
                                     true);
  const CadSolid cad = prepareSolid(
      TopoDS::Solid(BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(outline.Wire()).Face(), gp_Vec(0, 60, 0)).Shape()));
  const WallSides sides = classifyWallSides(cad);
  WallRays rays(cad, sides);
  const SweepLine line = aimSweepLine(rays, Vec3(15, 30, 2), Vec3::UnitZ(), 2);
  EXPECT_NEAR((line.bottom - Vec3(15, 30, 0)).norm(), 0, 1e-9) << "walls 12° apart: the chordal normal kept";
  EXPECT_NEAR((line.top - Vec3(15, 30, 2 + 15 * rise)).norm(), 0, 1e-9);
}
