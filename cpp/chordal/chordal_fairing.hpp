// Fairing of the chordal surface (beyond the paper): the tet-edge midpoints of §5 follow the
// bubble nodes, so where a bend has a sharp inside corner the surface zigzags in small steps, and
// Gmsh's patches and quads (§6) follow every step with tiny, distorted quads. Taubin's λ|μ
// smoothing removes that noise without shrinking the surface; the rim stays where it is.
#pragma once
#include "chordal/chordal_surface.hpp"

namespace hexlayer {

// Moves every vertex off the rim along its normal by `iterations` λ|μ Laplacian steps over the
// facet edges (Taubin 1995: λ = 0.5, μ = -0.53). Normals and radius (Eq. 1-3) must be computed afterwards.
// [in,out] chordal: its vertices moved; [in] iterations.
void fairChordalSurface(ChordalSurface& chordal, int iterations);

}  // namespace hexlayer
