// A column's hexes (issue 18; column_piece.hpp): its foot's quads swept up its axis to its caps, as a sheet's quads
// are swept across its wall (§7): every quad node's column of layers + 1 hex nodes runs straight from the foot to
// the cap, the outline's columns on the column's sides.
#pragma once
#include "core/types.hpp"
#include "geometry/column_piece.hpp"
#include "geometry/wall_projector.hpp"
#include "quadmesh/column_foot.hpp"

namespace hexlayer {

// Each outline node's column ends on the edges where the caps meet the sides (the nearest point to the node raised
// to the column's height: on a cone, round its axis), each inner node's at the caps, where its place raised by the
// outline's ends at its mean value coordinates in the outline (Floater) projects (exact for a straight or tapered
// column), or, where that point lies sideways from it (a domed cap, whose nearest point lies out towards its rim),
// where the line up the axis through it meets a cap; the nodes between are evenly spaced along the column, the
// outline's then projected onto the sides. [in] cad: the column's piece; [in] foot: columnFootQuads's; [in] column;
// [in] walls: the column's faces as walls (Bottom its foot, Top its caps, Lateral its sides); [in] layers: along the
// axis (>= 1). Returns the hexes in sweep.hpp's layout (quad node q's column is the hex nodes q (layers + 1) + k),
// nodeFace set where a node was put on a face (the foot's nodes on it). Throws geometryError if the caps or sides
// cannot be reached from a node.
HexMesh sweepColumn(const CadSolid& cad, const ColumnFoot& foot, const ColumnPiece& column, const WallProjector& walls,
                    int layers);

}  // namespace hexlayer
