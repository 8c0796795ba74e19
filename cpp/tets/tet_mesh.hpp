// Tets (paper §4, §5.4): Delaunay tetrahedralization of the bubble nodes with TetGen, then the
// tets outside the solid and the flat tets (all four nodes on one side, Case 4-0 / 0-4) are dropped.
#pragma once
#include <array>
#include <vector>

#include "bubbles/bubble_packing.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"

namespace hexlayer {

class BoundaryTriangles;

struct TetMesh {
  std::vector<Vec3> nodes;
  std::vector<Side> side;  // Top or Bottom per node
  std::vector<std::array<int, 4>> tets;
};

struct TetFilterCounts {
  std::size_t delaunay = 0;  // tets of the Delaunay tetrahedralization (the convex hull)
  std::size_t outside = 0;   // dropped: centroid outside the solid, or a coplanar sliver in a rim face or on the hull
  std::size_t flat = 0;      // dropped: all four nodes on the same side (§5.4)
  std::size_t coplanar = 0;  // kept although of zero volume: four nodes in one plane (at bends)
};

// Four nodes in one plane: a tet of zero volume, as two top and two bottom bubbles on the parallel
// edges of a bend give. Inside the wall it is kept: it joins the tets on either side of that plane,
// and the chordal surface collapses its degenerate facet. On a rim face (two bubbles on each of the
// parallel rim edges of a rounded corner) it is a sliver of the hull, dropped like the flat ones.
// Bubbles on the rim edges of a rounded corner sit a little off the rim face (about 2e-4 mm on
// sheet_metal_54: 6 x volume = 9e-6 x longest edge cubed), so "in one plane" is 6 x volume at most
// 1e-4 x shortest edge x longest edge squared. Measured against the shortest edge, a tet with one
// tiny edge (the U-channel's 0.002 mm tunnels) is not flat for that edge alone.
bool isCoplanarTet(const std::array<Vec3, 4>& corners);

// Delaunay tetrahedralization of the nodes (TetGen 1.5, library call). Throws on TetGen failure.
TetMesh delaunayTets(const std::vector<SurfaceNode>& nodes);

// Keeps the tets inside the solid that span top and bottom (also those of zero volume); returns
// what was dropped. [in,out] mesh: its tets filtered; [in] cad; [in] triangles: its boundary's (built here if not
// given).
TetFilterCounts keepSpanningTetsInside(TetMesh& mesh, const CadSolid& cad);
TetFilterCounts keepSpanningTetsInside(TetMesh& mesh, const CadSolid& cad, const BoundaryTriangles& triangles);

}  // namespace hexlayer
