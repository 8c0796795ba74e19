// Fillets at the feet of standing walls (geometry/foot_fillets.hpp): found and removed on the filleted junction
// samples (a rib on a plate filleted along both sides; a rib in an open box filleted all round, mitred at its
// corners), so that the smoothed part's standing sheet meets its base in concave edges; its volume the part's less
// the fillets'; none found on a rib with sharp feet, nor on a rib whose top is rounded (a convex round). On copies
// scaled by 1e-3 and 1e3, and converted to B-spline surfaces (as a STEP file in metres may come).
#include <gtest/gtest.h>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <cmath>
#include <set>
#include <string>

#include "geometry/cad_solid.hpp"
#include "geometry/foot_fillets.hpp"
#include "geometry/mixed_faces.hpp"
#include "geometry/sheet_edges.hpp"
#include "test_boxes.hpp"
#include "test_parts.hpp"

using namespace hexlayer;

namespace {

TopoDS_Solid sample(const std::string& name) {
  return readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/junctions/" + name + ".step").at(0);
}

TopoDS_Solid asBSplines(const TopoDS_Solid& solid) {
  BRepBuilderAPI_NurbsConvert convert(solid, true);
  return TopoDS::Solid(convert.Shape());
}

struct Found {
  CadSolid cad;
  std::optional<FootFillets> fillets;
};

// The solid scaled by s, prepared as the pipeline prepares it (its units, its mixed faces split), its foot fillets
// looked for.
Found footFilletsOf(const TopoDS_Solid& solid, double s) {
  const TopoDS_Solid scaled = test_boxes::scaled(solid, s);
  Found f{prepareSolid(scaled, normalizingUnit(scaled)), std::nullopt};
  WallSides sides = classifyWallSides(f.cad);
  splitMixedFaces(f.cad, sides);  // a fillet from a rib's wall to the plate's: part rim, part wall
  f.fillets = removeFootFillets(f.cad, sides, findSheets(f.cad, sides));
  return f;
}

// [in] name: a sample; [in] fillets: its fillet faces at the foot; [in] volume: the fillets', r^2 (1 - pi / 4) per
// unit length and the mitres'.
void expectRemoved(const std::string& name, std::size_t fillets, double volume) {
  for (const bool bsplines : {false, true})
    for (double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE(name + (bsplines ? " as B-splines" : "") + " x " + std::to_string(s));
      const TopoDS_Solid solid = bsplines ? asBSplines(sample(name)) : sample(name);
      const Found f = footFilletsOf(solid, s);
      ASSERT_TRUE(f.fillets);
      EXPECT_GE(f.fillets->faces.size(), fillets);  // a fillet split into a rim and a wall piece: two faces
      EXPECT_NEAR(f.fillets->largestRadius / f.cad.unit, s, 1e-6 * s);  // r = 1
      const double unit3 = std::pow(f.cad.unit, 3);
      EXPECT_NEAR((f.cad.volume - f.fillets->smooth.volume) / unit3, volume * s * s * s, 0.01 * volume * s * s * s);
      EXPECT_EQ(f.fillets->smooth.faces.Extent(), f.cad.faces.Extent() - static_cast<int>(f.fillets->faces.size()));
      std::set<int> inputs;  // the input faces removed
      for (int face : f.fillets->faces) inputs.insert(inputFaceOf(f.cad, face));
      EXPECT_EQ(inputs.size(), fillets);
      for (int face : f.fillets->smooth.inputFace) EXPECT_EQ(inputs.count(face), 0u);
      const WallSides sides = classifyWallSides(f.fillets->smooth);
      EXPECT_EQ(findSheets(f.fillets->smooth, sides).size(), 2u);
      EXPECT_FALSE(concaveEdges(f.fillets->smooth).empty());
    }
}

}  // namespace

// The rib along the plate, 60 long, filleted r = 1 on both sides: 2 x 60 x (1 - pi / 4).
TEST(FootFillets, ARibOnAPlate) { expectRemoved("plate_rib_fillet", 2, 2 * 60 * (1 - M_PI / 4)); }

