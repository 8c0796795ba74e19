// Smoothing of the quad mesh on the chordal surface: the quads' shape becomes the hexes' shape,
// so interior nodes are moved to the area-weighted centroid of their quads and projected back
// onto the chordal surface, where that does not worsen the quads around them.
#pragma once
#include "chordal/chordal_locator.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// Scaled Jacobian of a quad in 3D: min over corners of n · (e1 x e2) / (|e1||e2|), n the unit
// normal through the diagonals.
double quadScaledJacobian(const std::array<Vec3, 4>& corners);

// The same for a quad facing a given unit normal (the surface's side the quads face): negative for one turned over
// (its diagonals' normal against `normal`) or crossing itself (a bow tie: seen along `normal`, a corner turns back,
// though through its own diagonals' normal half its corners would look right, and turned over the others).
double quadScaledJacobian(const std::array<Vec3, 4>& corners, const Vec3& normal);

// What the smoothing maximizes: the scaled Jacobian, capped by four times the ratio of the shortest to
// the longest edge. A quad with a collapsed edge can have square corners, but its hexes are as
// thin as that edge; quads up to 4:1 (a structured grid across a tapering wall) are not penalized.
double quadSmoothingQuality(const std::array<Vec3, 4>& corners);

// Drops the nodes no quad uses and renumbers the rest in their order.
// [in,out] nodes: the unused ones dropped; [in,out] quads: their node ids renumbered.
void dropUnusedNodes(std::vector<Vec3>& nodes, std::vector<std::array<int, 4>>& quads);

// Removes the doublets: an interior node in just two quads, which share two of its edges, gives
// two quads with a corner near 180 degrees whatever the smoothing does; they are merged into one
// and the node dropped. Returns how many were removed. [in,out] quads.
int removeDoublets(QuadMesh& quads);

// Smooths the interior nodes, and where the worst quad round a rim node gains, slides it along the rim as Gmsh
// placed it (slideRim false: the rim nodes stay). Deterministic, the same on any number of threads: from 2000
// nodes on, the two halves of a cut through the poor quads are smoothed side by side (their seam after them).
// [in,out] quads: interior nodes moved on the surface; [in] chordal, iterations, slideRim; [in] fixed: per node,
// whether it stays (empty: none does).
void smoothQuadMesh(QuadMesh& quads, const ChordalLocator& chordal, int iterations, bool slideRim = true,
                    const std::vector<char>& fixed = {});

}  // namespace hexlayer
