// Rim caps (sweep/rim_cap.hpp) on the round ends of a bent sheet, and on a rim they would not improve.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/pipeline.hpp"
#include "quality/quality.hpp"
#include "sweep/cap_template.hpp"

using namespace hexlayer;

namespace {

MeshResult meshRim(const std::string& part, int layers) {
  MeshOptions o;
  o.layers = layers;
  return meshFile(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/rims/" + part + ".step", o);
}

}  // namespace

// lbracket_round_ends: two half-round ends (radius 1), 20 wide, 2 mm wall (rims/README.md). The sweep's last
// column runs between the round's edges and the cap drawn for the layer count (cap_template.hpp) lies beyond it:
// its profile nodes on the half circle, on a CAD face; its inside nodes inside the part, but where the cap ends
// on the strip's flat side faces. Without caps 2 chords' lens of each half disc would be lost (0.571 r^2 per
// length, 22.8 mm^3 for both ends); the templates lose 0.113 (2 layers) and 0.107 (3 layers), the bend's chords
// the rest. Every cap hex is at least the template's worst in the half disc.
TEST(RimCap, RoundEndsGetTheDrawnCap) {
  for (const int layers : {2, 3}) {
    const MeshResult r = meshRim("lbracket_round_ends", layers);
    const CapTemplate t = *drawnCap(layers);
    const RimCapStats& cap = r.report.rimCap;
    ASSERT_GT(cap.cappedEdges, 0u);
    EXPECT_EQ(cap.capHexes, t.quads.size() * cap.cappedEdges);
    EXPECT_EQ(cap.capColumns, cap.cappedEdges + 2) << "two open rows of edges, one per end";
    std::size_t onProfile = 0, inside = 0;
    for (std::size_t i = 0; i < r.mesh.nodes.size(); ++i) {
      if (r.mesh.nodeOnRim[i] == kRimCap && r.mesh.nodeLayer[i] >= 0) {
        ++onProfile;
        EXPECT_GE(r.mesh.nodeFace[i], 0);
      }
      inside += r.mesh.nodeLayer[i] < 0;
    }
    EXPECT_EQ(onProfile, t.onProfile.size() * cap.capColumns);
    EXPECT_EQ(inside, t.inside.size() * cap.capColumns);
    const double uncapped = 0.571 * 2 * 20;  // both ends, 20 wide, r = 1
    const double lost = r.report.mesh.cadVolume - r.report.mesh.quality.volume;
    EXPECT_LT(lost, 0.6 * uncapped) << "the caps' chords and the bend's";
    EXPECT_GT(lost, 0);
    EXPECT_GE(r.report.mesh.quality.sjMin, layers == 2 ? 0.73 : 0.8) << layers << " layers";
  }
}

// A rim chamfered on both sides loses a little of its profile to the sweep's column; the structured cap would not
// halve it, and the drawn one would lower the mesh's mean scaled Jacobian: it stays uncapped.
TEST(RimCap, ChamferedRimKeepsTheSweepsColumn) {
  for (const int layers : {2, 3}) {
    const MeshResult r = meshRim("plate_chamfer_both_sides", layers);
    EXPECT_GT(r.report.rimCap.rimEdges, 0u);
    EXPECT_EQ(r.report.rimCap.cappedEdges, 0u) << layers << " layers";
  }
}
