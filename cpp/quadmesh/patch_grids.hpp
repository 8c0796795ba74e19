// Structured grids of the chordal surface cut at its creases (§6; issue 19's crease-aligned layout). A sheet bent
// along sharp edges (an open box, a U-channel or a bracket bent without a round, a wall standing on a floor) has a
// chordal surface that turns at each bend within a facet or two. One grid over the whole surface (block_grids.hpp)
// shears its quads round the bends, Gmsh's quads fan round them (and fold where the patches it makes are poor). Cut
// at its creases into faces (chordalPatches), each face bounded by four curves is one structured grid, the grids
// conforming along the creases: node rows run along every bend, every node is regular but where three faces meet
// (a box's corner: three quads round it, as the part has).
#pragma once
#include "chordal/chordal_surface.hpp"
#include "quadmesh/block_grids.hpp"

namespace hexlayer {

// [in] chordal: the chordal surface (its facets turn counter-clockwise seen from the top, normals set);
// [in] size: the target quad size; [in] featureAngle: degrees, where the surface is cut (chordalPatches).
// The patches' curves are cut where they turn more than 45 degrees within a quad (a rim's corner); every patch must
// then be a disc bounded by four curves whose ends turn by 45 to 135 degrees, no curve twice. Opposite curves get as
// many segments, the most any curve of their chain of patches needs at the target size (interval assignment: a
// union-find of opposite curves), spaced evenly by arc length: both patches of a curve take the same nodes. A patch's
// nodes inside are evenly spaced in its map onto the square (mean value weights, its sides by arc length, so that its
// curves' nodes lie on the square's sides where the grid puts them).
// Returns the grid (blocks: one per patch; quads counter-clockwise seen from the top); empty if the surface has
// fewer than two patches or a patch is not four-sided.
BlockGrid patchGrid(const ChordalSurface& chordal, const SizeField& size, double featureAngle);

}  // namespace hexlayer
