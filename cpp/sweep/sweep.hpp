// Sweep (paper §7): every quad node is swept along the interpolated normal to place the hex nodes
// of all layers (§7.2), and every quad gives one hex per layer (§7.3).
#pragma once
#include <vector>

#include "quadmesh/quad_mesh.hpp"
#include "chordal/chordal_locator.hpp"

namespace hexlayer {

struct SweepDirection {
  Vec3 normal;    // unit sweep direction n̄
  double radius;  // half-thickness r
};

// n̄ and r at a point of the chordal surface (§7.1), interpolated from the facet's corners:
// Eq. 4-5 on an edge, Eq. 6-7 (area weights) in a triangle, inverse bilinear weights in a quad.
SweepDirection interpolateSweep(const ChordalSurface& chordal, const ChordalPoint& at);

// Offsets of the m + 1 hex nodes along n̄ in units of the radius r, from bottom to top (§7.2):
// even m: h_i = q ± n̄ s i (one node on the chordal surface); odd m: h_i = q ± n̄ s (i + 0.5);
// both are q + n̄ s (k - m/2), k = 0..m, with step s = 2r/m.
std::vector<double> layerOffsets(int layers);

// Builds the layered hex mesh. Quads are turned so that their normal agrees with n̄, which makes
// every hex positively oriented; a quad node shared by quads gives shared hex nodes (conformal).
HexMesh sweepQuads(const QuadMesh& quads, const ChordalLocator& chordal, int layers);

}  // namespace hexlayer
