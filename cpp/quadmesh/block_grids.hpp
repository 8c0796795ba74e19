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

// Grid of a triangle (a disc whose rim has three sharp corners, mapped onto the square with the middle of its longest
// side as the fourth corner: SurfaceMap::sideMiddle): three blocks, each from a corner to the centre, split at a point
// of each side (the centre the mean of the three), so that each corner keeps its angle in one quad and no quad has a
// side's straight angle (the square grid puts one at the fourth corner). Each block's cells as its sides need them
// (opposite sides alike: a spoke's as the two sides' parts across it), its spokes straight and its inside by
// transfinite interpolation in space, put on the surface by onSurface (the surface's point nearest to a point). Empty
// for any other map, or a triangle with holes.
BlockGrid triangleGrid(const SurfaceMap& map, const SizeField& size, const std::function<Vec3(const Vec3&)>& onSurface);

// Grid of a surface mapped onto the square: n0 x n1 quads, and around each hole a pocket of four
// blocks, from the sides of a box of grid cells in to the quarters of the hole. Empty for any other
// map, or if two pockets meet or one reaches the rim.
BlockGrid holedGrid(const SurfaceMap& map, const SizeField& size);

// A square map's rim as given nodes: n0 x n1 cells, and the rim's points along its walk from corner 0 (n0 from
// corner 0 to corner 1, n1 on to corner 2, n0, n1 back to corner 0).
struct SquareRim {
  int n0 = 1, n1 = 1;
  std::vector<LoopPoint> points;
};

// holedGrid with its rim's nodes given (a face of the patch grid, sharing its sides' nodes with the faces beside it):
// the grid's lines where the given points put them, its rim nodes at the points, first in its nodes in their order;
// a pocket that would leave the grid has its box's side on the rim instead (a hole within a cell of the rim: a bend
// relief at the face's corner). [in] map: the square map; [in] size: the target size; [in] rim: 2 (n0 + n1) points.
// Empty if two pockets meet or a hole has no four corners in turn, or the points are not as many as the rim's
// cells.
BlockGrid holedGrid(const SurfaceMap& map, const SizeField& size, const SquareRim& rim);

// Grid of a surface mapped onto the square with holes whose pockets would meet or reach the rim (issue 19): one
// tensor grid over the square, its lines through every hole's sides and spaced by the quads the target size needs
// between them, averaged over the rim's two sides along each axis (one cell at the least). A rectilinear hole
// (runs of its edges along one axis each, within half a quad of their side's line, its area within 5 % of their
// polygon's: a cutout, its notches too, where the chordal rim may cut a corner) is the block of cells inside its
// sides' lines left out, the nodes on its sides moved onto its loop, corners on corners (a layout traced from the
// holes' corners on to the rim, as a motorcycle graph's, every node inside regular); any other hole gets
// holedGrid's pocket, its box one quad beyond the hole where there is room, else half way to the next hole, on the
// rim if it would come within half a quad of it, its ring's nodes on the hole where spokes from the hole's centre
// through the box's nodes cross it. Lines of sides that do not face each other (pieces of a side a notch splits,
// holes in a row) within 0.35 quad are merged; a pocket's side within half a quad of a rim or side line is moved onto
// it, the pockets' sides left within half a quad of each other (holes in a row, neighbours' boxes meeting half way)
// onto their mean together.
// [in] map: the square map; [in] size: the target size. Returns the grid (blocks: 1 and 4 per pocket); empty for
// any other map, a surface without holes, or where two holes' extents overlap along both axes.
BlockGrid sharedGrid(const SurfaceMap& map, const SizeField& size);

// sharedGrid with its rim's nodes given (a face of the patch grid whose holes' pockets meet, sharing its sides' nodes
// with the faces beside it): as many lines as the rim's cells, the rim's lines (holedGrid's with a given rim) moved
// onto the holes' sides and the pockets' boxes, each onto the nearest line not yet taken, the lines between moved with
// them; its rim nodes at the points, first in its nodes in their order. [in] map, size; [in] rim: 2 (n0 + n1) points.
// Empty where sharedGrid is, or if the holes' sides and boxes need more lines than the rim has.
BlockGrid sharedGrid(const SurfaceMap& map, const SizeField& size, const SquareRim& rim);

// Ring grid of a surface mapped onto the annulus's rectangle (a tube, a ring): `around` x `across`
// quads evenly spaced in it (square where the map is conformal), the rim rows on the rims by arc
// length, periodic round the ring: every node is regular; `around` quads round if given (> 0), else as many as the
// longer rim holds at the size, even. Empty for any other map.
BlockGrid ringGrid(const SurfaceMap& map, const SizeField& size, int around = 0);

}  // namespace hexlayer
