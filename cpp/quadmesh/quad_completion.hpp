// All-quad completion of the quad-dominant mesh (paper §6.2 asks for quads only): Gmsh's full-quad
// recombination of a reparametrized discrete surface can leave a few triangles, typically where a
// patch's boundary has an odd number of edges. Two triangles joined by a straight strip of quads
// (possibly none) become quads by re-tiling the strip shifted by one node.
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

struct QuadCompletion {
  std::size_t paired = 0;    // triangles turned into quads (two per strip)
  std::size_t unpaired = 0;  // triangles left: each one is a hole in the quad mesh
};

// Pairs the triangles through the shortest straight strip of at most maxStrip quads, shortest
// strips first; the strip's n quads and the two triangles become n + 1 quads, appended to `quads`
// in place of the strip. Triangles it cannot pair stay in `triangles`.
QuadCompletion pairTriangles(std::vector<std::array<int, 4>>& quads, std::vector<std::array<int, 3>>& triangles, int maxStrip);

}  // namespace hexlayer
