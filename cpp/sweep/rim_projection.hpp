// The rim of the hex mesh onto the lateral faces ω_l (paper §3). The sweep (§7) puts the nodes of a
// rim column on the straight sweep line of a chordal rim point, which ends near the edges where the
// walls meet the rim and runs inside a rounded, chamfered or oblique rim face. Here every rim column
// is laid onto the rim's profile: its two ends onto the lateral faces (on the edges of the walls), its
// inner nodes evenly between them, then each along the rim's outward direction onto the lateral faces.
#pragma once
#include <cstddef>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// The columns of nodes swept from the chordal surface's rim, each from the bottom (layer 0) to the top: the
// nodes above one another in the hexes (corners k, k + 4), in the order of their bottom nodes.
std::vector<std::vector<int>> rimColumns(const HexMesh& mesh);

struct RimProjectionStats {
  std::size_t rimNodes = 0;        // nodes swept from the chordal surface's rim
  std::size_t onLateralFaces = 0;  // of those, put on a lateral face
  std::size_t columnsKept = 0;     // columns left where the sweep put them: moving them would spoil a hex
};

// [in,out] mesh: rim nodes moved onto the lateral faces, their nodeFace set to the face they are on.
// [in] cad, sides: the solid and its faces' sides; [in] walls: the nearest-point projector on them.
// [in] reach: how far a node may move (1.6 walls in the pipeline: half the width of the most oblique rim).
// The column nearest a sharp CAD edge between two lateral faces is laid along it; where rim columns lean (an
// oblique cut), the columns beside them move with them, fading over a few rows (their nodes moved too): sheared
// like the rim's where its wall nodes move the same way, shifted upright where they move apart.
// A column stays where the sweep put it if a hex around it would end below a scaled Jacobian of 0.2
// and be worse than before, with all other columns moved (whatever the order of the columns).
RimProjectionStats projectRim(HexMesh& mesh, const CadSolid& cad, const WallSides& sides, const WallProjector& walls,
                              double reach);

}  // namespace hexlayer
