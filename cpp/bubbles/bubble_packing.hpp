// Bubble packing (paper §4, after Shimada): nodes on the top and bottom surfaces of the solid only.
// Bubbles are packed on the edges first, then on the faces; their diameter is larger than the
// wall thickness, so no node lands on a lateral (rim) face: the rim is spanned by the tets alone.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

struct SurfaceNode {
  Vec3 point;
  Side side = Side::Top;  // which wall the node is on (decides top/bottom for the chordal surface)
  int face = -1;          // 0-based CAD face, edge or vertex the node lies on (one of them >= 0)
  int edge = -1;
  int vertex = -1;
};

struct BubbleOptions {
  double diameterOverThickness = 1.5;  // bubble diameter / local wall thickness (> 1, §4)
  double maxTurnAngle = 0.5;           // radians of curvature one bubble may span (geometry fidelity)
  int relaxationSteps = 15;
};

// Packs bubbles on every edge bounding a top/bottom face (not on a seam where a CAD system split one surface of a wall
// into faces: those are packed as one face), then on every top/bottom face.
std::vector<SurfaceNode> packBubbles(const CadSolid& cad, const WallSides& sides, const BubbleOptions& options);

// Shimada's inter-bubble force as a function of w = distance / stable distance:
// f(w) = 1.25 w^3 - 2.375 w^2 + 1.125 for 0 <= w <= 1.5, else 0 (repels below 1, attracts above).
double bubbleForce(double w);

}  // namespace hexlayer
