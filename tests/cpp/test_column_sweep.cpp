// Columns (column_piece.hpp, column_foot.hpp, column_sweep.hpp): a cone and a square post cut off at their feet are
// columns, swept from their feet's quads to their tops; a pin under a wider head is none; a pin below a plate takes
// the foot of the pin above, a wider one does not; a boss with a blind bore and a pin with a shoulder (ledges) are
// swept in tiers, each foot quad's hexes up to the cap above it. At scales 1e-3, 1 and 1e3.
#include <gtest/gtest.h>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <map>

#include "core/polygon.hpp"
#include "geometry/column_piece.hpp"
#include "geometry/wall_projector.hpp"
#include "quadmesh/column_foot.hpp"
#include "quality/quality.hpp"
#include "sweep/column_sweep.hpp"

namespace hexlayer {
namespace {

// The solid prepared, its face lowest in z (a plane z = 0) marked as a cut (its foot).
CadSolid withFootAtZ0(const TopoDS_Shape& shape) {
  TopExp_Explorer solid(shape, TopAbs_SOLID);
  CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()));
  cad.cutInput.assign(cad.faces.Extent(), 0);
  for (int f = 0; f < cad.faces.Extent(); ++f) {
    const BRepAdaptor_Surface s(TopoDS::Face(cad.faces(f + 1)));
    if (s.GetType() == GeomAbs_Plane && std::abs(s.Plane().Location().Z()) < 1e-9 &&
        std::abs(s.Plane().Axis().Direction().Z()) > 0.999)
      cad.cutInput[f] = 1;
  }
  return cad;
}

double meshVolume(const HexMesh& mesh) {
  double v = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) v += hexVolume(hexCorners(mesh, h));
  return v;
}

TEST(ColumnPiece, AConeAndAPostAreColumnsAPinUnderAWiderHeadIsNone) {
  for (double s : {1e-3, 1.0, 1e3}) {
    const CadSolid cone = withFootAtZ0(BRepPrimAPI_MakeCone(2.2 * s, 1.0 * s, 10 * s).Shape());
    const std::optional<ColumnPiece> c = columnPiece(cone);
    ASSERT_TRUE(c) << s;
    EXPECT_NEAR(c->axis.z(), 1.0, 1e-12);
    EXPECT_NEAR(c->height, 10 * s, 1e-9 * s);
    EXPECT_EQ(c->sides.size(), 1u);
    EXPECT_EQ(c->caps.size(), 1u);
    const CadSolid post = withFootAtZ0(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 4 * s, 3 * s, 9 * s).Shape());
    const std::optional<ColumnPiece> p = columnPiece(post);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->sides.size(), 4u);
    EXPECT_EQ(p->caps.size(), 1u);
    const TopoDS_Shape mushroom =
        BRepAlgoAPI_Fuse(BRepPrimAPI_MakeCylinder(1.5 * s, 8 * s).Shape(),
                         BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 8 * s), gp_Dir(0, 0, 1)), 3 * s, 2 * s).Shape())
            .Shape();
    EXPECT_FALSE(columnPiece(withFootAtZ0(mushroom))) << s;
    EXPECT_FALSE(columnPiece(prepareSolid(cone.solid)));  // no cut face: no foot
  }
}

