// Rim caps: the part of a rounded rim that lies beyond the sweep. The chordal surface (§5) ends where the
// medial surface does, on the axis of a full-round rim, so the sweep (§7) fills the wall up to the line
// joining the rim's edges and the rim projection lays the outermost column on the profile with layers + 1
// nodes: linear hexes cut a half-round profile with layers chords and leave out a lens of it (a fifth of the
// half disc with 3 layers, over a third with 2). Where the rim bulges that much, a cap fills the profile beyond
// the column: the sweep's outermost column goes back to the straight line between the rim's edges, and a quad
// mesh of the cross-section (cap_template.hpp: drawn for 2 and 3 layers, else structured) is laid on each
// column's profile, its hexes between neighbouring columns. Flat, chamfered and oblique rims, which lose little,
// are left as they are.
#pragma once
#include <cstddef>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

struct RimCapStats {
  std::size_t rimEdges = 0;     // edges of the chordal surface's rim (column pairs)
  std::size_t cappedEdges = 0;  // of those, capped
  std::size_t capColumns = 0;   // new columns of nodes
  std::size_t capHexes = 0;     // new hexes (capped edges x their template's quads)
};

// [in,out] mesh: a linear layered mesh after projectRim (rim_projection.hpp). Capped columns get their inner
// nodes back on the straight line between their ends (no longer on the boundary, nodeOnRim 0, unless the cap
// ends beside them); the cap nodes and hexes are appended: on the profile nodeOnRim kRimCap, nodeLayer the layer
// nearest their height, nodeFace the lateral face they lie on; inside nodeLayer -1, nodeOnRim 0 (kRimCap and
// on the side face where the cap ends beside a flat side face). [in] cad, sides: the solid and its faces' sides;
// [in] walls: the nearest-point projector on them.
// A rim edge is capped when linear hexes through its profile would leave out more than kMinLoss of the square of
// the wall's thickness and a cap halves that, and every cap hex has a scaled Jacobian >= kMinQuality; each chain
// of capped edges takes the structured cap, or the drawn one where that leaves the mesh's mean scaled Jacobian
// higher.
RimCapStats capRims(HexMesh& mesh, const CadSolid& cad, const WallSides& sides, const WallProjector& walls);

}  // namespace hexlayer
