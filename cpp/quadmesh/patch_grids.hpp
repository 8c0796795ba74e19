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

// [in] chordal: the chordal surface (its facets turn counter-clockwise seen from the top); [in] size: the target
// quad size; [in] featureAngle: degrees, where the surface is cut (facePatches: a bend's strips narrower than a quad
// go to the faces beside it).
// The rim's curves are cut where they turn more than 45 degrees within a quad (a corner of the outline; a rim curve
// shorter than a quad joins its neighbour: the chordal rim's chord across a wall's corner). Every face must then be
// a disc bounded by four curves turning into one another by 45 to 135 degrees (over up to three quads), no curve
// twice. A crease's path is its zigzag of facet edges averaged along it over a quad. Opposite curves get as many
// segments, the most any curve of their chain of faces needs (interval assignment: a union-find of opposite curves),
// placed at even shares of the curve's measure (the target size along it; if graded, twice as dense next to a crease
// ending on it away from the rim, fading over a quad): both faces of a curve take the same nodes. A face's nodes
// inside are a Coons patch of its four sides (bilinearly blended), put on the chordal surface by the caller.
// Returns the grids of one layout (blocks: one per face; quads counter-clockwise seen from the top): with even rows,
// and graded unless that folds a quad against its face's normal; both empty if the surface has fewer than two faces
// or a face is not four-sided.
struct PatchGrids {
  BlockGrid graded, even;
};
PatchGrids patchGrids(const ChordalSurface& chordal, const SizeField& size, double featureAngle);

}  // namespace hexlayer
