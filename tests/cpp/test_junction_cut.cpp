// Junction cut (geometry/junction_cut.hpp): a part with sheets standing on a base sheet cut into one piece per
// sheet, each a one-sheet part (no junction left), along feet that both pieces share and that lie on the base's
// wall. Run on a plate with a rib inside it, a rib running across it (a foot open at the plate's rims, closed
// along them), two ribs, and on copies scaled by 1e-3 and 1e3; a tab on a plate's rim face is refused, saying so.
#include <gtest/gtest.h>
#include <BRepAdaptor_Surface.hxx>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.hpp"
#include "geometry/junction_cut.hpp"
#include "test_boxes.hpp"
#include "test_parts.hpp"

using namespace hexlayer;
using hexlayer::test_boxes::Box;
using hexlayer::test_boxes::boxes;

namespace {

// Areas and volumes integrated to a relative error of 1e-10 (OpenCASCADE's default rule is 1e-3 off on B-spline faces).
double areaOf(const TopoDS_Shape& face) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props, 1e-10);
  return props.Mass();
}

// Every face of the cut solid is a face of the pieces or is cut into faces of them (their areas adding up to its),
// and only the feet (a face of two pieces each) have no origin.
void expectFaceOrigins(const CadSolid& cad, const JunctionCut& cut) {
  ASSERT_EQ(cut.faceOrigin.size(), cut.pieces.size());
  std::vector<double> area(cad.faces.Extent(), 0);
  std::size_t noOrigin = 0;
  for (std::size_t p = 0; p < cut.pieces.size(); ++p) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(cut.pieces[p], TopAbs_FACE, faces);
    ASSERT_EQ(cut.faceOrigin[p].size(), static_cast<std::size_t>(faces.Extent()));
    for (int f = 1; f <= faces.Extent(); ++f) {
      const int origin = cut.faceOrigin[p][f - 1];
      if (origin < 0)
        ++noOrigin;
      else
        area[origin] += areaOf(faces(f));
    }
  }
  EXPECT_EQ(noOrigin, 2 * cut.feet.size());
  for (int f = 0; f < cad.faces.Extent(); ++f) EXPECT_NEAR(area[f] / areaOf(cad.faces(f + 1)), 1, 1e-9) << "face " << f;
}

// To a relative error of 1e-10.
double exactVolume(const TopoDS_Shape& shape) { return volumeOf(shape, 1e-10).first; }

// The part cut at its junctions: as many pieces as sheets (the base the largest), each one sheet with no
// junction, their volumes the parts' (base box, then the ribs in order, times s^3), and feet of total area
// `footArea` (times s^2) shared by the base's piece and their sheet's piece.
void expectCut(const std::vector<Box>& parts, double footArea) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const CadSolid cad = prepareSolid(boxes(parts, s), normalizingUnit(boxes(parts, s)));
    const WallSides sides = classifyWallSides(cad);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), parts.size());
    const JunctionCut cut = cutAtJunctions(cad, sides, sheets);
    ASSERT_EQ(cut.pieces.size(), parts.size());
    const double unit3 = cad.unit * cad.unit * cad.unit, s3 = s * s * s;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      EXPECT_NEAR(exactVolume(cut.pieces[p]) / unit3 / s3 / parts[p].volume(), 1, 1e-9) << "piece " << p;
      if (sheets[p].column) continue;  // a post: no sheet, a column (column_piece.hpp)
      const CadSolid piece = prepareSolid(cut.pieces[p]);
      const WallSides pieceSides = classifyWallSides(piece);
      EXPECT_EQ(findSheets(piece, pieceSides).size(), 1u) << "piece " << p << " is one sheet";
      EXPECT_TRUE(pieceSides.ownSideFaces.empty()) << "piece " << p;
    }
    double area = 0;
    TopTools_IndexedMapOfShape baseFaces;
    TopExp::MapShapes(cut.pieces[0], TopAbs_FACE, baseFaces);
    for (const Foot& f : cut.feet) {
      area += f.area;
      TopTools_IndexedMapOfShape standing;
      TopExp::MapShapes(cut.pieces[f.sheet], TopAbs_FACE, standing);
      EXPECT_TRUE(baseFaces.Contains(f.face) && standing.Contains(f.face)) << "a foot is a face of both pieces";
    }
    EXPECT_NEAR(area / (cad.unit * cad.unit) / (s * s) / footArea, 1, 1e-9);
    expectFaceOrigins(cad, cut);
  }
}

}  // namespace

