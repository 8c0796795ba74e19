// Sharp edges captured (sweep/sharp_edges.hpp) on an L bent without a round: two hexes round the bend, the outside
// node of their shared column off the bend's outside edge.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include <array>
#include <cmath>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"
#include "quality/quality.hpp"
#include "sweep/sharp_edges.hpp"

using namespace hexlayer;

namespace {

// The L (floor x 0..20, z 0..2; wall x 0..2, z 0..20) extruded 0..10 along y, scaled by `scale`: its outside faces
// z = 0 and x = 0 meet in the sharp convex edge along y at x = z = 0.
CadSolid lBend(double scale) {
  BRepBuilderAPI_MakePolygon profile;
  for (const auto& [x, z] : std::array<std::array<double, 2>, 6>{{{0, 0}, {20, 0}, {20, 2}, {2, 2}, {2, 20}, {0, 20}}})
    profile.Add(gp_Pnt(x * scale, 0, z * scale));
  profile.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire());
  return prepareSolid(TopoDS::Solid(BRepPrimAPI_MakePrism(face, gp_Vec(0, 10 * scale, 0)).Shape()));
}

// The face (0-based) in the plane through p with normal n (either way).
int planeFace(const CadSolid& cad, const gp_Pnt& p, const gp_Dir& n) {
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    const BRepAdaptor_Surface s(TopoDS::Face(cad.faces(f)));
    if (s.GetType() == GeomAbs_Plane && s.Plane().Axis().Direction().IsParallel(n, 1e-9) &&
        s.Plane().Distance(p) < 1e-9)
      return f - 1;
  }
  return -1;
}

// Two hexes (one layer, y 0..1) round the bend: the floor's between the columns at x = a (outside (a, 0), inside
// (2, 2)) and x = 4, the wall's between that column and the one at z = 4. Outside nodes on the outside faces.
HexMesh bendHexes(const CadSolid& cad, const WallSides& sides, double a, double scale) {
  const int floorOut = planeFace(cad, gp_Pnt(0, 0, 0), gp::DZ()), wallOut = planeFace(cad, gp_Pnt(0, 0, 0), gp::DX());
  const int floorIn = planeFace(cad, gp_Pnt(0, 0, 2 * scale), gp::DZ());
  const int wallIn = planeFace(cad, gp_Pnt(2 * scale, 0, 0), gp::DX());
  EXPECT_TRUE(floorOut >= 0 && wallOut >= 0 && floorIn >= 0 && wallIn >= 0);
  const int outLayer = sides.faces[floorOut].side == Side::Bottom ? 0 : 1;
  HexMesh m;
  m.layers = 1;
  // columns: 0 the shared one, 1 the floor's, 2 the wall's; per column its outside and inside point (x, z)
  const std::array<std::array<std::array<double, 2>, 2>, 3> columns{
      {{{{a, 0}, {2, 2}}}, {{{4, 0}, {4, 2}}}, {{{0, 4}, {2, 4}}}}};
  const std::array<std::array<int, 2>, 3> faces{{{floorOut, floorIn}, {floorOut, floorIn}, {wallOut, wallIn}}};
  auto node = [](int column, int outside, int y) { return (column * 2 + outside) * 2 + y; };
  for (int c = 0; c < 3; ++c)
    for (int outside = 0; outside <= 1; ++outside)  // node(c, 1, y): the outside one
      for (int y = 0; y <= 1; ++y) {
        const auto& [x, z] = columns[c][1 - outside];
        m.nodes.emplace_back(x * scale, y * scale, z * scale);
        m.nodeLayer.push_back(outside ? outLayer : 1 - outLayer);
        m.nodeOnRim.push_back(0);
        m.nodeFace.push_back(faces[c][1 - outside]);
      }
  // ordered so that both hexes have a positive scaled Jacobian
  for (const int other : {1, 2}) {
    const int lo = outLayer == 0 ? 1 : 0, hi = 1 - lo;  // node(c, lo, y) in layer 0
    std::array<int, 8> h{node(0, lo, 0), node(other, lo, 0), node(other, lo, 1), node(0, lo, 1),
                         node(0, hi, 0), node(other, hi, 0), node(other, hi, 1), node(0, hi, 1)};
    m.hexes.push_back(h);
    if (hexScaledJacobian(hexCorners(m, m.hexes.size() - 1)) < 0)
      std::swap(m.hexes.back()[1], m.hexes.back()[3]), std::swap(m.hexes.back()[5], m.hexes.back()[7]);
  }
  return m;
}