TEST(ColumnSweep, AConesHexesFillItFromItsFootToItsTop) {
  for (double s : {1e-3, 1.0, 1e3}) {
    const double r0 = 2.2 * s, r1 = 1.0 * s, h = 10 * s;
    const CadSolid cone = withFootAtZ0(BRepPrimAPI_MakeCone(r0, r1, h).Shape());
    const ColumnPiece c = *columnPiece(cone);
    const ColumnFoot foot = columnFootQuads(cone, c, 1.0 * s, nullptr);
    ASSERT_EQ(foot.loops.size(), 1u);
    EXPECT_EQ(foot.loops[0].size(), 14u);  // 2 pi 2.2 / 1 = 13.8: 14
    for (int n : foot.loops[0]) EXPECT_NEAR(std::hypot(foot.quads.nodes[n].x(), foot.quads.nodes[n].y()), r0, 1e-9 * s);
    const WallSides sides = columnSides(cone, c);
    const WallProjector walls(cone, sides);
    const HexMesh mesh = sweepColumn(cone, foot, c, walls, ColumnTiers{{c.height}, {10}});
    EXPECT_EQ(mesh.hexes.size(), foot.quads.quads.size() * 10);
    for (std::size_t k = 0; k < mesh.hexes.size(); ++k) EXPECT_GT(hexScaledJacobian(hexCorners(mesh, k)), 0.3);
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
      const Vec3& p = mesh.nodes[n];
      if (mesh.nodeLayer[n] == 10) EXPECT_NEAR(p.z(), h, 1e-9 * s);
      if (mesh.nodeLayer[n] == 0) EXPECT_NEAR(p.z(), 0, 1e-12 * s);
      if (mesh.nodeOnRim[n]) EXPECT_NEAR(std::hypot(p.x(), p.y()), r0 + (r1 - r0) * p.z() / h, 1e-6 * s);
    }
    // the frustum's volume, less the chords' segments (14 sides: about 3.3 %)
    const double frustum = M_PI * h / 3 * (r0 * r0 + r0 * r1 + r1 * r1);
    EXPECT_NEAR(meshVolume(mesh) / frustum, 1 - 0.033, 0.005) << s;
  }
}

// A pin R1.5 standing on a tube R40 (its axis along x at z = -40): its foot is the tube's surface under it, curved. It
// is a column (the foot's normals within the draft of the one at its middle); the foot's inner quad nodes lie on the
// tube, the hexes fill the pin from it to its top at z = 10.
TEST(ColumnSweep, APinsCurvedFootOnATubeIsSweptFromTheTube) {
  for (double s : {1e-3, 1.0, 1e3}) {
    const TopoDS_Shape pin = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -2 * s), gp_Dir(0, 0, 1)), 1.5 * s, 12 * s);
    const TopoDS_Shape tube =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-10 * s, 0, -40 * s), gp_Dir(1, 0, 0), gp_Dir(0, 0, -1)), 40 * s, 20 * s)
            .Shape();  // its seam underneath, away from the foot
    TopExp_Explorer solid(BRepAlgoAPI_Cut(pin, tube).Shape(), TopAbs_SOLID);
    CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()));
    cad.cutInput.assign(cad.faces.Extent(), 0);
    for (int f = 0; f < cad.faces.Extent(); ++f) {
      const BRepAdaptor_Surface on(TopoDS::Face(cad.faces(f + 1)));
      cad.cutInput[f] = on.GetType() == GeomAbs_Cylinder && on.Cylinder().Radius() > 10 * s;
    }
    const std::optional<ColumnPiece> c = columnPiece(cad);
    ASSERT_TRUE(c) << s;
    EXPECT_TRUE(c->footOffPlane);
    EXPECT_NEAR(c->axis.z(), 1.0, 1e-6);
    const ColumnFoot foot = columnFootQuads(cad, *c, 1.0 * s, nullptr);
    auto onTube = [&](const Vec3& p) { return std::hypot(p.y(), p.z() + 40 * s) - 40 * s; };
    for (const Vec3& p : foot.quads.nodes) EXPECT_NEAR(onTube(p), 0, 1e-6 * s);
    const WallProjector walls(cad, columnSides(cad, *c));
    const HexMesh mesh = sweepColumn(cad, foot, *c, walls, ColumnTiers{{c->height}, {10}});
    for (std::size_t k = 0; k < mesh.hexes.size(); ++k) EXPECT_GT(hexScaledJacobian(hexCorners(mesh, k)), 0.3);
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
      if (mesh.nodeLayer[n] == 10) EXPECT_NEAR(mesh.nodes[n].z(), 10 * s, 1e-9 * s);
    // the pin over the tube (whose top sinks 0.007 under it on average) as a prism on the outline's polygon
    const double n = static_cast<double>(foot.loops[0].size()), polygon = n / (2 * M_PI) * std::sin(2 * M_PI / n);
    EXPECT_NEAR(meshVolume(mesh) / (M_PI * 2.25 * s * s * (10 * s)), polygon, 0.005) << s;
  }
}