// A 60 x 40 x 2 plate with a rib 2 thick, 30 long, 10 high standing inside it: the foot a closed 2 x 30 loop.
TEST(JunctionCut, RibInsideAPlate) { expectCut({{0, 0, 0, 60, 40, 2}, {20, 5, 2, 2, 30, 10}}, 2 * 30); }

// The rib running across the plate, its ends flush with the plate's rims (one face with them): the foot's two
// edges closed along the plate's edges.
TEST(JunctionCut, RibAcrossAPlate) { expectCut({{0, 0, 0, 60, 40, 2}, {20, 0, 2, 2, 40, 10}}, 2 * 40); }

// A 4 x 4 post 9 high (no wall of its own: standingColumns) inside the plate, flush with its side (one face with
// it: the foot closed along the side), and at its corner (flush with two sides: the foot closed round the corner,
// the rims run on from its two ends to where they meet).
TEST(JunctionCut, PostsInsideAtTheSideAndAtTheCornerOfAPlate) {
  expectCut({{0, 0, 0, 60, 40, 2}, {28, 18, 2, 4, 4, 8}}, 4 * 4);
  expectCut({{0, 0, 0, 60, 40, 2}, {56, 18, 2, 4, 4, 8}}, 4 * 4);
  expectCut({{0, 0, 0, 60, 40, 2}, {56, 36, 2, 4, 4, 8}}, 4 * 4);
}

// Two ribs, one thicker (3) and higher than the other (sheets come largest first).
TEST(JunctionCut, TwoRibs) {
  expectCut({{0, 0, 0, 60, 40, 2}, {40, 5, 2, 3, 30, 15}, {15, 5, 2, 2, 30, 10}}, 3 * 30 + 2 * 30);
}

// The junction samples (Resources/samples/junctions) whose base walls are planes: a rib across the plate, inside
// it, thinner and thicker than the plate, on a plate whose faces the boolean left split, a boss with a blind bore,
// a boss over a hole through the plate: two pieces of one sheet each, holding the part's volume.
TEST(JunctionCut, JunctionSamplesOnPlanes) {
  for (const char* name : {"plate_rib", "plate_rib_inside", "plate_rib_thin", "plate_rib_thick", "plate_rib_split",
                           "plate_boss", "plate_boss_hole"}) {
    SCOPED_TRACE(name);
    const TopoDS_Solid solid =
        readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/junctions/" + name + ".step").at(0);
    const CadSolid cad = prepareSolid(solid, normalizingUnit(solid));
    const WallSides sides = classifyWallSides(cad);
    const JunctionCut cut = cutAtJunctions(cad, sides, findSheets(cad, sides));
    ASSERT_EQ(cut.pieces.size(), 2u);
    EXPECT_FALSE(cut.feet.empty());
    double volume = 0;
    for (const TopoDS_Solid& p : cut.pieces) {
      volume += exactVolume(p);
      const CadSolid piece = prepareSolid(p);
      const WallSides pieceSides = classifyWallSides(piece);
      EXPECT_EQ(findSheets(piece, pieceSides).size(), 1u);
      EXPECT_TRUE(pieceSides.ownSideFaces.empty());
    }
    EXPECT_NEAR(volume / cad.volume, 1, 1e-9);
    expectFaceOrigins(cad, cut);
  }
}

// A solid of one sheet is its own piece, each face its own origin.
TEST(JunctionCut, OneSheetIsItsOwnPiece) {
  const TopoDS_Solid solid = boxes({{0, 0, 0, 60, 40, 2}}, 1);
  const CadSolid cad = prepareSolid(solid);
  const WallSides sides = classifyWallSides(cad);
  const JunctionCut cut = cutAtJunctions(cad, sides, findSheets(cad, sides));
  ASSERT_EQ(cut.pieces.size(), 1u);
  expectFaceOrigins(cad, cut);
  for (int f = 0; f < cad.faces.Extent(); ++f) EXPECT_EQ(cut.faceOrigin[0][f], f);
}

