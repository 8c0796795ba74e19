// Butt joints (geometry/butt_joints.hpp): a wall ending part way up the walls of its own sheet that run on flush with
// its outside is found, and its outside face split off their ends, so that it becomes a wall standing on them; a wall
// as high as its neighbours (a mitred corner) is left a bend. In millimetres, and scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>
#include <BRepTools.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <string>

#include "geometry/butt_joints.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_sides.hpp"
#include "test_boxes.hpp"

using namespace hexlayer;

namespace {

// The outward normal of face f at the middle of its parameter box.
Vec3 normalOf(const CadSolid& cad, int f) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(TopoDS::Face(cad.faces(f + 1)), u0, u1, v0, v1);
  return outwardNormal(cad.faces(f + 1), 0.5 * (u0 + u1), 0.5 * (v0 + v1));
}

}  // namespace

// The end wall 20 high between side walls 40 high: one joint, its wall the end wall's inside (facing +x), its outside
// the face over the end wall and the side walls' and floor's ends, three bases (the two side walls' insides and the
// floor's top). Split, that face leaves the end wall's outside a face of its own: two sheets, the end wall's the
// smaller. Before the split the box is one sheet (bent at every sharp inside edge).
TEST(ButtJoints, AnEndWallLowerThanTheSideWallsButtsOnThemAndOnTheFloor) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    CadSolid cad = prepareSolid(test_boxes::boxes(test_boxes::boxWithEndWall(20), s));
    WallSides sides = classifyWallSides(cad);
    ASSERT_EQ(findSheets(cad, sides).size(), 1u);
    const std::vector<ButtJoint> joints = findButtJoints(cad, sides);
    ASSERT_EQ(joints.size(), 1u);
    EXPECT_GT(normalOf(cad, joints[0].wall).x(), 0.99);
    EXPECT_LT(normalOf(cad, joints[0].outside).x(), -0.99);
    EXPECT_EQ(joints[0].bases.size(), 3u);
    ASSERT_EQ(splitButtJoints(cad, sides), 1u);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 2u);
    EXPECT_NEAR(sheets[1].area, 2 * 56 * 18 * s * s * cad.unit * cad.unit, 0.01 * sheets[1].area);
  }
}

// A box whose end wall is as high as its side walls has no butt joint (its corners are mitred bends, as before), nor
// has an L-bracket whose flange is as wide as its plate; a flange narrower than the plate it stands on at its end
// has one, on the plate's top alone.
TEST(ButtJoints, OnlyAWallEndingBeforeTheWallItMeetsButtsOnIt) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid full = prepareSolid(test_boxes::boxes(test_boxes::boxWithEndWall(40), s));
    EXPECT_TRUE(findButtJoints(full, classifyWallSides(full)).empty());
    const CadSolid wide = prepareSolid(test_boxes::boxes({{0, 0, 0, 80, 60, 2}, {0, 0, 0, 2, 60, 40}}, s));
    EXPECT_TRUE(findButtJoints(wide, classifyWallSides(wide)).empty());
    const CadSolid narrow = prepareSolid(test_boxes::boxes(test_boxes::narrowFlangeBracket(), s));
    const std::vector<ButtJoint> joints = findButtJoints(narrow, classifyWallSides(narrow));
    ASSERT_EQ(joints.size(), 1u);
    EXPECT_EQ(joints[0].bases.size(), 1u);
  }
}