// A pin R1.5 upright, cut at its foot by a plane sloping 25 degrees (a pin drawn straight on a sloping wall): its axis
// is its side's (z), not the foot's normal; the foot is off the plane square to it, its inner nodes put on the slope;
// the hexes reach the top at z = 10.
// A pin (round) and a square post (two of its sides square to the slope, two leaning as far as the slope: their normals
// alone leave the axis free) upright on walls sloping 25 and 40 degrees.
TEST(ColumnSweep, APinOrPostUprightOnASlopeRunsAlongItsSides) {
  for (double s : {1e-3, 1.0, 1e3})
    for (const bool round : {true, false})
      for (const double degrees : {25.0, 40.0}) {
        const TopoDS_Shape pin =
            round ? BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -5 * s), gp_Dir(0, 0, 1)), 1.5 * s, 15 * s).Shape()
                  : BRepPrimAPI_MakeBox(gp_Pnt(-1.5 * s, -1.5 * s, -5 * s), 3 * s, 3 * s, 15 * s).Shape();
        const double a = degrees * M_PI / 180;
        const Vec3 slope(std::sin(a), 0, std::cos(a));  // the plane's normal: z turned a about y
        gp_Trsf turn;
        turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0)), a);
        const TopoDS_Shape below =
            BRepPrimAPI_MakeBox(gp_Pnt(-10 * s, -10 * s, -20 * s), 20 * s, 20 * s, 20 * s).Shape();
        TopExp_Explorer solid(BRepAlgoAPI_Cut(pin, BRepBuilderAPI_Transform(below, turn).Shape()).Shape(),
                              TopAbs_SOLID);
        CadSolid cad = prepareSolid(TopoDS::Solid(solid.Current()));
        cad.cutInput.assign(cad.faces.Extent(), 0);
        for (int f = 0; f < cad.faces.Extent(); ++f) {
          const BRepAdaptor_Surface on(TopoDS::Face(cad.faces(f + 1)));
          cad.cutInput[f] = on.GetType() == GeomAbs_Plane && std::abs(on.Plane().Axis().Direction().Z()) < 0.99 &&
                            std::abs(on.Plane().Axis().Direction().Z()) > 0.5;
        }
        const std::optional<ColumnPiece> c = columnPiece(cad);
        ASSERT_TRUE(c) << s << " " << round << " " << degrees;
        EXPECT_TRUE(c->footOffPlane);
        EXPECT_NEAR(c->axis.z(), 1.0, 1e-9);
        const ColumnFoot foot = columnFootQuads(cad, *c, 1.0 * s, nullptr);
        for (const Vec3& p : foot.quads.nodes) EXPECT_NEAR(slope.dot(p), 0, 1e-9 * s);
        const WallProjector walls(cad, columnSides(cad, *c));
        const HexMesh mesh = sweepColumn(cad, foot, *c, walls, ColumnTiers{{c->height}, {10}});
        for (std::size_t k = 0; k < mesh.hexes.size(); ++k) EXPECT_GT(hexScaledJacobian(hexCorners(mesh, k)), 0.3);
        for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
          if (mesh.nodeLayer[n] == 10) EXPECT_NEAR(mesh.nodes[n].z(), 10 * s, 1e-9 * s);
      }
}