// A junction sample scaled by s, cut at its junctions (its ribs crossing merged first).
struct SampleCut {
  CadSolid cad;
  std::vector<Sheet> sheets;
  JunctionCut cut;
};

// The solid cut at its junctions, as the pipeline cuts it (crossing ribs merged first).
SampleCut cutSolid(const TopoDS_Solid& solid) {
  SampleCut c{prepareSolid(solid, normalizingUnit(solid)), {}, {}};
  const WallSides sides = classifyWallSides(c.cad);
  c.sheets = mergeCrossingRibs(c.cad, sides, findSheets(c.cad, sides));
  c.cut = cutAtJunctions(c.cad, sides, c.sheets);
  return c;
}

SampleCut cutSample(const std::string& name, double s) {
  const TopoDS_Solid read =
      readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/junctions/" + name + ".step").at(0);
  return cutSolid(test_boxes::scaled(read, s));
}

// The first solid of a boolean's result, its faces unified, cut at its junctions (cutSolid); its feet's areas, in the
// solid's units, none of them on a face of the sheet standing on it.
struct BooleanCut {
  SampleCut c;
  std::vector<double> footAreas;
};
BooleanCut cutBoolean(const TopoDS_Shape& result) {
  ShapeUpgrade_UnifySameDomain unify(result);
  unify.Build();
  TopExp_Explorer solid(unify.Shape(), TopAbs_SOLID);
  EXPECT_TRUE(solid.More());
  BooleanCut out{cutSolid(TopoDS::Solid(solid.Current())), {}};
  for (const Foot& f : out.c.cut.feet) {
    out.footAreas.push_back(f.area / (out.c.cad.unit * out.c.cad.unit));
    const std::vector<int>& own = out.c.sheets[out.c.cut.sheetOf[f.sheet]].faces;
    EXPECT_EQ(std::count(own.begin(), own.end(), f.baseFace), 0) << "a foot on the standing sheet's own face";
  }
  return out;
}

// Every piece is one sheet and the pieces' volumes are the part's.
void expectPiecesAddUp(const SampleCut& c) {
  double volume = 0;
  for (const TopoDS_Solid& p : c.cut.pieces) {
    volume += exactVolume(p);
    const CadSolid piece = prepareSolid(p, normalizingUnit(p));
    EXPECT_EQ(findSheets(piece, classifyWallSides(piece)).size(), 1u);
  }
  EXPECT_NEAR(volume / c.cad.volume, 1, 1e-9);
}

// Walls standing on curved walls: a rib along a cylindrical shell (its foot on the shell's inner cylinder, closed
// along its rulings), a partition across an open box's floor, bends and walls, a gusset in an L-bracket's bend (feet
// on planes and cylinders). Two pieces of one sheet each, a foot on a cylinder, the volumes adding up, on copies
// scaled by 1e-3 and 1e3.
TEST(JunctionCut, WallsOnCurvedWalls) {
  for (const auto& [name, feet] :
       {std::pair{"shell_rib", 1u}, std::pair{"box_partition", 5u}, std::pair{"lbracket_gusset", 3u}}) {
    for (double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE(std::string(name) + " x " + std::to_string(s));
      const SampleCut c = cutSample(name, s);
      ASSERT_EQ(c.cut.pieces.size(), 2u);
      EXPECT_EQ(c.cut.feet.size(), feet);
      EXPECT_TRUE(std::any_of(c.cut.feet.begin(), c.cut.feet.end(),
                              [](const Foot& f) { return BRepAdaptor_Surface(f.face).GetType() == GeomAbs_Cylinder; }));
      expectPiecesAddUp(c);
      expectFaceOrigins(c.cad, c.cut);
    }
  }
}

