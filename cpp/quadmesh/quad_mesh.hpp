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
};

struct QuadMeshOptions {
  double size = 0;  // target edge length (uniform sizing)
  // Degrees: chordal edges sharper than this split the surface into patches. Gmsh's reparametrization
  // of a patch can fail; the next angle is tried then, or when the worst quad is below acceptableQuad.
  std::vector<double> featureAngles{40.0, 60.0, 25.0};
  double acceptableQuad = 0.2;   // quad scaled Jacobian
  double timeoutSeconds = 600;   // for one Gmsh try
};

// For every node, the nodes it shares a rim edge with (an edge of a single quad); empty inside.
std::vector<std::vector<int>> rimEdgeNeighbours(const QuadMesh& quads);

// Meshes the chordal surface with quads only. Holes and the outer rim are the boundary curves of
// the discrete surface, so they are kept. Of the tries (one per feature angle) the one whose nodes
// all lie on the chordal surface and whose worst quad is best is kept. Throws geometryError if
// Gmsh cannot mesh the surface.
QuadMesh meshChordalSurface(const ChordalLocator& chordal, const QuadMeshOptions& options);

}  // namespace hexlayer
