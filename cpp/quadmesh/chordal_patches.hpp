// Patches of the chordal surface cut by HexLayer for Gmsh (§6), where Gmsh's own classification fails: on a
// sheet bent sharply (a box, a U-channel without bend rounds) the chordal surface turns in a few facets at each
// bend, Gmsh's patches between its feature edges touch themselves at a vertex ("pinched"), and its
// reparametrization refuses them ("Wrong topology of boundary mesh for parametrization": a patch's rim must be
// simple loops). These patches are made so that each one's rim is: no patch meets itself at a vertex only.
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

// The triangles grouped into patches: grown from the first triangle not yet in a patch across edges where the
// surface turns less than featureAngle, taking triangles whose normal is within featureAngle of the first one's
// (so that each patch is nearly flat and maps onto the plane in one piece); then, until nothing changes, a patch
// of fewer than a few triangles joins the neighbour it shares most edges with, a patch meeting itself at a vertex
// keeps its largest fan of triangles there and gives the others to their neighbours' patches, and a patch in
// pieces becomes one patch per piece.
// [in] points; [in] triangles: a manifold surface (an edge in one or two triangles);
// [in] featureAngle: degrees. Returns each triangle's patch, numbered 0.. in order of their first triangle.
std::vector<int> chordalPatches(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                                double featureAngle);

// Faces of the chordal surface between its creases, for the patch grids (patch_grids.hpp): patches grown as
// chordalPatches' (across edges turning less than featureAngle, normals within it of the first's), then those narrower
// than minWidth (twice their area over their perimeter: a bend's strips of facets turning between its faces) given
// away a row of triangles at a time, each to the neighbour whose normal is nearest its own, then cleaned as
// chordalPatches' (small pieces joined, pinches undone). [in] points, triangles, featureAngle: as chordalPatches';
// [in] minWidth; [in] seeds: where patches grow from first: the triangles in index order, or those lying flat among
// their neighbours (within 5 degrees) first, so that a rounded corner between two faces is shared out between them by
// its normals instead of claimed by a patch grown from within it, whose normal cone ends anywhere on the faces
// beside (a cut across a wall). Returns each triangle's patch.
// [in] rims: as grown, or fitted to the patches' normals before the cleaning (each rim triangle round after round to
// the neighbouring patch whose area-weighted mean normal is nearer its own, within featureAngle of it: variational
// shape approximation's normal proxies), which puts a rim where the surface turns from one face to the next instead
// of where a grown patch's normal cone ran out (at a box's corner, a wall's patch reaching a quad into the floor);
// [out] fitted: if given, the triangles the fitting moved (0 as grown).
enum class PatchSeeds { InOrder, FlatFirst };
enum class PatchRims { AsGrown, FittedToNormals };
std::vector<int> facePatches(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                             double featureAngle, double minWidth, PatchSeeds seeds = PatchSeeds::InOrder,
                             PatchRims rims = PatchRims::AsGrown, std::size_t* fitted = nullptr);

// The curves between the patches and along the rim, for Gmsh's discrete model (made here, not by Gmsh's
// createTopology, whose order depends on where its objects lie in memory: its meshes changed from run to run).
struct PatchCurve {
  std::vector<int> vertices;   // a chain from one corner to another (the same corner if the curve is a loop)
  std::array<int, 2> patches;  // the patches on either side, the lower first; -1: the rim
};
struct PatchTopology {
  std::vector<int> corners;                // vertices where curves end: where three or more patches (or the
                                           // rim) meet, and the lowest vertex of a loop without such a vertex
  std::vector<PatchCurve> curves;          // in order of their first corner, then of their first edge
  std::vector<std::vector<int>> bounding;  // per patch, the curves on its rim
};

// [in] triangles; [in] patch: per triangle (chordalPatches). Returns the curves and their corners.
PatchTopology patchTopology(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch);

// The patches that meet themselves at a vertex only (0 for chordalPatches' own), as a check.
// [in] triangles; [in] patch: per triangle. Returns the number of (vertex, patch) pairs with more than one fan.
std::size_t pinchedPatchVertices(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch);

}  // namespace hexlayer
