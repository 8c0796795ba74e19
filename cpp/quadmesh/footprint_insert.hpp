// Walls standing on a sheet (issue 18; ../shared/design/junctions.md §3): the sheet's quad mesh made to carry their
// feet. Seen from the sheet, a standing wall's foot is a strip of quads (its layers across, its quads along; a ring
// for a boss) whose nodes are fixed: under them the sheet's hexes must end on the wall's hex nodes. The sheet's
// quads near a footprint are taken out, and the gap between the quads kept and the footprint is meshed again with
// quads in the gap unfolded onto the plane (least-squares conformal map: a gap on a curved sheet or across a bend is
// meshed as a flat one; Gmsh, every boundary node fixed: the kept quads', the footprint's, and the sheet's rim,
// divided again where a footprint reaches it; a ring between a footprint and a hole through the sheet inside it, one
// row of quads from the footprint's nodes to as many placed anew on the hole's rim). The footprint's quads are then the
// sheet's, node for node, whatever the sheet's outline, holes or quad layout.
#pragma once
#include <Eigen/Core>

#include <array>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "core/child_process.hpp"
#include "core/types.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// The footprints of the walls standing on a sheet, on its chordal surface.
struct FootprintQuads {
  std::vector<Vec3> nodes;                // on the sheet's chordal surface
  std::vector<std::array<int, 4>> quads;  // each foot a strip (or a ring) of them, any orientation
};

// The footprint put on the sheet's chordal surface: each node where the line through it along the sheet's wall normal
// there (its footprint quads' mean normal: the foot lies on the wall) meets the surface, as the sheet's sweep lines
// run (sweep_to_walls.hpp aims them across the walls), so that the sweep line from there ends at the node also where
// the chordal facets stand oblique to the walls (a bend's facets, coarser than the bend).
// [in] footprint: on the sheet's wall; [in] chordal. Returns it on the chordal surface.
FootprintQuads onChordalSurface(FootprintQuads footprint, const ChordalLocator& chordal);

// Walls standing on both sides of a sheet at one place (ribs crossing: the crossed rib's segments on the two walls of
// the rib running through) have one footprint on the chordal surface, whose sweep columns end at one wall's foot node
// and at the other's: two feet that overlap there and are alike (as many nodes, each node of one within a fifth of
// the footprint's shortest edge of one of the other once moved by the shift between their centroids, which is not
// zero where the ribs cross obliquely) are merged, each pair of nodes at its middle put back on the surface.
struct MergedFootprints {
  FootprintQuads footprint;  // the feet merged
  std::vector<int> node;     // per footprint node given, its node in `footprint`
  double shift = 0;          // the largest distance of a node given from its merged node (half a pair's offset)
};
// [in] footprint: on the chordal surface (onChordalSurface); [in] chordal.
MergedFootprints mergeFeetOnBothSides(const FootprintQuads& footprint, const ChordalLocator& chordal);

struct FootprintInsertion {
  QuadMesh quads;                                 // the sheet's quads carrying the footprints
  std::vector<int> node;                          // per footprint node, its node in `quads`
  std::size_t quadsRemoved = 0, quadsMeshed = 0;  // the sheet's quads taken out, the gap's quads meshed again
  double worstQuad = 1;                           // the gap's worst quad's scaled Jacobian
};

// [in] sheet: the sheet's quads (quad_mesh.hpp); [in] footprint; [in] chordal: the sheet's chordal surface, where
// the gap's new nodes are put; [in] size: the sheet's quad size (the gap is two quads wide round each footprint, three
// or four where the quads Gmsh can make in the narrower one are poor: the widest's worst quad best); [in] server:
// forks the gaps' Gmsh runs (child_process.hpp; null: this process does).
// Returns the quads: the kept ones first (their nodes in their order), then the gap's and the footprint's.
// Throws geometryError saying why if a footprint does not lie on the sheet, footprints overlap, the gap round one
// does not unfold onto the plane, or Gmsh cannot fill it with quads.
FootprintInsertion insertFootprints(const QuadMesh& sheet, const FootprintQuads& footprint,
                                    const ChordalLocator& chordal, double size, ForkServer* server = nullptr);

// [in] nodes: in the plane z = 0; [in] quads. Returns the quads' worst scaled Jacobian, negative for a clockwise one
// (turned over) or a bow tie.
double worstInPlane(const std::vector<Vec3>& nodes, const std::vector<std::array<int, 4>>& quads);

// Quads filling a polygon in the plane (with holes), every boundary node fixed, as the gaps round feet are filled:
// Gmsh's 2D algorithms side by side, Blossom's recombination, the one whose worst quad is best (the first of equals).
// A column's foot (column_sweep.hpp). [in] at: the loops' points; [in] loops: the outer loop counter-clockwise, then
// the holes clockwise, an even number of edges in all; [in] server: forks the Gmsh runs (null: this process does).
// Returns the quads (counter-clockwise), their first at.size() nodes the given points (z = 0). Throws geometryError if
// no algorithm fills the polygon with quads alone.
QuadMesh quadsInPolygon(const std::vector<Eigen::Vector2d>& at, const std::vector<std::vector<int>>& loops,
                        ForkServer* server = nullptr);

}  // namespace hexlayer
