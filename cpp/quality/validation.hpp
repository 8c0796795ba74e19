// Validation of a finished mesh before it is written (issue 5): every element a proper hex, none
// inverted, conformal, a watertight boundary, and the volume of the CAD solid. A failed check says
// what and where, so that no bad mesh reaches a solver silently.
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
  std::string check;       // "hexes", "inverted", "conformal", "watertight" or "volume"
  std::size_t count = 0;   // how many elements, node pairs or edges fail (1 for the volume)
  std::optional<Vec3> at;  // where: the worst or first offender (none for the volume)
  std::string message;     // one sentence naming the check, the count and the place
};

// Runs every check on the corners of the hexes; q and b are the mesh's measured quality and boundary.
std::vector<ValidationFailure> validateMesh(const HexMesh& mesh, const QualityReport& q, const BoundaryCheck& b,
                                            double cadVolume);

}  // namespace hexlayer
