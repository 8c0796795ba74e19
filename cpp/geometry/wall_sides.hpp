// Which faces of a thin solid are its top (ω_t), bottom (ω_b) and lateral (ω_l) surfaces (paper §3),
// and how thick the wall is. The user gives neither: both are measured here by casting rays.
#pragma once
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"

namespace hexlayer {

struct FaceSide {
  Side side = Side::Lateral;
  double thickness = 0;  // area-weighted median distance to the opposite wall along the inward normal
  double width = 0;      // 2 * area / perimeter: about the wall thickness for a lateral (rim) face
  double area = 0;
  int opposite = -1;     // 0-based index of the face most rays hit, -1 if none
};

struct WallSides {
  std::vector<FaceSide> faces;  // indexed like CadSolid::faces, 0-based (FreeCAD's Face<i+1>)
  double thickness = 0;         // area-weighted median over top and bottom faces
  double sheetAreaShare = 0;    // area of top + bottom over the whole boundary
  std::vector<std::pair<int, int>> sheetJoins;  // faces sharing a smooth or convex edge (sheet_edges.hpp)
};

// Measures the wall and sorts the faces into top, bottom and lateral.
//  - A face is a wall face (top or bottom) when rays cast inward along its normal cross the wall
//    (median length `thickness`) before they could cross the face itself (`width`); a lateral
//    face is as wide as the wall is thick, while rays from it run along the wall, far.
//  - Wall faces that share an edge are on the same side; a face and the face its rays hit are on
//    opposite sides. A parity union-find solves these constraints; the side whose faces look
//    more towards +z is called Top.
// Throws geometryError when the part is not a thin section or its sides cannot be told apart.
WallSides classifyWallSides(const CadSolid& cad);

// CAD features smaller than the quad size, which the quad mesh may smooth over: edges of the top
// and bottom walls shorter than `size` (a small hole's rim, a short edge), faces narrower than it
// (walls) or than half the wall thickness (lateral faces): slivers, small fillets and chamfers.
struct SmallFeatures {
  int shortEdges = 0, narrowFaces = 0;  // narrowFaces: wall or lateral
  Vec3 firstAt = Vec3::Zero();  // the middle of the first such edge, else a point of the first such face
};
SmallFeatures findSmallFeatures(const CadSolid& cad, const WallSides& sides, double size);

}  // namespace hexlayer