double meshVolume(const HexMesh& m) {
  double v = 0;
  for (std::size_t h = 0; h < m.hexes.size(); ++h) v += hexVolume(hexCorners(m, h));
  return v;
}

}  // namespace

// The shared column's outside node 0.5 off the bend's edge on the floor: the wall's quad edge from it to (0, 4)
// crosses the edge, so it is put on the edge (both of its nodes along y), the inside node stays; the corner's
// triangle (0.5 x 4 / 2 per unit of y) is meshed and both hexes stay above 0.5. In mm and scaled by 1e-3 and 1e3.
TEST(SharpEdges, AWallNodeOffABendsOutsideEdgeGoesOntoIt) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const CadSolid cad = lBend(scale);
    const WallSides sides = classifyWallSides(cad);
    HexMesh m = bendHexes(cad, sides, 0.5, scale);
    const double before = meshVolume(m);
    const SharpEdgeStats s = captureSharpEdges(m, cad, sides);
    EXPECT_GE(s.edges, 1u);
    EXPECT_EQ(s.nodesMoved, 2u);
    for (int y = 0; y <= 1; ++y) {
      EXPECT_LT((m.nodes[2 + y] - Vec3(0, y * scale, 0)).norm(), 1e-9 * scale);  // the outside node: on the edge
      EXPECT_EQ(m.nodes[y], Vec3(2 * scale, y * scale, 2 * scale));              // the inside one: where it was
    }
    EXPECT_NEAR(meshVolume(m) - before, 1.0 * scale * scale * scale, 1e-9 * scale * scale * scale);
    for (std::size_t h = 0; h < m.hexes.size(); ++h) EXPECT_GT(hexScaledJacobian(hexCorners(m, h)), 0.5);
  }
}

// The shared column's outside node on the edge already: nothing moves.
TEST(SharpEdges, ANodeOnTheEdgeStays) {
  const CadSolid cad = lBend(1);
  const WallSides sides = classifyWallSides(cad);
  HexMesh m = bendHexes(cad, sides, 0, 1);
  const HexMesh before = m;
  EXPECT_EQ(captureSharpEdges(m, cad, sides).nodesMoved, 0u);
  EXPECT_EQ(m.nodes, before.nodes);
}

// The hexes' face y = 0 on the L's end face (a rim: lateral), the shared column's outside node there 0.5 off the end
// of the bend's outside edge: no interior quad edge of the wall crosses the edge there (its nodes are the rim's), so it
// is put on the edge's end, (0, 0, 0), and its partner at y = 1 on the edge by the quad edge crossing it; the inside
// nodes stay. In mm and scaled by 1e-3 and 1e3 (fails before: the rim's node stayed 0.5 off the corner).
TEST(SharpEdges, ARimNodeOffTheEndOfABendsOutsideEdgeGoesOntoItsEnd) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const CadSolid cad = lBend(scale);
    const WallSides sides = classifyWallSides(cad);
    ASSERT_EQ(sides.faces[planeFace(cad, gp_Pnt(0, 0, 0), gp::DY())].side, Side::Lateral);
    HexMesh m = bendHexes(cad, sides, 0.5, scale);
    for (std::size_t n = 0; n < m.nodes.size(); n += 2) m.nodeOnRim[n] = kRimSwept;  // y = 0
    const double before = meshVolume(m);
    const SharpEdgeStats s = captureSharpEdges(m, cad, sides);
    EXPECT_EQ(s.nodesMoved, 2u);
    EXPECT_LT(m.nodes[2].norm(), 1e-9 * scale);                        // the rim's: on the edge's end
    EXPECT_LT((m.nodes[3] - Vec3(0, scale, 0)).norm(), 1e-9 * scale);  // y = 1: on the edge
    EXPECT_EQ(m.nodes[0], Vec3(2 * scale, 0, 2 * scale));              // the inside ones stay
    EXPECT_EQ(m.nodes[1], Vec3(2 * scale, scale, 2 * scale));
    EXPECT_NEAR(meshVolume(m) - before, 1.0 * scale * scale * scale, 1e-9 * scale * scale * scale);
    for (std::size_t h = 0; h < m.hexes.size(); ++h) EXPECT_GT(hexScaledJacobian(hexCorners(m, h)), 0.5);
  }
}
