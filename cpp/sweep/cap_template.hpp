// The cross-section of a rim cap (rim_cap.hpp): a quad mesh of the region between the sweep's straight column and
// a round rim's profile, drawn once in the unit half disc (the column from (0, -1) to (0, 1), the profile the
// half circle of radius 1 beyond it) and laid onto every capped column's real profile. A structured cap (the
// column's layers + 1 nodes opposite as many on the profile) puts two quad corners on the smooth profile, where
// two of its chords meet at 180 degrees less their turn (135 degrees with 4 chords: scaled Jacobian 0.71, 144
// with 5: 0.59); the templates for 2 and 3 layers give every node on the profile a quad edge inwards, so that no
// corner there is wider than about 120 degrees, and cut the profile with more chords for the volume.
#pragma once
#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

namespace hexlayer {

using Vec2 = Eigen::Vector2d;

// Nodes: the column's layers + 1 (0 .. layers, bottom to top), then the nodes on the profile (onProfile, bottom
// to top), then the nodes inside (inside). Quads run clockwise in (outward, up) and their edges q0 -> q1 and
// q3 -> q2 go up (strictly): a cap hex's sweep edges, so that its nodes chain bottom to top as a sweep's do.
struct CapTemplate {
  int layers = 0;
  std::vector<double> onProfile;  // fractions of the profile's arc length from its bottom end, increasing
  std::vector<Vec2> inside;       // positions in the unit half disc
  std::vector<std::array<int, 4>> quads;

  int nodeCount() const { return layers + 1 + static_cast<int>(onProfile.size() + inside.size()); }
  int firstInside() const { return layers + 1 + static_cast<int>(onProfile.size()); }
};

// [in] layers >= 1; [in] rows >= 1. Returns the structured cap: rows columns of layers + 1 nodes, layers + 2 rows
// chords (the outermost column on the profile, the others' ends on it and their inner nodes between the straight
// column and the outermost, evenly).
CapTemplate structuredCap(int layers, int rows);

// [in] layers. Returns the template drawn for that many layers, if any: 2 layers (5 quads, 6 chords), 3 layers
// (7 quads: a ring of 5 along the profile round 2, 5 chords).
std::optional<CapTemplate> drawnCap(int layers);

// [in] t; [in] node: any node of t. Returns its place in the unit half disc (a profile node on the half circle at
// its fraction of the arc).
Vec2 templatePosition(const CapTemplate& t, int node);

// The template's boundary as a polygon of node ids, clockwise: the column bottom to top, then the profile top to
// bottom.
std::vector<int> templateBoundary(const CapTemplate& t);

// Per inside node, its mean value coordinates (Floater 2003) in the template's boundary polygon, in the order of
// templateBoundary: the weights that place it in a real profile's polygon as in the half disc.
std::vector<std::vector<double>> insideWeights(const CapTemplate& t);

}  // namespace hexlayer
