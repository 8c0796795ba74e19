// Smoothing of the poor hexes the rim leaves (after §7's sweep, the rim projection and the rim caps): where a
// rim is oblique, overhangs the wall or turns a corner, the hexes beside it are sheared more than the rim's
// own angle asks. Each node of a hex below kPoorHex is moved towards the mean of its neighbours along the
// hex edges, kept on its CAD face: a wall node slides on the walls of its side (one that lies on a lateral face off
// the rim, in the middle of the rounds of a step where the wall's thickness changes, on those walls and the lateral
// faces, the nearer), a rim node on the lateral faces, an inner node is free; the nodes on the CAD edges where walls
// meet the rim, and the caps' nodes, stay.
// A move is kept only if it raises the scaled Jacobian of the worst hex around the node, so no hex gets worse
// than the worst it was beside. The nodes of hexes still below kBadHex, and of the hexes around them, then take
// pattern-search steps (towards or away from each neighbour, the one that most lowers their hexes' squared shortfall
// below kSearchGoal), under the same rule and keeping their edges no shorter than kShortEdge of their mean: an
// inverted hex whose nodes must move away from their neighbours' mean to untangle it. In the search the nodes on the
// CAD edges where the walls meet the rim slide along those edges (a rim column drawn onto another where a rim
// turns a corner folds the hexes between them).
#pragma once
#include <cstddef>
#include <vector>

#include "core/types.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

struct SmoothingStats {
  std::size_t poorHexes = 0;               // hexes below kPoorHex before
  std::size_t nodesMoved = 0;              // Laplacian moves kept (a node may move in several rounds)
  std::size_t searchMoves = 0;             // pattern-search moves kept
  double worstBefore = 1, worstAfter = 1;  // scaled Jacobian of the worst hex
};

// [in,out] mesh: a linear layered mesh (nodeFace, nodeOnRim and nodeLayer sized); nodes moved, nodeFace of the
// nodes moved onto the CAD updated. [in] walls, sides: the nearest-point projector and the faces' sides. [in] pinned:
// per node, whether it stays where it is (a node a wall's foot shares, whose place the wall gives; empty: none).
SmoothingStats smoothPoorHexes(HexMesh& mesh, const WallProjector& walls, const WallSides& sides,
                               const std::vector<char>& pinned = {});

}  // namespace hexlayer