// Walls standing on walls: a rib ending on another rib (plate_ribs_tee) stands on it and on the plate; of two ribs
// crossing, the larger runs through (its segments one sheet) and the other's segments stand on it (plate_rib_grid:
// two 60-long ribs through, the two 40-long ones in three segments each). Every piece is one sheet, the volumes add
// up, on copies scaled by 1e-3 and 1e3.
TEST(JunctionCut, WallsStandingOnWalls) {
  for (const auto& [name, sheets, onWalls] :
       {std::tuple{"plate_ribs_tee", 3u, 1u}, std::tuple{"plate_rib_grid", 9u, 6u}}) {
    for (double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE(std::string(name) + " x " + std::to_string(s));
      const SampleCut c = cutSample(name, s);
      ASSERT_EQ(c.sheets.size(), sheets);
      ASSERT_EQ(c.cut.pieces.size(), sheets);
      std::set<int> standingOnWalls;
      for (const Foot& f : c.cut.feet) {
        EXPECT_LT(f.base, f.sheet);
        if (f.base > 0) standingOnWalls.insert(f.sheet);
      }
      EXPECT_EQ(standingOnWalls.size(), onWalls);
      expectPiecesAddUp(c);
    }
  }
}

// A plate 60 x 40 x 2 bent up into a lip 3 thick and 8 high along y = 0, the bend's inside corner chamfered 1 (or
// rounded R1) and its outside `outer` (0: sharp), and a tab 5 thick (x = 30..35) standing on the plate against the lip
// across the chamfer, `along` the plate, 12 high (the Framework cover's tabs: 9 along, a sheet; 5 along, a column). The
// tab's edges on the chamfer are two short lines across it (on the round, two quarter arcs): each closed on itself
// bounded no area (a sliver), and the cut left the tab joined to the plate (`no piece holds the sheet`); with the
// outside sharp the chamfer is a lateral face inside the bend (bendSheetOfFaces), and a column's sides are no such
// face. Cut now into two pieces (the tab's one sheet, its feet cuts; the column's not meshed yet: three feet), feet on
// the lip (5 x 5), the chamfer (5 x 1.41; the round 5 x pi / 2) and the plate (5 x (along - 1)), the volumes adding up;
// at scales 1, 1e-3, 1e3.
TEST(JunctionCut, ATabAcrossABendsChamferedInsideCorner) {
  for (const auto& [outer, along, round] : {std::tuple{3.0, 9.0, false}, std::tuple{0.0, 9.0, false},
                                            std::tuple{3.0, 5.0, false}, std::tuple{3.0, 9.0, true}})
    for (const double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE("outer " + std::to_string(outer) + " along " + std::to_string(along) + (round ? " round" : "") +
                   " x " + std::to_string(s));
      BRepBuilderAPI_MakePolygon profile;
      std::vector<std::pair<double, double>> corners{{outer, 0}, {40, 0}, {40, 2}, {4, 2}, {3, 3}, {3, 8}, {0, 8}};
      if (round) corners.erase(corners.begin() + 3), corners[3] = {3, 2};  // a sharp inside corner, rounded below
      if (outer > 0) corners.emplace_back(0, outer);
      for (const auto& [y, z] : corners) profile.Add(gp_Pnt(0, y * s, z * s));
      profile.Close();
      TopoDS_Shape bent =
          BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(profile.Wire()).Face(), gp_Vec(60 * s, 0, 0)).Shape();
      if (round) {
        BRepFilletAPI_MakeFillet fillet(bent);
        for (TopExp_Explorer e(bent, TopAbs_EDGE); e.More(); e.Next()) {
          TopoDS_Vertex a, b;
          TopExp::Vertices(TopoDS::Edge(e.Current()), a, b);
          const gp_Pnt p = BRep_Tool::Pnt(a), q = BRep_Tool::Pnt(b);
          if (std::abs(p.Y() - 3 * s) + std::abs(q.Y() - 3 * s) + std::abs(p.Z() - 2 * s) + std::abs(q.Z() - 2 * s) <
              1e-9 * s)
            fillet.Add(1 * s, TopoDS::Edge(e.Current()));
        }
        bent = fillet.Shape();
      }
      BRepAlgoAPI_Fuse fuse(bent, BRepPrimAPI_MakeBox(gp_Pnt(30 * s, 3 * s, 1 * s), 5 * s, along * s, 11 * s).Shape());
      const BooleanCut cut = cutBoolean(fuse.Shape());
      const SampleCut& c = cut.c;
      ASSERT_EQ(c.cut.pieces.size(), 2u);
      const double area = std::accumulate(cut.footAreas.begin(), cut.footAreas.end(), 0.0);
      EXPECT_NEAR(area / (s * s), 25 + 5 * (round ? M_PI / 2 : std::sqrt(2.0)) + 5 * (along - 1), 1e-6);
      EXPECT_EQ(c.cut.feet.size(), 3u);
      double volume = 0;
      for (std::size_t p = 0; p < c.cut.pieces.size(); ++p) {  // one sheet each, its feet cuts (as the pipeline has it)
        volume += exactVolume(c.cut.pieces[p]);
        if (c.sheets[c.cut.sheetOf[p]].column) continue;
        CadSolid piece = prepareSolid(c.cut.pieces[p], normalizingUnit(c.cut.pieces[p]));
        for (int origin : c.cut.faceOrigin[p]) piece.cutInput.push_back(origin < 0);
        EXPECT_EQ(findSheets(piece, classifyWallSides(piece)).size(), 1u) << "piece " << p;
      }
      EXPECT_NEAR(volume / c.cad.volume, 1, 1e-9);
      expectFaceOrigins(c.cad, c.cut);
    }
}

