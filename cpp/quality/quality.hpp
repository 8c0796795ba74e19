// Quality of a layered hex mesh (paper §8, Figure 11): scaled Jacobian, aspect ratio, volume,
// and the checks that the mesh is conformal (closed boundary, no duplicated nodes).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

// The 8 corner positions of hex h (node order of HexMesh).
std::array<Vec3, 8> hexCorners(const HexMesh& mesh, std::size_t h);

// Verdict scaled Jacobian restricted to the corners, in [-1, 1]; +1 for a right-handed box,
// < 0 for an inverted corner, -1 if an edge has zero length (flagged invalid).
double hexScaledJacobian(const std::array<Vec3, 8>& x);

// Exact volume of the trilinear hex (negative if inverted).
double hexVolume(const std::array<Vec3, 8>& x);

// In-plane size over layer thickness: mean length of the 8 quad edges over the mean length of
// the 4 sweep edges i -> i+4; +infinity if the sweep edges have zero length.
double hexAspectRatio(const std::array<Vec3, 8>& x);

struct Histogram {
  double lo = 0, hi = 1;
  std::vector<int> counts;  // equal bins on [lo, hi]; values below lo in the first, above hi in the last
};

struct QualityReport {
  double sjMin = 0, sjAvg = 0;
  Histogram sjHistogram;  // 10 bins on [0, 1]
  double arMin = 0, arAvg = 0, arMax = 0;
  double volume = 0;                   // sum of the hex volumes
  std::size_t inverted = 0;            // hexes with scaled Jacobian <= 0 (not usable in a solver)
  Vec3 worstAt = Vec3::Zero();         // centroid of the hex with the smallest scaled Jacobian
  std::vector<double> scaledJacobian;  // per hex
};

// All measures of every hex (all zero for an empty mesh). Deterministic, parallel with OpenMP.
QualityReport measureQuality(const HexMesh& mesh);

// A hex face used by exactly one hex; nodes ordered so their normal points out of the hex.
struct BoundaryFace {
  std::array<int, 4> nodes;
  int hex;
  int localFace;  // 0 bottom (0,3,2,1), 1 top (4,5,6,7), 2..5 sides (0,1,5,4) (1,2,6,5) (2,3,7,6) (3,0,4,7)
};

// The outward-oriented local faces of a hex, indexed by BoundaryFace::localFace.
extern const std::array<std::array<int, 4>, 6> kHexFaces;

// Faces used by exactly one hex, sorted by hex then local face. O(n log n).
std::vector<BoundaryFace> boundaryFaces(const HexMesh& mesh);

struct BoundaryCheck {
  std::size_t faces = 0, openEdges = 0, nonManifoldEdges = 0, inconsistentlyOrientedEdges = 0;
  long eulerCharacteristic = 0;
  std::array<int, 2> firstBadEdge{-1,
                                  -1};  // nodes of the first open, non-manifold or flipped edge (by node ids)  // V - E
                                        // + F of the boundary faces: 2 - 2 x (number of holes) for one closed shell
  // Every boundary edge is used by exactly 2 boundary faces, in opposite directions (true if no faces).
  bool watertight() const { return openEdges == 0 && nonManifoldEdges == 0 && inconsistentlyOrientedEdges == 0; }
};

BoundaryCheck checkBoundary(const HexMesh& mesh);

struct CoincidentNodes {
  std::size_t pairs = 0;  // node pairs closer than the tolerance
  int firstNode = -1;     // the lowest-numbered node that closes such a pair, -1 if none
};

// Node pairs closer than tol (strictly), found in cells sorted by key; none if tol <= 0.
CoincidentNodes findCoincidentNodes(const HexMesh& mesh, double tol);
std::size_t countCoincidentNodes(const HexMesh& mesh, double tol);

}  // namespace hexlayer
