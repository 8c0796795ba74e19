// Sharp edges of the walls captured (after §7's sweep and the smoothing). Where two faces of one wall meet in a sharp
// edge (a bend without an outside round, the two edges of a chamfered bend's outside, its inside corner), the quad
// mesh's rows need not run along it: a wall's quad edge crossing it from one face to the other cuts its corner off
// (a convex edge: volume lost) or bridges it (a concave one: volume added). The end of such an edge nearer to the CAD
// edge, when no farther from it than kMaxReach of the quad edge, is moved onto it, the nodes of its column with it
// (less towards the other wall, not at all at it), if no hex round the column then has a scaled Jacobian below the
// lower of kFloor and the worst it had. Where such an edge ends on a rim (a lateral face: a boss's flat merged into a
// box's wall meets the boss's top and its foot, a bend without an outside round meets the box's rim), the rim's quad
// edges cross it there, and the rim's wall node on one of its faces nearest its end, within kMaxReach of its rim edge,
// is put on that end the same way (a boss's hexes straddling its flat's edge at its top lay on the wall's unjoined).
#pragma once
#include <cstddef>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

struct SharpEdgeStats {
  std::size_t edges = 0;       // sharp edges between two faces of one wall
  std::size_t nodesMoved = 0;  // wall nodes put on them (their columns moved with them)
  std::size_t nodesKept = 0;   // wall nodes that would have been, but a hex round their column got too poor
};

// [in,out] mesh: a linear layered mesh (nodeFace, nodeOnRim and nodeLayer sized); nodes moved, nodeFace of the wall
// nodes put on an edge set to one of its faces. [in] cad, sides: the solid and its faces' sides.
SharpEdgeStats captureSharpEdges(HexMesh& mesh, const CadSolid& cad, const WallSides& sides);

}  // namespace hexlayer