// The rib in the box, 40 x 2, filleted all round (the samples README's volume: the part's less the box's and rib's).
TEST(FootFillets, ARibInABoxFilletedAllRound) {
  expectRemoved("box_rib_fillet", 4, (2 * 40 + 2 * 2) * (1 - M_PI / 4) + 4 * (5.0 / 3 - M_PI / 2));
}

// The same box with its faces written in pieces (none over a twelfth of the surface: the floor in four, the fillets
// whole): OpenCASCADE's defeaturing left the fillets where they were (a warning, the part unchanged, and the rib
// refused: `no foot found`); the faces on one surface are merged first now. The fillets' volume removed, the floor's
// pieces but one merged (listed: their quads are grouped by nearness; so are the floor's bottom's), every other input
// face named by a face of the smoothed part, two sheets meeting in concave edges. At scales 1, 1e-3, 1e3.
TEST(FootFillets, ARibInABoxWrittenInPieces) {
  const TopoDS_Solid part = test_parts::inPieces(sample("box_rib_fillet"), 12);
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const Found f = footFilletsOf(part, s);
    ASSERT_TRUE(f.fillets);
    const double volume = (2 * 40 + 2 * 2) * (1 - M_PI / 4) + 4 * (5.0 / 3 - M_PI / 2), unit3 = std::pow(f.cad.unit, 3);
    EXPECT_NEAR((f.cad.volume - f.fillets->smooth.volume) / unit3, volume * s * s * s, 0.01 * volume * s * s * s);
    std::set<int> named(f.fillets->smooth.inputFace.begin(), f.fillets->smooth.inputFace.end()), merged, removed;
    for (int face : f.fillets->merged) merged.insert(inputFaceOf(f.cad, face));
    for (int face : f.fillets->faces) removed.insert(inputFaceOf(f.cad, face));
    EXPECT_GE(merged.size(), 3u);  // the floor's top in four pieces: one names the merged face
    for (int face = 0; face < f.cad.faces.Extent(); ++face) {
      const int input = inputFaceOf(f.cad, face);
      EXPECT_EQ(named.count(input) + merged.count(input) + removed.count(input), 1u) << "input face " << input;
    }
    const WallSides sides = classifyWallSides(f.fillets->smooth);
    EXPECT_EQ(findSheets(f.fillets->smooth, sides).size(), 2u);
    EXPECT_FALSE(concaveEdges(f.fillets->smooth).empty());
  }
}

// The rib's top edges (at z = 10: along its sides and across its ends) rounded r = 0.8.
TopoDS_Solid topRounded(const TopoDS_Solid& rib) {
  BRepFilletAPI_MakeFillet round(rib);
  for (TopExp_Explorer e(rib, TopAbs_EDGE); e.More(); e.Next()) {
    TopoDS_Vertex a, b;
    TopExp::Vertices(TopoDS::Edge(e.Current()), a, b);
    const gp_Pnt p = BRep_Tool::Pnt(a), q = BRep_Tool::Pnt(b);
    if (std::abs(p.Z() - 10) < 1e-6 && std::abs(q.Z() - 10) < 1e-6) round.Add(0.8, TopoDS::Edge(e.Current()));
  }
  return TopoDS::Solid(TopExp_Explorer(round.Shape(), TopAbs_SOLID).Current());
}

// Sharp feet: nothing to remove. The box's rib, its feet filleted, its top rounded: the feet's fillets only.
TEST(FootFillets, NoneOnSharpFeetNorOnRounds) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    EXPECT_FALSE(footFilletsOf(sample("plate_rib"), s).fillets);
    const Found f = footFilletsOf(topRounded(sample("box_rib_fillet")), s);
    ASSERT_TRUE(f.fillets);
    std::set<int> inputs;
    for (int face : f.fillets->faces) inputs.insert(inputFaceOf(f.cad, face));
    EXPECT_EQ(inputs.size(), 4u);
  }
}
