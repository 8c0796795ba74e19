// pipeline/report.hpp and pipeline/mesh_report.hpp: a MeshReport built by hand, its lengths brought to the input's
// units, several solids merged, and the JSON written from it.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "pipeline/mesh_report.hpp"
#include "pipeline/report.hpp"

using namespace hexlayer;

namespace {

std::set<std::string> keysOf(const nlohmann::json& object) {
  std::set<std::string> keys;
  for (const auto& item : object.items()) keys.insert(item.key());
  return keys;
}

// One solid's report in the pipeline's units (10 per input length), its mesh measured in the input's units.
MeshReport solidReport() {
  MeshReport r;
  r.stages["geometry"] = {0.5, 60};
  r.stages["quality"] = {0.25, 64};
  r.thickness = 20, r.size = 30;
  r.junctions.push_back({Vec3(10, 20, 30), {"Face3", "Face4"}, 500, 7000});
  r.junctionsLeftOut = 7;
  r.smallFeatures = {1, 2, Vec3(40, 50, 60)};
  r.chordal.rim.largestMove = 4;
  r.boundaryDeviation.max = 2, r.boundaryDeviation.mean = 1, r.boundaryDeviation.maxRelative = 0.5;
  r.boundaryDeviation.worstAt = Vec3(70, 80, 90), r.boundaryDeviation.worstFace = "Face2";
  r.quadratic = QuadraticStats{};
  r.quadratic->maxProjectionMove = 6;
  r.smoothing.worstBefore = 0.3;
  r.sharpEdges.edges = 4, r.sharpEdges.nodesMoved = 5, r.sharpEdges.nodesKept = 6;
  r.memory.bytes = 1e6;
  r.mesh.hexes = 100, r.mesh.nodes = 242, r.mesh.layers = 2;
  r.mesh.quality.volume = 102, r.mesh.cadVolume = 100;
  r.mesh.boundary.eulerCharacteristic = 2, r.mesh.cadEuler = 2;
  return r;
}

ValidationFailure inverted() { return {"inverted", 3, Vec3(1, 2, 3), "inverted: 3 inverted hexes"}; }

}  // namespace

// Lengths are divided by the unit, the junctions' areas by its square and volumes by its cube; ratios, counts,
// bytes and the mesh's own numbers (already in the input's units) are left as they are.
TEST(Report, ToInputUnitsScalesLengthsAreasAndVolumes) {
  MeshReport r = solidReport();
  toInputUnits(r, 10);
  EXPECT_DOUBLE_EQ(r.thickness, 2);
  EXPECT_DOUBLE_EQ(r.size, 3);
  EXPECT_TRUE(r.junctions[0].at.isApprox(Vec3(1, 2, 3)));
  EXPECT_DOUBLE_EQ(r.junctions[0].area, 5);
  EXPECT_DOUBLE_EQ(r.junctions[0].volume, 7);
  EXPECT_TRUE(r.smallFeatures.firstAt.isApprox(Vec3(4, 5, 6)));
  EXPECT_DOUBLE_EQ(r.chordal.rim.largestMove, 0.4);
  EXPECT_DOUBLE_EQ(r.boundaryDeviation.max, 0.2);
  EXPECT_DOUBLE_EQ(r.boundaryDeviation.mean, 0.1);
  EXPECT_TRUE(r.boundaryDeviation.worstAt->isApprox(Vec3(7, 8, 9)));
  EXPECT_DOUBLE_EQ(r.quadratic->maxProjectionMove, 0.6);
  EXPECT_EQ(r.boundaryDeviation.maxRelative, 0.5);
  EXPECT_EQ(r.smoothing.worstBefore, 0.3);
  EXPECT_EQ(r.memory.bytes, 1e6);
  EXPECT_EQ(r.junctionsLeftOut, 7);
  EXPECT_EQ(r.mesh.cadVolume, 100);
  EXPECT_EQ(r.mesh.quality.volume, 102);
}

