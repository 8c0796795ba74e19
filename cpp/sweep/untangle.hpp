// Untangling the sweep (beyond the paper, whose §7 assumes the chordal surface bends less than its
// radius function): where the sweep lines of neighbouring quad nodes converge before they reach a
// wall, as at a sheet-metal bend with a sharp inside corner, the hexes between them fold. There the
// sweep directions are smoothed (each becomes the mean of its neighbours') over a growing ring of
// quads until the hexes unfold: the lines then fan out along the inner wall instead of meeting.
#pragma once
#include <functional>
#include <vector>

#include "core/types.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

struct UntangleResult {
  int regions = 0;                         // connected groups of bad columns that were worked on
  int improved = 0;                        // smoothing rounds that were kept
  double worstBefore = 1, worstAfter = 1;  // smallest column scaled Jacobian
};

// Moves the sweep directions `dir` of the quad nodes so that every hex column (the hexes of one
// quad) reaches a scaled Jacobian of at least `target` where it can. `place(i)` re-places the hex
// nodes of quad node i from dir[i]; `columnQuality(j)` is the smallest scaled Jacobian of the
// hexes of quad j. A round is kept only where it raises the worst column it touches.
// [in] quads; [in,out] dir: the sweep directions, moved; [in] target, place, columnQuality.
UntangleResult untangleSweep(const QuadMesh& quads, std::vector<Vec3>& dir, double target,
                             const std::function<void(int)>& place, const std::function<double(int)>& columnQuality);

}  // namespace hexlayer
