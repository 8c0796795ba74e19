// Quad mesh of the chordal surface (paper §6) through Gmsh's C++ API: the chordal facets become a
// discrete surface, Gmsh reparametrizes it, meshes it quad-dominant and turns it all-quad.
#pragma once
#include <array>
#include <vector>

#include "chordal/chordal_surface.hpp"
#include "core/types.hpp"

namespace hexlayer {

struct QuadMesh {
  std::vector<Vec3> nodes;                 // on the chordal surface
  std::vector<std::array<int, 4>> quads;   // orientation as Gmsh made it (the sweep orients them)
};

struct QuadMeshOptions {
  double size = 0;             // target edge length (uniform sizing)
  double featureAngle = 40.0;  // degrees: chordal edges sharper than this become curves
};

// Meshes the chordal surface with quads only. Holes and the outer rim are the boundary curves of
// the discrete surface, so they are kept. Throws geometryError if Gmsh cannot mesh the surface.
QuadMesh meshChordalSurface(const ChordalSurface& chordal, const QuadMeshOptions& options);

}  // namespace hexlayer
