// The report's JSON (every key described in docs/report.schema.json), written once from the typed MeshReport that
// the pipeline gathers: the one place where the stages' numbers get their keys.
#pragma once
#include <nlohmann/json.hpp>

#include "pipeline/mesh_report.hpp"

namespace hexlayer {

// [in] report: one solid's (every stage's key, "timings_s" and "peak_memory_mib"; "quadratic" and
// "aspect_ratio_hit" when set), or, with report.solids, the mesh of several solids (the mesh's own numbers and
// "solids", each solid's report as one alone). Returns the JSON object; its values as they are in `report`
// (toInputUnits converts the units before); "validation"."passed" is report.mesh.passed().
nlohmann::json toJson(const MeshReport& report);

}  // namespace hexlayer
