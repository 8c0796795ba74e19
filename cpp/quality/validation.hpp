// Validation of a finished mesh before it is written (issue 5): every element a proper hex, none
// inverted, conformal, no two pieces lying face to face unjoined, a watertight boundary, the volume of the CAD solid
// and no hole the CAD solid does not have (its Euler characteristic). A failed check says what and where, so that no
// bad mesh reaches a solver silently.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "quality/quality.hpp"

namespace hexlayer {

// Largest accepted |mesh volume - CAD volume| / CAD volume.
inline constexpr double kMaxVolumeError = 0.05;

struct ValidationFailure {
  std::string check;       // "hexes", "inverted", "conformal", "joined", "watertight", "volume" or "topology"
  std::size_t count = 0;   // how many elements, node pairs, faces, edges or holes fail (1 for the volume)
  std::optional<Vec3> at;  // where: the worst or first offender (none for the volume and the topology)
  std::string message;     // one sentence naming the check, the count and the place
};

// Runs every check on the corners of the hexes. [in] q, b: the mesh's measured quality and boundary; [in] cadVolume;
// [in] cadEuler: the CAD boundary's Euler characteristic (none: not compared). A watertight boundary whose Euler
// characteristic is below the CAD's has a hole (a tunnel) the part does not have: refused. One above it fills holes
// of the part (a bend relief narrower than a quad): not refused here, the caller reports it.
std::vector<ValidationFailure> validateMesh(const HexMesh& mesh, const QualityReport& q, const BoundaryCheck& b,
                                            double cadVolume, std::optional<long> cadEuler);

}  // namespace hexlayer
