// Surface groups (pipeline/surface_groups.hpp): the boundary of a meshed 40 x 30 x 2 box grouped per CAD face,
// checked against the faces' planes from the coordinates (MakeBox numbers its faces like FreeCAD: Face1 x = 0,
// Face2 x = 40, Face3 y = 0, Face4 y = 30, Face5 z = 0, Face6 z = 2); and appendSurfaceGroups' renumbering.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "pipeline/pipeline.hpp"
#include "pipeline/surface_groups.hpp"
#include "quality/quality.hpp"

using namespace hexlayer;

namespace {

// Whether p lies on box face f (0-based, MakeBox's order) of the box [0, size].
bool onFace(const Vec3& p, int f, const Vec3& size) {
  const int axis = f / 2;
  return std::abs(p[axis] - (f % 2 ? size[axis] : 0.0)) < 1e-9;
}

}  // namespace

// Every group holds exactly the nodes on its face's plane, and the hex faces whose four corners are on it; every
// boundary hex face is in one group.
TEST(SurfaceGroups, BoxFacesHoldTheNodesAndHexFacesOnTheirPlanes) {
  const Vec3 size(40, 30, 2);
  MeshOptions o;
  o.layers = 2, o.size = 2;
  const MeshResult r = meshSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), size.x(), size.y(), size.z()).Solid(), o);
  ASSERT_EQ(r.surfaceGroups.size(), 6u);
  std::size_t faces = 0;
  for (int f = 0; f < 6; ++f) {
    const SurfaceGroup& g = r.surfaceGroups[f];
    EXPECT_EQ(g.name, "Face" + std::to_string(f + 1));
    std::vector<int> on;
    for (std::size_t v = 0; v < r.mesh.nodes.size(); ++v)
      if (onFace(r.mesh.nodes[v], f, size)) on.push_back(static_cast<int>(v));
    EXPECT_EQ(g.nodes, on) << g.name;
    for (const HexFace& h : g.hexFaces)
      for (int k : kHexFaces[h.localFace]) EXPECT_TRUE(onFace(r.mesh.nodes[r.mesh.hexes[h.hex][k]], f, size));
    faces += g.hexFaces.size();
  }
  EXPECT_EQ(faces, boundaryFaces(r.mesh).size());
  // The grid of 2 x 2 quads in 2 layers: 20 x 15 quads on the walls, 15 x 2 and 20 x 2 on the sides.
  EXPECT_EQ(r.surfaceGroups[4].hexFaces.size(), 300u);
  EXPECT_EQ(r.surfaceGroups[0].hexFaces.size(), 30u);
  EXPECT_EQ(r.surfaceGroups[2].hexFaces.size(), 40u);
}

// A second solid's groups come after the first's, their node and hex ids shifted, named on after them.
TEST(SurfaceGroups, AppendShiftsIdsAndNumbersOn) {
  std::vector<SurfaceGroup> all{{"Face1", {0, 1}, {{0, 2}}}};
  const std::vector<SurfaceGroup> part{{"Face1", {0, 3}, {{1, 4}}}, {"Face2", {2}, {}}};
  appendSurfaceGroups(all, part, 10, 5);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[1].name, "Face2");
  EXPECT_EQ(all[2].name, "Face3");
  EXPECT_EQ(all[1].nodes, (std::vector<int>{10, 13}));
  EXPECT_EQ(all[1].hexFaces, (std::vector<HexFace>{{6, 4}}));
  EXPECT_EQ(all[2].nodes, (std::vector<int>{12}));
}
