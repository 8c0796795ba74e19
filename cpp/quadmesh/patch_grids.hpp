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
#include "quadmesh/chordal_patches.hpp"

namespace hexlayer {

// [in] chordal: the chordal surface (its facets turn counter-clockwise seen from the top); [in] size: the target
// quad size; [in] featureAngle: degrees, where the surface is cut (facePatches: a bend's strips narrower than a quad
// go to the faces beside it).
// The rim's curves are cut where they turn more than 45 degrees within a quad (a corner of the outline; a rim curve
// shorter than a quad joins its neighbour, its path cutting across it: the chordal rim's chord across a wall's
// corner, its step round a bend's end). A face's loops: the one with creases outside, the others holes along the rim.
// The outside loop has its corners where its curves turn into one another by 45 degrees or more (the others run on
// flat along a side: a side may be several curves); a face with fewer than four has its rim cut at rounded corners
// (45 degrees over three quads, else over six: a corner rounded R10 at 2 mm quads, its turn then measured over six
// quads too), one with a reflex corner is cut in two from it straight on into the face along the facets' edges (the
// curve it lands on split there). Every face must then have four corners turning 45 to 135 degrees (over three quads,
// or a round's six). A crease's path is its zigzag of facet edges averaged along it over a quad.
// Interval assignment: opposite sides of every face get as many segments, each curve at least what its measure needs
// (the side with fewer takes one more on its curve with the most measure per segment, round after round), placed at
// even shares of the curve's measure (the target size along it; if graded, twice as dense next to a crease ending on
// it away from the rim, fading over a quad): both faces of a curve take the same nodes. A face's nodes inside are a
// Coons patch of its four sides (bilinearly blended); a face with holes is mapped onto the square at its corners
// (mapOntoSquare) and gets holedGrid's pocket of four blocks round each hole on its sides' nodes (where two pockets
// would meet, sharedGrid's lines on its sides' nodes; a pinhole, shorter than a quad's edge, closed). The nodes are
// put on the chordal surface by the caller.
// Returns the grids of one layout (blocks: one per face and four per pocket; quads counter-clockwise seen from the
// top): with even rows, and graded unless that folds a quad against its face's normal; both empty if the surface has
// fewer than two faces, a face has no four corners, its holes have neither pockets nor a shared grid, or the sides'
// segments cannot match.
struct PatchGrids {
  BlockGrid graded, even;
};
// Which loops of a face become its four sides: those with four corners; or also those with five or six, the gentlest
// turns left inside its sides (a strip whose ends are two short curves each meeting at an angle, as a chamfer's
// chordal surface may be cut at a mitre): the last layout tried before Gmsh's quads.
enum class PatchSides { FourCorners, KinksInSides };
// [in] seeds, rims: facePatches' (PatchSeeds::FlatFirst where the faces grown in index order give no grid;
// PatchRims::FittedToNormals where those as grown give no acceptable grid: no grid if the fitting moves no triangle,
// the faces then being those as grown); [in] sides.
PatchGrids patchGrids(const ChordalSurface& chordal, const SizeField& size, double featureAngle,
                      PatchSeeds seeds = PatchSeeds::InOrder, PatchRims rims = PatchRims::AsGrown,
                      PatchSides sides = PatchSides::FourCorners);

}  // namespace hexlayer