// The area of the disc round (cx, cy) of radius r where x >= a and y >= b (the midpoint rule over x, 20 000 strips).
double discBeyond(double cx, double cy, double r, double a, double b) {
  const int n = 20000;
  double area = 0;
  const double x0 = std::max(a, cx - r), dx = (cx + r - x0) / n;
  for (int i = 0; i < n; ++i) {
    const double x = x0 + (i + 0.5) * dx, h = std::sqrt(std::max(0.0, r * r - (x - cx) * (x - cx)));
    area += std::max(0.0, cy + h - std::max(b, cy - h)) * dx;
  }
  return area;
}

// Hollow screw bosses molded into an open box (60 x 40 x 15, walls and floor 2): outside R3.5, bore R1.5 from the
// floor up, 13 over the floor, at (30, 5) merged 0.5 into the wall y = 0..2, at (4, 4) into the corner (both walls).
// The boss's foot on the floor was closed round its own cylinder inside the wall (a whole disc), and the cut left
// the box's piece a second shell, not closed; in the corner the boss's top was taken for a face inside the box's
// bend, so the boss had no foot on the walls (`no piece holds the sheet`). Cut now into two pieces, each one closed
// shell: feet on each wall the boss lies on (its chord x 12 high) and on the floor (the disc beyond the walls, less
// the bore), the boss's piece a prism on its foot on the floor, the volumes adding up; at scales 1, 1e-3, 1e3.
TEST(JunctionCut, BossesMergedIntoABoxsWallAndCorner) {
  for (const auto& [cx, cy, walls] : {std::tuple{30.0, 5.0, 1u}, std::tuple{4.0, 4.0, 2u}})
    for (const double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE("boss at " + std::to_string(cx) + ", " + std::to_string(cy) + " x " + std::to_string(s));
      const double r = 3.5, bore = 1.5;
      const TopoDS_Shape box = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60 * s, 40 * s, 15 * s).Shape(),
                                               BRepPrimAPI_MakeBox(gp_Pnt(2 * s, 2 * s, 2 * s), 56 * s, 36 * s, 15 * s))
                                   .Shape();
      const TopoDS_Shape boss =
          BRepAlgoAPI_Fuse(box, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(cx * s, cy * s, s), gp::DZ()), r * s, 13 * s))
              .Shape();
      const BooleanCut cut = cutBoolean(BRepAlgoAPI_Cut(
          boss, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(cx * s, cy * s, 2 * s), gp::DZ()), bore * s, 15 * s)));
      const SampleCut& c = cut.c;
      ASSERT_EQ(c.cut.pieces.size(), 2u);
      ASSERT_EQ(c.cut.feet.size(), walls + 1);
      const double chord = walls == 1 ? 2 * std::sqrt(r * r - (cy - 2) * (cy - 2))        // across the wall's face
                                      : cx + std::sqrt(r * r - (cy - 2) * (cy - 2)) - 2;  // from the corner
      const double floor = discBeyond(cx, cy, r, walls == 1 ? -1e9 : 2, 2) - M_PI * bore * bore;
      double onFloor = 0;
      for (std::size_t f = 0; f < c.cut.feet.size(); ++f) {
        const bool level =
            BRepAdaptor_Surface(c.cut.feet[f].face).Plane().Axis().Direction().IsParallel(gp::DZ(), 1e-9);
        if (level)
          onFloor += cut.footAreas[f] / (s * s);
        else
          EXPECT_NEAR(cut.footAreas[f] / (s * s), chord * 12, 1e-6);
      }
      EXPECT_NEAR(onFloor, floor, 1e-4);
      double volume = 0;
      for (const TopoDS_Solid& p : c.cut.pieces) {
        int shells = 0;
        for (TopExp_Explorer shell(p, TopAbs_SHELL); shell.More(); shell.Next(), ++shells)
          EXPECT_TRUE(BRep_Tool::IsClosed(shell.Current()));
        EXPECT_EQ(shells, 1);
        volume += exactVolume(p);
      }
      const double unit = s * c.cad.unit;  // the cut is in the pipeline's units
      EXPECT_NEAR(exactVolume(c.cut.pieces[1]) / (unit * unit * unit), floor * 12, 1e-3);
      EXPECT_NEAR(volume / c.cad.volume, 1, 1e-9);
      expectFaceOrigins(c.cad, c.cut);
    }
}