// A solid's report has every stage's key, the optional ones only when set, and the values as the struct has them.
TEST(Report, OneSolidHasEveryKeyWithItsValue) {
  MeshReport r = solidReport();
  toInputUnits(r, 10);
  const nlohmann::json j = toJson(r);
  const std::set<std::string> expected = {"aspect_ratio",
                                          "boundary",
                                          "boundary_deviation",
                                          "bubbles",
                                          "chordal_surface",
                                          "faces",
                                          "faces_split",
                                          "hexes",
                                          "inverted_hexes",
                                          "junctions",
                                          "layers",
                                          "memory_estimate",
                                          "nodes",
                                          "order",
                                          "peak_memory_mib",
                                          "quad_mesh",
                                          "quadratic",
                                          "rim_cap",
                                          "scaled_jacobian",
                                          "sharp_edges",
                                          "size",
                                          "size_source",
                                          "sizing",
                                          "small_features",
                                          "smoothing",
                                          "surface_groups",
                                          "sweep",
                                          "tet_classes",
                                          "tets",
                                          "thickness",
                                          "timings_s",
                                          "validation",
                                          "volume",
                                          "worst_hex_at"};
  EXPECT_EQ(keysOf(j), expected);
  EXPECT_DOUBLE_EQ(j["thickness"].get<double>(), 2);
  EXPECT_DOUBLE_EQ(j["size"].get<double>(), 3);
  EXPECT_DOUBLE_EQ(j["junctions"][0]["area"].get<double>(), 5);
  EXPECT_DOUBLE_EQ(j["junctions"][0]["volume"].get<double>(), 7);
  EXPECT_DOUBLE_EQ(j["junctions"][0]["at"][2].get<double>(), 3);
  EXPECT_EQ(j["junctions"][0]["faces"], nlohmann::json({"Face3", "Face4"}));
  EXPECT_DOUBLE_EQ(j["small_features"]["first_at"][0].get<double>(), 4);
  EXPECT_EQ(j["small_features"]["narrow_faces"], 2);
  EXPECT_DOUBLE_EQ(j["chordal_surface"]["rim"]["largest_move"].get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(j["boundary_deviation"]["worst_at"][1].get<double>(), 8);
  EXPECT_EQ(j["boundary_deviation"]["worst_face"], "Face2");
  EXPECT_DOUBLE_EQ(j["quadratic"]["max_projection_move"].get<double>(), 0.6);
  EXPECT_EQ(j["sharp_edges"], nlohmann::json({{"edges", 4}, {"nodes_moved", 5}, {"nodes_kept", 6}}));
  EXPECT_EQ(j["volume"],
            nlohmann::json({{"cad", 100.0}, {"mesh", 102.0}, {"relative_error", 0.02}, {"junctions_left_out", 7.0}}));
  EXPECT_EQ(j["timings_s"], nlohmann::json({{"geometry", 0.5}, {"quality", 0.25}}));
  EXPECT_EQ(j["peak_memory_mib"], nlohmann::json({{"geometry", 60.0}, {"quality", 64.0}}));
  EXPECT_EQ(j["boundary"]["cad_euler_characteristic"], 2);
  EXPECT_EQ(j["boundary"]["same_topology_as_cad"], true);
  EXPECT_EQ(j["hexes"], 100);
}

// Without the optional numbers: no "quadratic", "aspect_ratio_hit" or deviation "worst_at"; with --aspect's share, the
// key is there; a boundary with another Euler characteristic than the CAD's is not the same topology.
TEST(Report, OptionalKeysOnlyWhenSet) {
  MeshReport r = solidReport();
  r.quadratic.reset(), r.boundaryDeviation.worstAt.reset();
  r.mesh.boundary.eulerCharacteristic = 0;
  nlohmann::json j = toJson(r);
  EXPECT_FALSE(j.contains("quadratic"));
  EXPECT_FALSE(j.contains("aspect_ratio_hit"));
  EXPECT_FALSE(j["boundary_deviation"].contains("worst_at"));
  EXPECT_FALSE(j["boundary_deviation"].contains("worst_face"));
  EXPECT_EQ(j["boundary"]["same_topology_as_cad"], false);
  r.aspectRatioHit = 0.75;
  j = toJson(r);
  EXPECT_EQ(j["aspect_ratio_hit"], 0.75);
}

// "passed" follows the failures: true with none, false with one, whose place is written only if it has one.
TEST(Report, ValidationPassedFollowsTheFailures) {
  MeshReport r = solidReport();
  EXPECT_EQ(toJson(r)["validation"], nlohmann::json({{"passed", true}, {"failures", nlohmann::json::array()}}));
  r.mesh.failures = {inverted(), {"volume", 1, std::nullopt, "volume: 20 % off"}};
  const nlohmann::json v = toJson(r)["validation"];
  EXPECT_EQ(v["passed"], false);
  ASSERT_EQ(v["failures"].size(), 2u);
  EXPECT_EQ(
      v["failures"][0],
      nlohmann::json(
          {{"check", "inverted"}, {"count", 3}, {"at", {1.0, 2.0, 3.0}}, {"message", "inverted: 3 inverted hexes"}}));
  EXPECT_FALSE(v["failures"][1].contains("at"));
  EXPECT_EQ(v["failures"][1]["check"], "volume");
}

// Several solids: the whole mesh's numbers with the solids' CAD volumes and Euler characteristics summed, their
// failures named by solid, and each solid's report under "solids" as it is alone; no stage keys at the top.
TEST(Report, SolidsMergeIntoOneReport) {
  MeshReport first = solidReport(), second = solidReport();
  second.mesh.cadVolume = 50, second.mesh.cadEuler = 0;
  second.mesh.failures = {inverted()};
  const nlohmann::json secondAlone = toJson(second);
  MeshMeasures whole;
  whole.hexes = 200, whole.layers = 2, whole.quality.volume = 153;
  whole.boundary.eulerCharacteristic = 2;
  whole.cadVolume = 1, whole.cadEuler = 9, whole.failures = {inverted()};  // replaced by the solids' numbers
  const MeshReport merged = mergeSolids({first, second}, whole);
  EXPECT_EQ(merged.mesh.cadVolume, 150);
  EXPECT_EQ(merged.mesh.cadEuler, 2);
  ASSERT_EQ(merged.mesh.failures.size(), 1u);
  EXPECT_EQ(merged.mesh.failures[0].message, "solid 2: inverted: 3 inverted hexes");
  EXPECT_FALSE(merged.mesh.passed());
  const nlohmann::json j = toJson(merged);
  EXPECT_EQ(keysOf(j),
            (std::set<std::string>{"aspect_ratio", "boundary", "hexes", "inverted_hexes", "layers", "nodes", "order",
                                   "scaled_jacobian", "solids", "validation", "volume", "worst_hex_at"}));
  EXPECT_EQ(j["volume"], nlohmann::json({{"cad", 150.0}, {"mesh", 153.0}, {"relative_error", 0.02}}));
  EXPECT_EQ(j["boundary"]["cad_euler_characteristic"], 2);
  EXPECT_EQ(j["boundary"]["same_topology_as_cad"], true);
  EXPECT_EQ(j["validation"]["passed"], false);
  EXPECT_EQ(j["validation"]["failures"][0]["message"], "solid 2: inverted: 3 inverted hexes");
  ASSERT_EQ(j["solids"].size(), 2u);
  EXPECT_EQ(j["solids"][0], toJson(first));
  EXPECT_EQ(j["solids"][1], secondAlone);
  EXPECT_EQ(j["solids"][1]["validation"]["failures"][0]["message"], "inverted: 3 inverted hexes");
}

// The crease chains (quadmesh/crease_chains.hpp) are reported only for a piece that has a lap's crease.
TEST(Report, CreaseChainsOnlyWhereThereAreAny) {
  MeshReport r = solidReport();
  EXPECT_FALSE(toJson(r).contains("crease_chains"));
  r.creaseChains.chains = 1, r.creaseChains.dropped = 1, r.creaseChains.nodesMoved = 7;
  r.creaseChains.farthest = 0.25, r.creaseChains.worstQuad = 0.5;
  EXPECT_EQ(
      toJson(r)["crease_chains"],
      nlohmann::json({{"chains", 1}, {"dropped", 1}, {"nodes_moved", 7}, {"farthest", 0.25}, {"worst_quad", 0.5}}));
}
