// The report's JSON (every key described in docs/report.schema.json), written from each stage's typed result:
// the one place where the stages' numbers get their keys. The pipeline runs the stages and hands their results
// here; lengths are in the pipeline's units unless a writer takes `unit` (pipeline lengths per input length).
#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "chordal/chordal_rim.hpp"
#include "chordal/chordal_surface.hpp"
#include "core/memory.hpp"
#include "geometry/wall_sides.hpp"
#include "quadmesh/quad_stage.hpp"
#include "quality/quality.hpp"
#include "quality/validation.hpp"
#include "sweep/quadratic.hpp"
#include "sweep/rim_cap.hpp"
#include "sweep/rim_projection.hpp"
#include "sweep/smoothing.hpp"
#include "sweep/untangle.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer::report {

nlohmann::json faces(const WallSides& sides);                                  // "faces"
nlohmann::json memory(const MemoryEstimate& m);                                // "memory_estimate"
nlohmann::json tets(const TetFilterCounts& dropped, std::size_t kept);         // "tets"
nlohmann::json chordal(const ChordalSurface& cut);                             // "chordal_surface" as cut
nlohmann::json chordalRim(const RimSnapStats& s, double unit);                 // "chordal_surface"."rim"
nlohmann::json smallFeatures(const SmallFeatures& s);                          // "small_features"
nlohmann::json quadMesh(const QuadMesh& q);                                    // "quad_mesh"
nlohmann::json sweep(const UntangleResult& u, const RimProjectionStats& rim);  // "sweep"
nlohmann::json rimCap(const RimCapStats& s);                                   // "rim_cap"
nlohmann::json smoothing(const SmoothingStats& s);                             // "smoothing"
nlohmann::json quadratic(const QuadraticStats& s);                             // "quadratic"
nlohmann::json validation(const std::vector<ValidationFailure>& failures);     // "validation"

// The mesh's own numbers: "order", "hexes", "nodes", "layers", "inverted_hexes", "worst_hex_at",
// "scaled_jacobian", "aspect_ratio", "volume" (against cadVolume), "boundary" (without the CAD's Euler
// characteristic, added by the pipeline), "validation".
void writeMesh(const HexMesh& mesh, const QualityReport& q, const BoundaryCheck& b, double cadVolume,
               const std::vector<ValidationFailure>& failures, nlohmann::json& r);

}  // namespace hexlayer::report
