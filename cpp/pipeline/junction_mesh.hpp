// The first junction meshed all-hex and conformal (issue 18; ../shared/design/junctions.md): a T where a straight
// planar rib stands on a flat rectangular plate. The part is cut at the rib's foot (junction_cut.hpp); the rib's
// piece is meshed as one sheet, and its rim nodes on the foot form a grid of (layers + 1) rows x (M + 1) columns;
// the plate's quad mesh is a grid carrying that footprint (footprint_grid.hpp), and the plate's swept nodes under
// the foot are the rib's foot nodes, by id (append.hpp's joinHexMesh). Every hex is a hex of one sheet.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/junction_cut.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_sides.hpp"
#include "quadmesh/footprint_grid.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// The T in a frame of the plate: u along the rib's foot, v across it, w the plate's normal towards the wall the
// rib stands on; a point p has the coordinates (p·u, p·v, p·w).
struct TJunctionFrame {
  Footprint plate;  // origin (on the plate's mid-plane: its chordal surface), u, v and the plate's rectangle
  Vec3 w = Vec3::UnitZ();
  double footW = 0;      // the foot's plane: p·w
  double thickness = 0;  // the plate's
};

// [in] cad; [in] sheets: findSheets's (the plate, then the rib); [in] cut: cutAtJunctions's of them.
// Returns the frame. Throws geometryError saying why if the part is not such a T: two sheets and one foot, the
// plate's piece a box (planar faces, its volume its extent's in the frame), the rib's walls on parallel planes
// standing across the plate.
TJunctionFrame tJunctionFrame(const CadSolid& cad, const std::vector<Sheet>& sheets, const JunctionCut& cut);

// The rib's foot as the rib's hexes have it.
struct FootGrid {
  std::vector<std::vector<int>> nodes;           // nodes[i][j]: the rib's hex node at row i (v ascending), column j (u)
  std::vector<double> columns, rows;             // their u and v in the frame, each the mean over its nodes
  std::vector<std::vector<Eigen::Vector2d>> at;  // at[i][j]: (u, v) of node [i][j]
};

// [in] rib: hexes swept from `quads` (sweep.hpp's layout: quad node q's sweep column is the hex nodes q (m + 1) + k,
// k = 0..m); [in] quads; [in] frame. Returns the foot grid: the sweep columns lying on the foot's plane (within a
// thousandth of the plate's layer), ordered along u. Throws geometryError if they are fewer than two, or not a chain
// of quad edges.
FootGrid footGrid(const HexMesh& rib, const QuadMesh& quads, const TJunctionFrame& frame);

// The plate's rectangle with the foot's columns, rows and nodes, quads outside it as long as the foot's mean column
// spacing, all scaled by `unit` (the plate piece's CadSolid::unit). [in] frame, foot, unit.
Footprint footprintOf(const TJunctionFrame& frame, const FootGrid& foot, double unit);

// Per node of the plate's hexes, the rib's node it is, or -1: for every foot node (i, j) the end of the sweep
// column of strip[i][j] (footprintGrid's) nearer to it, and for 20-node hexes the mid-edge node of every plate
// edge between two of them the rib's mid-edge node of that edge. [in] plate: swept from the footprint grid, as many
// layers as the rib, of the same order; [in] strip; [in] rib, foot; [in] tolerance: how far such an end may be from
// its foot node. Throws geometryError with the distance if one is farther (the plate's walls do not meet the rib's
// foot there), or if an edge on the foot is not a rib's edge.
std::vector<int> footNodesShared(const HexMesh& plate, const std::vector<std::vector<int>>& strip, const HexMesh& rib,
                                 const FootGrid& foot, double tolerance);

// The junction hexes: those with a corner among `footNodes`, and their scaled Jacobian's min and mean.
struct JunctionHexes {
  std::size_t hexes = 0;
  double minScaledJacobian = 0, meanScaledJacobian = 0;
};

// [in] mesh; [in] scaledJacobian: per hex; [in] footNodes: node ids. Returns the junction hexes' numbers.
JunctionHexes junctionHexes(const HexMesh& mesh, const std::vector<double>& scaledJacobian,
                            const std::vector<int>& footNodes);

}  // namespace hexlayer