// The Framework cover's (shared/parts/real) upper tab with the plate, the chamfered bend and the lip round it (the part
// cut to x 120..135, z 115..140): a column 5 x 5 across the bend, standing on the plate, the bend's inside chamfer and
// the lip. Its sides were taken for faces inside the bend (lateral, meeting walls of one sheet and one side in concave
// edges), a foot was put on one, and the cut left the tab joined to the plate (`no piece holds the sheet`). Cut now,
// feet on the lip (5 x 5), the chamfer (5 x 1.41) and the plate (5 x 4), none on the tab's own faces.
TEST(JunctionCut, TheFrameworkCoversUpperTabIsCutOffItsBentPlate) {
  const TopoDS_Solid cover = readSolids(std::string(HEXLAYER_SHARED_PARTS) + "/framework_top_cover_r_full.stp").at(0);
  BRepAlgoAPI_Common crop(cover, BRepPrimAPI_MakeBox(gp_Pnt(120, -20, 115), gp_Pnt(135, 20, 140)).Shape());
  const BooleanCut cut = cutBoolean(crop.Shape());
  ASSERT_EQ(cut.c.cut.pieces.size(), 2u);
  std::vector<double> areas = cut.footAreas;
  std::sort(areas.begin(), areas.end());
  ASSERT_EQ(areas.size(), 3u);
  EXPECT_NEAR(areas[0], 5 * std::sqrt(2.0), 1e-3);
  EXPECT_NEAR(areas[1], 20, 1e-3);
  EXPECT_NEAR(areas[2], 25, 1e-3);
  expectFaceOrigins(cut.c.cad, cut.c.cut);
}

// A tab 1 thick sticking out of the 2 mm plate's side face (mid-thickness): it stands on the plate's rim face, not on
// its wall; refused, saying so (a post on a wall's edge, as on the Framework cover), and naming the thickness step
// (thicknessSteps takes none whose side is wider than the thinner wall: this rim face is as wide as the plate's).
TEST(JunctionCut, ASheetOnARimFaceIsRefusedSayingSo) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const TopoDS_Solid solid = boxes({{0, 0, 0, 60, 40, 2}, {60, 15, 0.5, 12, 10, 1}}, s);
    const CadSolid cad = prepareSolid(solid, normalizingUnit(solid));
    const WallSides sides = classifyWallSides(cad);
    const std::vector<Sheet> sheets = findSheets(cad, sides);
    ASSERT_EQ(sheets.size(), 2u);
    try {
      cutAtJunctions(cad, sides, sheets);
      ADD_FAILURE() << "not refused";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::UnsupportedGeometry);
      EXPECT_NE(std::string(e.what()).find("stands on the edge (a rim face) of another sheet"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("a thinner wall going on from a thicker one's rim"), std::string::npos)
          << e.what();
    }
  }
}

