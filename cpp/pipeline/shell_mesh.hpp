// The mid-surface shell (issue 20): the quad mesh of the chordal surface (§6) written as shell elements, with the
// wall thickness at every node measured on the sweep line the hexes were laid along (§7), and node sets per CAD face
// taken from the hex mesh's surface groups, so that supports and loads go where the solid had them.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// [in] mesh: the hexes swept from `quads` (sweep.hpp's layout: quad node i's column is hex nodes i (m + 1) + k,
//   k = 0..m, quad j's hexes j m + k; rim caps and mid-edge nodes after them), 20-node hexes for order 2;
// [in] quads: the quad mesh; [in] groups: the hex mesh's surface groups (one per CAD face).
// Returns the shell: corner i is quad node i, on the chordal surface; for 20-node hexes a mid-side node per quad edge
// (S8R), midway between the hexes' mid-edge nodes of that edge on the two walls (on the CAD walls: on the mid-surface
// that the chordal surface approximates; a point located on the faceted chordal surface was up to 3 % of the wall
// off the mid-plane of a plate drawn in metres). Thickness at a node: t = |(π_t - π_b) · n| (π_t, π_b: its sweep
// column's ends on the walls, the top and bottom hex nodes or mid-edge nodes; n: the shell's unit normal there, the
// mean of its quads' normals), which follows the CAD walls rather than the radius function interpolated from the tets
// (2 r, Eq. 3) and is the wall's thickness also where a rim column leans. A node is in FaceN's set when a node of its
// column lies on FaceN (the walls its sweep line ends on; a rim face its column lies on), in RIM when it is on the
// boundary of the quad mesh.
ShellMesh midSurfaceShell(const HexMesh& mesh, const QuadMesh& quads, const std::vector<SurfaceGroup>& groups);

// Area of the shell: the sum of its quads' vector areas |(p2 - p0) x (p3 - p1)| / 2 (on the corners).
double shellArea(const ShellMesh& shell);

// The shell's numbers (report "shell").
struct ShellRecord {
  int order = 1;  // 2: S8R, 8-node quads
  std::size_t elements = 0, nodes = 0;
  double thicknessMin = 0, thicknessMedian = 0, thicknessMax = 0;  // over the nodes
  double area = 0;                                                 // shellArea
  double cadMidSurfaceArea = 0;  // (A_top + A_bottom) / 2 of the CAD's walls: a plate's or cylinder segment's
                                 // mid-surface area
  double relativeAreaError() const {
    return cadMidSurfaceArea > 0 ? (area - cadMidSurfaceArea) / cadMidSurfaceArea : 0;
  }
};

// [in] shell; [in] cadMidSurfaceArea: the mean of the top and bottom walls' areas. Returns its record.
ShellRecord measureShell(const ShellMesh& shell, double cadMidSurfaceArea);

}  // namespace hexlayer