// A boss R4.5, 20 high, with a blind bore R1.8 from its top down to 2 over its foot (a screw boss), and a pin R3
// standing on a wider one R5 10 high (a shoulder), each cut off at its foot: the bore's bottom and the shoulder are
// ledges; the foot's quads follow the step's circle (no quad across it); the hexes under the bore's bottom and the
// shoulder stop at their height, the others reach the top; the hexes fill the part (its volume but the circles'
// polygons' shortfall), none poor, the column conformal (every inner hex face in two hexes).
TEST(ColumnSweep, ABlindBoreAndAShoulderAreLedgesTheHexesUnderThemStopThere) {
  for (double s : {1e-3, 1.0, 1e3})
    for (const bool bore : {true, false}) {
      const double ledge = bore ? 2 : 10, step = bore ? 1.8 : 3;
      const TopoDS_Shape shape =
          bore ? BRepAlgoAPI_Cut(
                     BRepPrimAPI_MakeCylinder(4.5 * s, 20 * s).Shape(),
                     BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 2 * s), gp_Dir(0, 0, 1)), 1.8 * s, 30 * s).Shape())
                     .Shape()
               : BRepAlgoAPI_Fuse(
                     BRepPrimAPI_MakeCylinder(5 * s, 10 * s).Shape(),
                     BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 5 * s), gp_Dir(0, 0, 1)), 3 * s, 15 * s).Shape())
                     .Shape();
      const CadSolid cad = withFootAtZ0(shape);
      const std::optional<ColumnPiece> c = columnPiece(cad);
      ASSERT_TRUE(c) << s << " " << bore;
      ASSERT_EQ(c->ledges.size(), 1u);
      EXPECT_NEAR(c->ledges[0].height, ledge * s, 1e-9 * s);
      EXPECT_EQ(c->ledges[0].steps.size(), 1u);
      const ColumnTiers tiers = columnTiers(*c, 1.0 * s);
      EXPECT_EQ(tiers.layers, (std::vector<int>{static_cast<int>(ledge), static_cast<int>(20 - ledge)}));
      const ColumnFoot foot = columnFootQuads(cad, *c, 1.0 * s, nullptr);
      auto radius = [&](const Vec3& p) { return std::hypot(p.x(), p.y()); };
      for (const auto& q : foot.quads.quads) {  // on one side of the step's circle
        int in = 0, out = 0;
        for (int n : q)
          in += radius(foot.quads.nodes[n])<step * s*(1 - 1e-6), out += radius(foot.quads.nodes[n])> step * s *
                (1 + 1e-6);
        EXPECT_TRUE(in == 0 || out == 0) << s << " " << bore;
      }
      const WallProjector walls(cad, columnSides(cad, *c));
      const HexMesh mesh = sweepColumn(cad, foot, *c, walls, tiers);
      auto faceKey = [&](std::size_t k, int f) {
        std::array<int, 4> key;
        for (int c4 = 0; c4 < 4; ++c4) key[c4] = mesh.hexes[k][kHexFaces[f][c4]];
        std::sort(key.begin(), key.end());
        return key;
      };
      std::map<std::array<int, 4>, int> faces;
      for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {
        EXPECT_GT(hexScaledJacobian(hexCorners(mesh, k)), 0.3) << s << " " << bore;
        for (int f = 0; f < 6; ++f) ++faces[faceKey(k, f)];
      }
      for (const auto& [key, count] : faces) EXPECT_LE(count, 2);
      for (std::size_t k = 0; k < mesh.hexes.size(); ++k) {  // a column's top hex (its top face in no other hex)
        if (faces[faceKey(k, 1)] != 1) continue;
        Vec3 middle = Vec3::Zero();
        double top = -1e300;
        for (const Vec3& p : hexCorners(mesh, k)) middle += p / 8, top = std::max(top, p.z());
        const bool under = bore ? radius(middle) < step * s : radius(middle) > step * s;
        EXPECT_NEAR(top, (under ? ledge : 20) * s, 1e-6 * s) << s << " " << bore;
      }
      const double volume = bore ? M_PI * (4.5 * 4.5 * 20 - 1.8 * 1.8 * 18) : M_PI * (25 * 10 + 9 * 10);
      EXPECT_NEAR(meshVolume(mesh) / (volume * s * s * s), 1, 0.04) << s << " " << bore;
    }
}