// Two gussets 1.5 thick, 8 long and 6 high ending on a hollow boss (outside R4, bore R2 from the plate's top, 10
// high) on a 60 x 40 x 2 plate, one on each side: the one along +x ends across the cylinder's seam. Each gusset
// stands on the plate and on the boss: four pieces of one sheet each, the volumes adding up, a foot of each gusset
// on the boss's cylinder, and the feet on the plate meeting on the boss's foot circle (their areas add up to the
// boss's ring and the gussets' feet outside its circle, not cut at their chords), on copies scaled by 1e-3 and 1e3,
// and on the part with every face a B-spline (as OpenCASCADE's NURBS conversion and some CAD exports write it: the
// boss's side trimmed to the face, no surface under the gussets' ends, its cylinder found again).
TEST(JunctionCut, GussetsEndingOnABossAcrossItsSeam) {
  const double r = 4, bore = 2, a = 0.75, x = 30, y = 20, t = 2, in = 3, length = 8;
  TopoDS_Shape part = test_boxes::boxes({{0, 0, 0, 60, 40, t}}, 1);
  part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, 1), gp::DZ()), r, 11).Shape()).Shape();
  for (const double side : {1.0, -1.0}) {
    const double x0 = side > 0 ? x + in : x - in - length;
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(x0, y - a, 1), length, 2 * a, 7).Shape()).Shape();
  }
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, t), gp::DZ()), bore, 11).Shape()).Shape();
  ShapeUpgrade_UnifySameDomain unify(part);
  unify.Build();
  // a gusset's foot on the plate: its 2a x (in + length) footprint less the part of the disc in it
  const double inDisc = a * std::sqrt(r * r - a * a) + r * r * std::asin(a / r) - 2 * a * in;
  const double plateFeet = M_PI * (r * r - bore * bore) + 2 * (2 * a * length - inDisc);  // the boss's a ring
  for (const bool nurbs : {false, true})
    for (double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE("x " + std::to_string(s) + (nurbs ? " B-spline" : ""));
      const TopoDS_Shape scaled = test_boxes::scaled(unify.Shape(), s);
      const SampleCut c =
          cutSolid(nurbs ? TopoDS::Solid(BRepBuilderAPI_NurbsConvert(scaled, true).Shape()) : TopoDS::Solid(scaled));
      const CadSolid& cad = c.cad;
      const JunctionCut& cut = c.cut;
      ASSERT_EQ(c.sheets.size(), 4u);
      ASSERT_EQ(cut.pieces.size(), 4u);
      expectPiecesAddUp(c);
      double onPlate = 0;
      std::set<int> onBoss;
      for (const Foot& f : cut.feet) {
        if (f.base == 0) onPlate += areaOf(f.face);
        if (f.base > 0 && BRepAdaptor_Surface(f.face).GetType() == GeomAbs_Cylinder) onBoss.insert(f.sheet);
      }
      EXPECT_EQ(onBoss.size(), 2u) << "each gusset has a foot on the boss";
      EXPECT_NEAR(onPlate / (cad.unit * cad.unit) / (s * s) / plateFeet, 1, 1e-6);
    }
}

// A rib tying a hollow boss to a box's end wall (a housing's): an open box 80 x 50 x 20, wall 2, sharp edges, a boss
// on its floor (outside R3.5, bore R1.5 from the floor's top, 12 high) and a rib 2 x 8 from the end wall into the
// boss. The rib stands on the floor, the wall and the boss; one of the boss's foot wires on the floor was a segment
// there and back, a face of no area that no piece kept (refused: `the foot ... is not a face of both pieces`). The
// cut gives three pieces of one sheet each, the volumes adding up, every foot of some area; at scales 1, 1e-3, 1e3.
TEST(JunctionCut, ARibFromAWallIntoABoss) {
  TopoDS_Shape part = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 80, 50, 20).Shape(),
                                      BRepPrimAPI_MakeBox(gp_Pnt(2, 2, 2), 76, 46, 20).Shape())
                          .Shape();
  part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 25, 1), gp::DZ()), 3.5, 13).Shape()).Shape();
  part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(1, 24, 1), 19, 2, 9).Shape()).Shape();
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 25, 2), gp::DZ()), 1.5, 13).Shape()).Shape();
  ShapeUpgrade_UnifySameDomain unify(part);
  unify.Build();
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const SampleCut c = cutSolid(test_boxes::scaled(unify.Shape(), s));
    ASSERT_EQ(c.sheets.size(), 3u);
    ASSERT_EQ(c.cut.pieces.size(), 3u);
    expectPiecesAddUp(c);
    for (const Foot& f : c.cut.feet)
      EXPECT_GT(areaOf(f.face) / (c.cad.unit * c.cad.unit) / (s * s), 1.0) << "sheet " << f.sheet;
  }
}

