// Structured block grids of the chordal surface, laid out in its map onto the plane
// (surface_map.hpp): every node regular except at the few block corners, so the quads are as square
// as the surface allows (§6, for the patches Gmsh would mesh unstructured).
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "quadmesh/surface_map.hpp"

namespace hexlayer {

using SizeField = std::function<double(const Vec3&)>;  // target quad edge length at a point (§6.1)

struct BlockGrid {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 4>> quads;  // counter-clockwise in the plane
  std::size_t blocks = 0;
  bool empty() const { return quads.empty(); }
};

// O-grid of a disc mapped onto the circle: a core of n0 x n1 quads and four blocks around it, each
// from a side of the core out to a quarter of the rim. Empty for any other map.
BlockGrid oGrid(const SurfaceMap& map, const SizeField& size);

// Grid of a surface mapped onto the square: n0 x n1 quads, and around each hole a pocket of four
// blocks, from the sides of a box of grid cells in to the quarters of the hole. Empty for any other
// map, or if two pockets meet or one reaches the rim.
BlockGrid holedGrid(const SurfaceMap& map, const SizeField& size);

// Ring grid of a surface mapped onto the annulus's rectangle (a tube, a ring): `around` x `across`
// quads evenly spaced in it (square where the map is conformal), the rim rows on the rims by arc
// length, periodic round the ring: every node is regular. Empty for any other map.
BlockGrid ringGrid(const SurfaceMap& map, const SizeField& size);

}  // namespace hexlayer
