// Bends whose inside edge is sharp. Two walls meeting in a sharp inside (concave) edge, their outside faces joined
// by a small round, are one sheet bent with a zero inside radius, as a sheet-metal or molded box is
// at its floor and corners. The round's inward rays run to the sharp inside edge and cross no wall, so the round
// alone would be a rim face (wall_sides.hpp) and the walls two sheets, one standing on the other. The round is a
// top or bottom face of the bent sheet instead (paper §3: ω_t and ω_b run on through a bend).
#pragma once
#include <map>
#include <vector>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// The rim (lateral) faces that are the outside of a bend with a sharp inside edge:
//  - a face at most as wide as the wall is thick (FaceSide::width: a round of radius up to about 0.6 x the wall)
//    tangent (a smooth edge, WallSides::sheetJoins) to two wall faces whose rays cross the wall to two faces sharing
//    a concave edge (the bend's inside edge), and joined by no smooth or convex edge to two walls facing each other
//    (a rim across the wall joins a wall to its other side), and
//  - then, repeatedly, a face as narrow joined by such edges only to wall faces and faces found so, tangent to at
//    least two of those: a sphere or torus where rounds of three walls meet at a corner.
// A rim's round (tangent to one wall, or to two facing each other across the wall) is none of them, nor is a flat
// rim face meeting walls in sharp edges (a chamfered outside stays a rim).
// [in] cad: the solid; [in] w: the first classification (sides Top or Lateral, sheetJoins, thickness);
// [in] across: per face, the ray area crossing the wall to each face. Returns the faces, ascending.
std::vector<int> findBendRounds(const CadSolid& cad, const WallSides& w,
                                const std::vector<std::map<int, double>>& across);

}  // namespace hexlayer
