// Quad mesh of the chordal surface (paper §6) through Gmsh's C++ API: the chordal facets become a
// discrete surface, Gmsh reparametrizes it, meshes it quad-dominant and turns it all-quad.
#pragma once
#include <array>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "core/types.hpp"

namespace hexlayer {

struct QuadMesh {
  std::vector<Vec3> nodes;                 // on the chordal surface
  std::vector<std::array<int, 4>> quads;   // orientation as Gmsh made it (the sweep orients them)
  std::size_t pairedTriangles = 0;         // Gmsh's leftover triangles turned into quads (quad_completion)
  std::size_t splitTriangles = 0;          // the others, split into quads with the strips from them
  std::size_t holes = 0;                   // leftover triangles neither could handle: each is a hole
};

// How Gmsh cuts the chordal surface into patches it can parametrize, in degrees: chordal edges
// sharper than featureAngle bound the patches, and their boundary curves are split where they turn
// more than curveAngle (180: never). Splitting at the rim's corners keeps them sharp; not splitting
// the feature curves of a noisy bend keeps Gmsh from filling it with tiny quads.
struct PatchSplit {
  double featureAngle, curveAngle;
};

struct QuadMeshOptions {
  double size = 0;  // target edge length (uniform sizing)
  std::vector<double> vertexSize;  // adaptive sizing: target edge length per chordal vertex (sizing.hpp)
  // Gmsh's reparametrization of a patch can fail: the next split is tried then, or when some quads
  // are below acceptableQuad; of the tries, the one with the fewest such quads (then the best worst) is kept.
  std::vector<PatchSplit> patchSplits{{60, 60}, {60, 180}, {40, 40}, {40, 180}, {80, 80}, {25, 25}};
  double acceptableQuad = 0.2;   // quad scaled Jacobian
  // For one Gmsh try: a fixed minute plus a second per 2000 quads the surface will get (Gmsh 4.8
  // meshes tens of thousands of quads a second; a try that takes far longer has hung).
  double timeoutSeconds = 0;      // 0: from the chordal surface's area and the size
};

// For every node, the nodes it shares a rim edge with (an edge of a single quad); empty inside.
std::vector<std::vector<int>> rimEdgeNeighbours(const QuadMesh& quads);

// Meshes the chordal surface with quads only. Holes and the outer rim are the boundary curves of
// the discrete surface, so they are kept. Of the tries (one per patch split) whose nodes all lie on
// the chordal surface, the one with the fewest holes (unpaired triangles), then the fewest poor
// quads, then the best worst quad is kept. Throws geometryError if
// Gmsh cannot mesh the surface.
QuadMesh meshChordalSurface(const ChordalLocator& chordal, const QuadMeshOptions& options);

}  // namespace hexlayer
