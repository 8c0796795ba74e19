// The quad mesh of a flat rectangular sheet that carries a rib's footprint (issue 18; design/junctions.md §3): a
// tensor-product grid of the sheet's chordal plane whose lines through the footprint are the rib's foot columns and
// rows, so that the footprint is a strip of exactly rows x columns quads, node for node under the rib's foot nodes.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// The sheet and the foot in a frame of the chordal plane: u along the rib's foot, v across it.
struct Footprint {
  Vec3 origin = Vec3::Zero();                     // a point of the chordal plane: (u, v) = (0, 0)
  Vec3 u = Vec3::UnitX(), v = Vec3::UnitY();      // unit and orthogonal, in the plane
  double uMin = 0, uMax = 0, vMin = 0, vMax = 0;  // the sheet's rectangle
  std::vector<double> columns;                    // u of the foot's M + 1 columns, ascending
  std::vector<double> rows;                       // v of its N_r + 1 rows (the rib's layers + 1), ascending
  double size = 0;                                // quad edge length outside the footprint
  // (u, v) of each foot node, feet[i][j] at row i, column j: where the strip's nodes are put (a rib's sweep
  // columns may lean, its foot nodes off their lines); empty: at the lines.
  std::vector<std::vector<Eigen::Vector2d>> feet;
};

struct FootprintGrid {
  QuadMesh quads;                       // the grid, its quads counter-clockwise seen along u x v
  std::vector<std::vector<int>> strip;  // strip[i][j]: the quad node at the foot's row i, column j
};

// [in] f: the sheet's rectangle and the foot inside it (the foot may reach the rectangle's sides: its first or last
// column or row on them within 1e-6 of the rectangle's width, where the grid then has no line of its own).
// Returns the grid: between the foot and the sides, lines evenly spaced about f.size apart; the strip's nodes at
// f.feet if given.
// Throws geometryError if the foot is not inside the rectangle or has fewer than two columns or rows.
FootprintGrid footprintGrid(const Footprint& f);

}  // namespace hexlayer
