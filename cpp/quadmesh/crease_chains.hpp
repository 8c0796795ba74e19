// Quads made to follow creases of the walls (issue 18's laps): where a boss merged into a box's wall is cut off along
// the wall, its outer side is its cylinder and a flat lying on the wall, and the wall's hexes are joined to the
// boss's faces on the flat only if none of those faces straddles the crease between them (sweep/sharp_edges.hpp puts
// the hex nodes nearest a crease on it, but a quad crossed by it obliquely keeps a corner on either side, or is cut
// along a diagonal). Each crease, put on the chordal surface, is followed by a chain of the quads' edges: the path
// between the quad nodes nearest its ends whose edges lie nearest it (Dijkstra, each edge's length weighted by its
// middle's distance from the crease, a turn inside a quad avoided: its three nodes on the crease would flatten it),
// whose inner nodes are put on it, the quads round it smoothed with the chains fixed. The quads on either side then lie
// on one face each, and the sweep lines from the chain end on (near) the crease. A chain whose quads would end poorer
// than 0.2 (a crease midway between grid lines near a rim node on its end, where the chain must turn) is dropped: the
// quads are left as they were. The quad stage ranks a layout with a dropped chain after those that follow every crease
// (quad_mesh.hpp QuadMeshOptions::creases).
#pragma once
#include <cstddef>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

struct CreaseChainStats {
  std::size_t chains = 0;      // creases followed
  std::size_t dropped = 0;     // creases not followed: the quads round their chain too poor (kFloor)
  std::size_t nodesMoved = 0;  // chain nodes put on a crease
  double farthest = 0;         // the longest move, in units of the mean quad edge
  double worstQuad = 1;        // the worst scaled Jacobian of the quads round the moved nodes, after
};

// [in,out] quads: on the chordal surface, the chains' inner nodes moved and the others smoothed (rim nodes slide along
// the rim); [in] chordal; [in] creases: polylines near the walls (wall_sides.hpp lapCreases), each put on the chordal
// surface (its points' nearest) before its chain is found. Where a crease ends within half a mean quad edge of
// the chordal surface's rim, its chain ends at the quads' rim node nearest the rim's point nearest the crease's end,
// slid along the rim to that point (not a corner of the quads' rim, turning over 30 degrees there: it stays); the
// chain's other rim nodes stay (the rim's capture, sharp_edges.hpp, puts the column nearest each CAD edge's end on
// it).
CreaseChainStats followCreases(QuadMesh& quads, const ChordalLocator& chordal,
                               const std::vector<std::vector<Vec3>>& creases);

}  // namespace hexlayer
