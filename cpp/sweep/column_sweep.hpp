// A column's hexes (issue 18; column_piece.hpp): its foot's quads swept up its axis to its caps, as a sheet's quads
// are swept across its wall (§7): every quad node's column of layers + 1 hex nodes runs straight from the foot to
// the cap, the outline's columns on the column's sides.
#pragma once
#include "core/types.hpp"
#include "geometry/column_piece.hpp"
#include "geometry/wall_projector.hpp"
#include "quadmesh/column_foot.hpp"

namespace hexlayer {

// A column's tiers along its axis: one up to each ledge's height (ColumnPiece::ledges, equal heights one tier), the
// last up to its caps. Each gets about as many layers as its height holds quads of `size`, one at least.
struct ColumnTiers {
  std::vector<double> top;  // per tier, its top's height over the foot's plane (the last: the column's height)
  std::vector<int> layers;  // per tier, its layers along the axis
};
ColumnTiers columnTiers(const ColumnPiece& column, double size);

// Each foot quad's hexes go up to the cap above its middle (the line up the axis from it): to the top of that ledge's
// tier, or through every tier to the caps that end the column. A node's column goes as high as its quads' hexes; it
// passes each tier's top at that height (a step's node, at its ledge's edge, then up the step's side).
// Each outline node's column ends on the edges where the caps meet the sides (the nearest point to the node raised
// to the column's height: on a cone, round its axis), each inner node's at the caps, where its place raised by the
// outline's ends at its mean value coordinates in the outline (Floater) projects (exact for a straight or tapered
// column), or, where that point lies sideways from it (a domed cap, whose nearest point lies out towards its rim),
// where the line up the axis through it meets a cap (in a column with ledges: always); a ledge's nodes on it raised
// along the axis; the nodes between are evenly spaced along each tier, those on a side then projected onto it.
// [in] cad: the column's piece; [in] foot: columnFootQuads's; [in] column; [in] walls: the column's faces as walls
// (Bottom its foot, Top its caps, Lateral its sides); [in] tiers: columnTiers's. Returns the hexes, each node's column
// in turn, bottom to top (nodeLayer: its layer; in a column of one tier, sweep.hpp's layout: quad node q's column is
// the hex nodes q (layers + 1) + k), nodeFace set where a node was put on a face (the foot's nodes on it). Throws
// geometryError if the caps or sides cannot be reached from a node.
HexMesh sweepColumn(const CadSolid& cad, const ColumnFoot& foot, const ColumnPiece& column, const WallProjector& walls,
                    const ColumnTiers& tiers);

}  // namespace hexlayer