// A hollow boss (R4, 10 high) on a 60 x 40 x 2 plate, its blind bore R2 down to the plate's top or stopping 0.9 above
// it (a cup), as built and with its faces listed in the reverse order (as another CAD system may write it). The
// bore's bottom is a wall face of the plate's sheet; listed first, it was the face that named the plate's piece, which
// went to the cup (`no piece holds the sheet`), and a foot on it (the bore's bottom itself, no face of both pieces)
// coming first was taken for the sheet having no foot. Now: the plate's piece holds the plate (60 x 40 x 2), the
// boss's the ring or the cup (its bottom with it), its foot the ring (pi (4^2 - 2^2)) or the cup's whole disc (pi 4^2),
// at scales 1, 1e-3, 1e3.
TEST(JunctionCut, ACuppedBossIsCutOffWhateverTheOrderOfItsFaces) {
  for (const double bottom : {0.0, 0.9})
    for (const bool reversed : {false, true})
      for (const double s : {1.0, 1e-3, 1e3}) {
        SCOPED_TRACE("bottom " + std::to_string(bottom) + (reversed ? ", reversed" : "") + ", x " + std::to_string(s));
        const TopoDS_Solid part = test_parts::cuppedBoss(bottom, s);
        const SampleCut c = cutSolid(reversed ? test_parts::withFacesReversed(part) : part);
        ASSERT_EQ(c.cut.pieces.size(), 2u);
        EXPECT_EQ(c.cut.sheetOf, (std::vector<int>{0, 1}));
        const double unit3 = std::pow(s * c.cad.unit, 3);
        EXPECT_NEAR(exactVolume(c.cut.pieces[0]) / unit3, 60 * 40 * 2, 1e-6);
        EXPECT_NEAR(exactVolume(c.cut.pieces[1]) / unit3, M_PI * (16 * 10 - 4 * (10 - bottom)), 1e-6);
        double feet = 0;
        for (const Foot& f : c.cut.feet) feet += f.area / std::pow(s * c.cad.unit, 2);
        EXPECT_NEAR(feet, M_PI * (bottom > 0 ? 16 : 16 - 4), 1e-6);
        expectFaceOrigins(c.cad, c.cut);
      }
}

// A hollow boss through the plate (R4 outside, R2 bore through both, from z = -6 to 12 on a 2 mm plate): one sheet
// (its bore one face on both sides), cut off along both of the plate's walls into two pieces, the one below appended
// as a further piece of the same sheet, each with its ring foot (pi (4^2 - 2^2)) shared with the plate's piece; the
// volumes adding up, at scales 1, 1e-3, 1e3.
TEST(JunctionCut, ABossThroughThePlateIsCutInTwoPieces) {
  TopoDS_Shape part = BRepAlgoAPI_Fuse(boxes({{0, 0, 0, 60, 40, 2}}, 1),
                                       BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, -6), gp::DZ()), 4, 18).Shape())
                          .Shape();
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, -7), gp::DZ()), 2, 20).Shape()).Shape();
  ShapeUpgrade_UnifySameDomain unify(part);
  unify.Build();
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const SampleCut c = cutSolid(test_boxes::scaled(unify.Shape(), s));
    ASSERT_EQ(c.sheets.size(), 2u);
    ASSERT_EQ(c.cut.pieces.size(), 3u);
    EXPECT_EQ(c.cut.sheetOf, (std::vector<int>{0, 1, 1}));
    expectPiecesAddUp(c);
    ASSERT_EQ(c.cut.feet.size(), 2u);
    std::set<int> standing;
    for (const Foot& f : c.cut.feet) {
      standing.insert(f.sheet);
      EXPECT_EQ(f.base, 0);
      EXPECT_NEAR(areaOf(f.face) / (c.cad.unit * c.cad.unit) / (s * s) / (M_PI * 12), 1, 1e-6);
    }
    EXPECT_EQ(standing, (std::set<int>{1, 2})) << "each piece of the boss on its foot";
  }
}