TEST(MeanValueWeights, ReproduceLinearFunctionsInAPolygonWithAHole) {
  const std::vector<Eigen::Vector2d> outer{{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}};
  const std::vector<Eigen::Vector2d> hole{{1.5, 1.5}, {1.5, 2.5}, {2.5, 2.5}, {2.5, 1.5}};  // clockwise
  for (const Eigen::Vector2d& x : {Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(3.5, 1.0), Eigen::Vector2d(2, 4)}) {
    const std::vector<double> w = meanValueWeights({outer, hole}, x);
    ASSERT_EQ(w.size(), 9u);
    Eigen::Vector2d at = Eigen::Vector2d::Zero();
    double sum = 0;
    for (std::size_t i = 0; i < 9; ++i) at += w[i] * (i < 5 ? outer[i] : hole[i - 5]), sum += w[i];
    EXPECT_NEAR(sum, 1, 1e-12);
    EXPECT_NEAR((at - x).norm(), 0, 1e-12);
  }
}

TEST(ColumnFoot, APinBelowThePlateTakesTheFootOfThePinAboveNodeForNode) {
  for (double s : {1e-3, 1.0, 1e3}) {
    const CadSolid above = withFootAtZ0(BRepPrimAPI_MakeCylinder(1.5 * s, 8 * s).Shape());
    const std::optional<ColumnPiece> a = columnPiece(above);
    ASSERT_TRUE(a) << s;
    const ColumnFoot given = columnFootQuads(above, *a, 1.0 * s, nullptr);
    const FootprintQuads other{given.quads.nodes, given.quads.quads};
    // the pin's twin below z = 0 (its axis -z): the same nodes, its quads counter-clockwise seen from down the z axis
    const gp_Ax2 down(gp_Pnt(0, 0, 0), gp_Dir(0, 0, -1));
    const CadSolid below = withFootAtZ0(BRepPrimAPI_MakeCylinder(down, 1.5 * s, 6 * s).Shape());
    const std::optional<ColumnPiece> b = columnPiece(below);
    ASSERT_TRUE(b) << s;
    EXPECT_NEAR(b->axis.z(), -1.0, 1e-12);
    const std::optional<ColumnFoot> taken = columnFootAcross(below, *b, other, 1.0 * s);
    ASSERT_TRUE(taken) << s;
    ASSERT_EQ(taken->quads.nodes.size(), given.quads.nodes.size());
    for (std::size_t n = 0; n < given.quads.nodes.size(); ++n)
      EXPECT_LT((taken->quads.nodes[n] - given.quads.nodes[n]).norm(), 1e-12 * s) << n;
    ASSERT_EQ(taken->loops.size(), 1u);
    EXPECT_EQ(taken->loops[0].size(), given.loops[0].size());
    std::vector<Eigen::Vector2d> outline;
    for (int n : taken->loops[0]) outline.push_back(onFootPlane(*taken, *b, taken->quads.nodes[n]));
    EXPECT_GT(polygonArea(outline), 0.9 * M_PI * 1.5 * 1.5 * s * s);  // counter-clockwise up the axis
    for (const auto& q : taken->quads.quads)
      EXPECT_GT(
          polygonArea(
              {onFootPlane(*taken, *b, taken->quads.nodes[q[0]]), onFootPlane(*taken, *b, taken->quads.nodes[q[1]]),
               onFootPlane(*taken, *b, taken->quads.nodes[q[2]]), onFootPlane(*taken, *b, taken->quads.nodes[q[3]])}),
          0);
    // a wider pin below: the feet are not alike
    const CadSolid wider = withFootAtZ0(BRepPrimAPI_MakeCylinder(down, 2.5 * s, 6 * s).Shape());
    const std::optional<ColumnPiece> w = columnPiece(wider);
    ASSERT_TRUE(w);
    EXPECT_FALSE(columnFootAcross(wider, *w, other, 1.0 * s)) << s;
  }
}

}  // namespace
}  // namespace hexlayer
