// All-quad completion of the quad-dominant mesh (paper §6.2 asks for quads only): Gmsh's full-quad
// recombination of a reparametrized discrete surface can leave a few triangles, typically where a
// patch's boundary has an odd number of edges. Two triangles joined by a straight strip of quads
// (possibly none) become quads by re-tiling the strip shifted by one node; a triangle left over is
// split into three quads, and the quad strips from its edge midpoints are halved up to the rim.
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

struct QuadCompletion {
  std::size_t paired = 0;    // triangles turned into quads (two per strip)
  std::size_t unpaired = 0;  // triangles left: each one is a hole in the quad mesh
};

// Splits every triangle into three quads at its centroid and edge midpoints. A quad whose edge got
// a midpoint is halved across to the opposite edge (quartered if both pairs of its edges were), so
// the split runs along the quad strip to the rim or to another split triangle: all quads, conformal.
// New nodes are appended to `nodes`. Returns how many triangles were split.
// [in,out] nodes: the edge midpoints and centroids appended; [in,out] quads: replaced by the quads after the
// split (those a split crosses halved or quartered, three per triangle); [in,out] triangles: emptied.
std::size_t splitTriangles(std::vector<Vec3>& nodes, std::vector<std::array<int, 4>>& quads,
                           std::vector<std::array<int, 3>>& triangles);

// Pairs the triangles through the shortest straight strip of at most maxStrip quads, shortest
// strips first; the strip's n quads and the two triangles become n + 1 quads, appended to `quads`
// in place of the strip. Triangles it cannot pair stay in `triangles`.
// [in,out] quads; [in,out] triangles: the paired ones removed; [in] maxStrip.
QuadCompletion pairTriangles(std::vector<std::array<int, 4>>& quads, std::vector<std::array<int, 3>>& triangles,
                             int maxStrip);

}  // namespace hexlayer
